// sphdeck: checks LS-DYNA and OpenRadioss SPH decks before they reach the solver.
#include <cstdio>
#include <exception>
#include <fmt/format.h>
#include <vector>

#include "cli/commands.hpp"
#include "cli/parse_error_message.hpp"
#include "cli/stream_order.hpp"
#include "cli/suggest.hpp"
#include "cli/unknown_option.hpp"
#include "text/big_file_heap.hpp"

namespace {

const std::vector<sphdeck::cli::Command>& commands() {
    static const std::vector<sphdeck::cli::Command> table = {
        {"check", "read decks and report problems with file:line:column and rule codes", sphdeck::cli::setup_check},
        {"rule", "explain one rule: what it checks, why, how to fix it, an example", sphdeck::cli::setup_rule},
        {"rules", "list every rule (--format markdown: docs/rules.md)", sphdeck::cli::setup_rules},
        {"keyword", "print a keyword's cards: columns, types, defaults, allowed values", sphdeck::cli::setup_keyword},
        {"format", "rewrite decks in a canonical column layout without changing a value (--check, --diff)",
         sphdeck::cli::setup_format},
        {"dump", "print the decoded deck model (--format json)", sphdeck::cli::setup_dump},
        {"diff", "what the solver reads differently in two decks (exit 1 when they differ)", sphdeck::cli::setup_diff},
        {"smooth", "preview smoothing lengths, neighbours and time step per part (table, json, csv, vtk, svg)",
         sphdeck::cli::setup_smooth},
        {"sol2sph", "generate the particles SOL2SPH parts of a Radioss deck will release (vtp, csv)",
         sphdeck::cli::setup_sol2sph},
        {"run", "run the deck with the compact reference SPH solver (time history, vtp snapshots)",
         sphdeck::cli::setup_run},
        {"verify",
         "run the verification cases (sod, hydrostatic, dambreak, sedov, noh...) against exact, experimental and independent data",
         sphdeck::cli::setup_verify},
        {"lsp",
         "serve editors over the Language Server Protocol on stdio: diagnostics as you type, hover, go to definition",
         sphdeck::cli::setup_lsp, true},
        {"mcp", "serve coding agents over the Model Context Protocol on stdio: check, fix, format, explain decks",
         sphdeck::cli::setup_mcp, true},
    };
    return table;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace sphdeck::cli;
    keep_streams_in_order();
    CLI::App app{"sphdeck: checks LS-DYNA and OpenRadioss SPH decks before they reach the solver", "sphdeck"};
    app.set_version_flag("--version", std::string("sphdeck ") + SPHDECK_VERSION);
    app.require_subcommand(1);
    std::function<int()> run;
    bool serves = false;
    for (const Command& c : commands()) {
        CLI::App* sub = app.add_subcommand(std::string(c.name), std::string(c.description));
        auto runner = c.setup(*sub);
        sub->callback([&run, &serves, runner, server = c.serves] { run = runner, serves = server; });
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (argc > 1 && e.get_name() == "RequiredError" && argv[1][0] != '-' && app.get_subcommands().empty()) {
            std::vector<std::string_view> names;
            for (const Command& c : commands()) names.push_back(c.name);
            std::string hint = did_you_mean(argv[1], names);
            fmt::print(stderr, "sphdeck: unknown command '{}'{}\nrun 'sphdeck --help' for the list\n", argv[1], hint);
            return exit_usage;
        }
        // (An ExtrasError thrown by a subcommand carries the subcommand's name, not its kind.)
        if (dynamic_cast<const CLI::ExtrasError*>(&e) || e.get_name() == "RequiredError") {
            if (auto message = unknown_option_message(app, argc, argv)) {
                fmt::print(stderr, "{}\n", *message);
                return exit_usage;
            }
        }
        // --help and --version end the parse with an "error" that CLI11 prints itself.
        if (e.get_exit_code() == 0) return app.exit(e) == 0 ? exit_clean : exit_usage;
        fmt::print(stderr, "{}\n", parse_error_message(app, e, argc, argv));
        return exit_usage;
    }
    // A batch command reads its decks once and ends: malloc's heap may be shaped for a big deck (issue 40).
    if (run && !serves) sphdeck::text::allow_big_file_heap();
    try {
        return run ? run() : exit_usage;
    } catch (const std::exception& e) {
        fmt::print(stderr, "sphdeck: error: {}\n", e.what());
        return exit_usage;
    }
}
