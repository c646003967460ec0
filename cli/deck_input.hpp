// One deck named on the command line: a file, or `-` for standard input named by --stdin-filename
// (which also anchors its includes), the same for every subcommand that reads decks.
#pragma once

#include <string>

#include "engine/check.hpp"

namespace sphdeck::cli {

inline constexpr const char* stdin_help =
    "the name of the deck read from standard input (-): for messages and include resolution";

// The name a deck is shown by: the path as given, or --stdin-filename (default "<stdin>") for `-`.
std::string deck_display_name(const std::string& path, const std::string& stdin_filename);

// Reads and checks `path`; `-` reads standard input to its end.
engine::CheckResult check_deck_input(const std::string& path, const std::string& stdin_filename,
                                     const engine::CheckOptions& options);

}  // namespace sphdeck::cli
