// CLI11's parse errors ("decks is required", "A subcommand is required") in sphdeck's words, with the
// "sphdeck CMD:" prefix every other message has and where to look next.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace sphdeck::cli {

// The message for a failed parse of `argv` by `app` (help and version requests are not errors and are
// left to CLI11): "sphdeck check: no deck given; try 'sphdeck check --help'".
std::string parse_error_message(const CLI::App& app, const CLI::ParseError& error, int argc, const char* const* argv);

}  // namespace sphdeck::cli
