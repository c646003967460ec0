// What `sphdeck check` was asked to check (issue 33 item 1): files as given, folders searched
// recursively for decks, `-` for standard input; --exclude globs; and, for the decks found in folders,
// which of them another found deck includes (checked as part of it, not again on their own).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sphdeck::cli {

struct CheckInput {
    std::string path;              // as given or found ("-" for standard input)
    bool found_in_folder = false;  // found by searching a folder, not named
};

struct ExpandedInputs {
    std::vector<CheckInput> inputs;
    std::optional<std::string> error;  // a folder without decks
};

// Deck files in a folder: *.k *.key *.dyn *.inc and OpenRadioss starter decks *_0000.rad (the engine
// deck is read with its starter). Hidden folders are skipped. `exclude`: patterns as in .gitignore, a
// name (glob) matching a file or folder below the given folder (`--exclude old --exclude 'tmp_*.k'`)
// or a glob with '/' matching the path as found or one of its folders (`--exclude '*/old/*'`).
ExpandedInputs expand_inputs(const std::vector<std::string>& given, const std::vector<std::string>& exclude);

// The decks found in folders that no other found deck includes (by their *INCLUDE / #include lines,
// names resolved from the including file's folder: a cheap text scan, files over 64 MiB not scanned);
// named files are always kept. The included ones are checked as part of their includer.
std::vector<CheckInput> drop_included(const std::vector<CheckInput>& inputs);

}  // namespace sphdeck::cli
