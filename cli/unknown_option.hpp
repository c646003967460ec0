// "unknown option --formt; did you mean --format?" for every subcommand: CLI11 only says that an
// argument was not expected.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace sphdeck::cli {

// After a failed parse: the first option of the command line that the parsed subcommand (or the
// program, when none was parsed) does not know, as a message with the closest option it has;
// nullopt when every option is known (the error is about something else).
std::optional<std::string> unknown_option_message(const CLI::App& app, int argc, const char* const* argv);

}  // namespace sphdeck::cli
