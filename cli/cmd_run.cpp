// Placeholder until the `run` subcommand lands (being written in this session).
#include <fmt/core.h>

#include "cli/commands.hpp"

namespace sphdeck::cli {

std::function<int()> setup_run(CLI::App&) {
    return [] {
        fmt::print(stderr, "sphdeck run: not implemented yet\n");
        return exit_usage;
    };
}

}  // namespace sphdeck::cli
