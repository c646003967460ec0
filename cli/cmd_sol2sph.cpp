// Placeholder until the `sol2sph` subcommand lands (being written in this session).
#include <fmt/core.h>

#include "cli/commands.hpp"

namespace sphdeck::cli {

std::function<int()> setup_sol2sph(CLI::App&) {
    return [] {
        fmt::print(stderr, "sphdeck sol2sph: not implemented yet\n");
        return exit_usage;
    };
}

}  // namespace sphdeck::cli
