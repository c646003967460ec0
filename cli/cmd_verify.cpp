// Placeholder until the `verify` subcommand lands (being written in this session).
#include <fmt/core.h>

#include "cli/commands.hpp"

namespace sphdeck::cli {

std::function<int()> setup_verify(CLI::App&) {
    return [] {
        fmt::print(stderr, "sphdeck verify: not implemented yet\n");
        return exit_usage;
    };
}

}  // namespace sphdeck::cli
