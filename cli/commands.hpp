// The subcommands: one file each, registered in one table (main.cpp).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string_view>

namespace sphdeck::cli {

// Exit codes shared by every subcommand.
inline constexpr int exit_clean = 0;     // no error found
inline constexpr int exit_findings = 1;  // errors found (or warnings with --fail-on warning)
inline constexpr int exit_usage = 2;     // bad usage or an I/O failure

struct Command {
    std::string_view name;
    std::string_view description;
    // Adds the subcommand's options to `app` and returns what runs it after parsing.
    std::function<std::function<int()>(CLI::App& app)> setup;
    // A server (editor, agents): runs until its client leaves, so it keeps malloc's defaults rather than a
    // heap shaped for one big deck (text/big_file_heap.hpp).
    bool serves = false;
};

std::function<int()> setup_check(CLI::App& app);
std::function<int()> setup_rule(CLI::App& app);
std::function<int()> setup_rules(CLI::App& app);
std::function<int()> setup_keyword(CLI::App& app);
std::function<int()> setup_dump(CLI::App& app);
std::function<int()> setup_format(CLI::App& app);
std::function<int()> setup_diff(CLI::App& app);
std::function<int()> setup_smooth(CLI::App& app);
std::function<int()> setup_sol2sph(CLI::App& app);
std::function<int()> setup_run(CLI::App& app);
std::function<int()> setup_verify(CLI::App& app);
std::function<int()> setup_lsp(CLI::App& app);
std::function<int()> setup_mcp(CLI::App& app);

}  // namespace sphdeck::cli
