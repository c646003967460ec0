// An include file checked in the context of the decks that include it (issue 26 item 2): `sphdeck
// check part.k` and the editor find the decks that *INCLUDE (or #include) the file and report the
// file's findings as part of them, once each. A file no deck includes is checked on its own.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "engine/check.hpp"

namespace sphdeck::engine {

// The files that may be decks including `file`: with `roots` (sphdeck.toml; absolute paths of decks
// or folders), the decks named and the deck files of the folders named; otherwise the deck files of
// the file's folder and each folder above it up to the project root (the nearest folder with a
// sphdeck.toml or a .git, .hg or .svn; without one, the file's folder and its parent), and of the
// folders directly inside those. Deck files: .k .key .dyn .inc .rad by extension; `file` itself left
// out; at most kMostCandidates, nearest folders first. Folders are walked as `file` reaches them (a
// linked folder stays the link) and the candidates returned so, absolute; two names of one deck are one.
inline constexpr std::size_t kMostCandidates = 2000;
std::vector<std::filesystem::path> candidate_decks(const std::filesystem::path& file,
                                                   const std::vector<std::string>& roots);

struct IncludeContext {
    // The checks of the decks that read the file, each a deck no other of them reads, in name order.
    std::vector<CheckResult> decks;
    // Per deck, its findings that lie in the file (any include instance of it), each finding once over
    // all decks (the first deck that has it keeps it).
    std::vector<std::vector<diag::Diagnostic>> findings;
};

// Finds and checks the decks around `file` that read it. A candidate is read only when its text (or,
// for a deck reached through another include, an include's text) names the file, and is kept only
// when its check's include graph holds the file, so what counts is what the reader resolved
// (-I, *INCLUDE_PATH, parameters). Files over kMostCandidateBytes are not searched for names.
inline constexpr std::size_t kMostCandidateBytes = std::size_t{64} << 20;
IncludeContext check_in_context(const std::filesystem::path& file, const Documents& documents,
                                const CheckOptions& options);

}  // namespace sphdeck::engine
