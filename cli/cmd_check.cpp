// sphdeck check DECK...: read decks, report problems, end with one summary line.
#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <map>
#include <unistd.h>

#include "cli/commands.hpp"
#include "diag/render_text.hpp"
#include "lint/pipeline.hpp"

namespace sphdeck::cli {
namespace {

struct CheckArgs {
    std::vector<std::string> decks;
    std::string format = "full";
    std::vector<std::string> include_paths;
    std::size_t max_per_code = 20;
};

struct Totals {
    std::size_t files = 0, keywords = 0, cards = 0, particles = 0;
    diag::Counts counts;
};

// Prints a deck's diagnostics; past `max_per_code` of one code, the rest are counted, not shown.
void print_diagnostics(const lint::CheckResult& r, const CheckArgs& args, bool colour) {
    std::map<std::string, std::size_t> shown, hidden;
    diag::RenderOptions options{colour};
    for (const diag::Diagnostic& d : r.diagnostics) {
        if (args.max_per_code > 0 && shown[d.code] >= args.max_per_code) {
            ++hidden[d.code];
            continue;
        }
        ++shown[d.code];
        if (args.format == "concise") {
            fmt::print("{}", diag::render_concise(d, r.deck.sources));
        } else {
            fmt::print("{}\n", diag::render_full(d, r.deck.sources, options));
        }
    }
    for (const auto& [code, n] : hidden)
        fmt::print("{}: {} more {} finding(s) not shown (--max-per-code 0 shows all)\n",
                   r.deck.sources.file(0).display_name, n, code);
}

int run_check(const CheckArgs& args) {
    auto start = std::chrono::steady_clock::now();
    lint::CheckOptions options;
    options.reader.include_paths = args.include_paths;
    bool colour = args.format == "full" && diag::colour_wanted(STDOUT_FILENO);
    Totals totals;
    bool io_failure = false;
    for (const std::string& path : args.decks) {
        lint::CheckResult r;
        try {
            r = lint::check_file(path, options);
        } catch (const std::exception& e) {
            fmt::print(stderr, "sphdeck: error: {}\n", e.what());
            io_failure = true;
            continue;
        }
        print_diagnostics(r, args, colour);
        totals.files += r.deck.stats.files;
        totals.keywords += r.deck.stats.keywords;
        totals.cards += r.deck.stats.cards;
        totals.particles += r.summary.particles;
        diag::Counts c = diag::count(r.diagnostics);
        totals.counts.errors += c.errors;
        totals.counts.warnings += c.warnings;
        totals.counts.infos += c.infos;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::FILE* summary_stream = args.format == "concise" ? stderr : stdout;
    fmt::print(summary_stream,
               "checked {} file(s): {} keywords, {} cards, {} particles; {} error(s), {} warning(s), {} info(s) "
               "in {:.2f} s\n",
               totals.files, totals.keywords, totals.cards, totals.particles, totals.counts.errors,
               totals.counts.warnings, totals.counts.infos, seconds);
    if (io_failure) return exit_usage;
    return totals.counts.errors > 0 ? exit_findings : exit_clean;
}

}  // namespace

std::function<int()> setup_check(CLI::App& app) {
    auto args = std::make_shared<CheckArgs>();
    app.add_option("decks", args->decks, "LS-DYNA keyword decks (.k, .key, .dyn)")->required();
    app.add_option("--format", args->format, "output format")
        ->check(CLI::IsMember({"full", "concise"}))
        ->capture_default_str();
    app.add_option("-I,--include-path", args->include_paths,
                   "extra folder searched for *INCLUDE files, after the deck's own folders");
    app.add_option("--max-per-code", args->max_per_code,
                   "show at most N findings of one rule per deck (0: all)")
        ->capture_default_str();
    return [args] { return run_check(*args); };
}

}  // namespace sphdeck::cli
