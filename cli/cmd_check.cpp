// sphdeck check DECK...: read decks, report problems in the chosen format, end with one summary
// line (stdout for the full text format, stderr otherwise so stdout stays machine-readable).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <malloc.h>
#include <fmt/format.h>
#include <limits>
#include <map>
#include <memory>
#include <omp.h>
#include <thread>
#include <unistd.h>

#include "cli/check_inputs.hpp"
#include "cli/check_statistics.hpp"
#include "cli/commands.hpp"
#include "cli/deck_input.hpp"
#include "cli/fix_output.hpp"
#include "cli/ordered_jobs.hpp"
#include "cli/text_folding.hpp"
#include "diag/render_github.hpp"
#include "diag/render_json.hpp"
#include "diag/render_sarif.hpp"
#include "diag/render_text.hpp"
#include "edit/fix_session.hpp"
#include "engine/check.hpp"
#include "engine/check_named.hpp"
#include "engine/shared_preview.hpp"
#include "engine/config_file.hpp"
#include "lint/rule_catalog.hpp"

namespace sphdeck::cli {
namespace {

struct CheckArgs {
    std::vector<std::string> decks;
    std::string format = "full";
    std::vector<std::string> include_paths;
    std::size_t max_per_code = 20;
    std::vector<std::string> select, ignore;
    std::string solver, fail_on, config_file;
    bool no_config = false;
    bool no_geometry = false;
    bool alone = false;  // no search for the decks that include a named file
    bool fix = false, unsafe_fixes = false, diff = false;
    std::vector<std::string> exclude;
    std::string stdin_filename;
    bool statistics = false, exit_zero = false;
    std::string output_file;
    unsigned jobs = 0;                     // decks checked at once; 0: one per core
    CLI::Option* select_option = nullptr;  // to tell "--select" absent from empty
};

// Prints a deck's diagnostics as text, folded for reading (cli/text_folding.hpp).
void print_text(const engine::CheckResult& r, const CheckArgs& args, bool colour) {
    diag::RenderOptions options{colour};
    for (const TextItem& item : fold_for_text(r.diagnostics, r.deck, args.max_per_code)) {
        if (!item.finding)
            fmt::print("{}{}", item.line, args.format == "concise" ? "" : "\n");
        else if (args.format == "concise")
            fmt::print("{}", diag::render_concise(*item.finding, r.deck.sources));
        else
            fmt::print("{}\n", diag::render_full(*item.finding, r.deck.sources, options));
    }
}

lint::ConfigOverrides overrides_of(const CheckArgs& args) {
    lint::ConfigOverrides o;
    if (args.select_option && args.select_option->count() > 0) o.select = args.select;
    o.ignore = args.ignore;
    if (!args.solver.empty()) o.solver = args.solver;
    lint::FailOn level{};
    if (lint::parse_fail_on(args.fail_on, level)) o.fail_on = level;
    o.include_paths = args.include_paths;
    return o;
}

// Every deck's settings, resolved before any deck is read: a bad sphdeck.toml stops the run
// (exit 2) instead of leaving a half-written report. Each config file is read once.
std::optional<std::vector<lint::Config>> resolve_configs(const CheckArgs& args, const std::vector<CheckInput>& inputs) {
    const lint::ConfigOverrides overrides = overrides_of(args);
    std::map<std::string, lint::Config> loaded;
    std::vector<lint::Config> out;
    for (const CheckInput& input : inputs) {
        // Standard input is configured as the file it stands for, or as a deck in the working folder.
        const std::string deck =
            input.path != "-" ? input.path : (args.stdin_filename.empty() ? "stdin.k" : args.stdin_filename);
        std::string path;
        if (!args.no_config && !args.config_file.empty()) {
            path = args.config_file;
        } else if (!args.no_config) {
            if (auto found = engine::find_config(deck)) path = found->string();
        }
        lint::Config config;
        if (!path.empty()) {
            auto it = loaded.find(path);
            if (it == loaded.end()) {
                if (auto error = engine::load_config(path, config)) {
                    fmt::print(stderr, "{}\n", error->to_string());
                    return std::nullopt;
                }
                it = loaded.emplace(path, config).first;
            }
            config = it->second;
        }
        lint::apply_overrides(overrides, config);
        out.push_back(std::move(config));
    }
    return out;
}

// The options the config gives (engine::options_for, as in the editor), with what the command line says.
engine::CheckOptions options_for(const lint::Config& config, const CheckArgs& args) {
    engine::CheckOptions options = engine::options_for(config);
    options.rules.geometry = !args.no_geometry;
    if (config.solver && !args.solver.empty()) options.rules.solver_source = "--solver";
    return options;
}

void add_totals(const engine::CheckResult& r, diag::RunSummary& totals) {
    totals.files += r.deck.stats.files;
    totals.keywords += r.deck.stats.keywords;
    totals.cards += r.deck.stats.cards;
    totals.particles += r.summary.particles;
    diag::Counts c = diag::count(r.diagnostics);
    totals.counts.errors += c.errors;
    totals.counts.warnings += c.warnings;
    totals.counts.infos += c.infos;
}

// What checking one input gave: its checks, or why it could not be checked.
struct InputOutcome {
    std::vector<engine::CheckResult> checked;
    std::string included_by;  // the decks a named include was checked as part of ("a.k, b.k"), if any
    std::string error;        // the message when the input could not be read
};

// A named file checked as part of the decks around it that include it (engine/check_named.hpp).
// Prints nothing: it may run on any thread (--jobs).
InputOutcome check_named_file(const CheckInput& input, const engine::CheckOptions& options, const CheckArgs& args) {
    InputOutcome out;
    if (input.path == "-") {  // standard input: named and resolved as --stdin-filename says
        out.checked.push_back(check_deck_input(input.path, args.stdin_filename, options));
        return out;
    }
    // A deck found in a folder is checked alone: the decks of the folder that include it were dropped
    // from the list or are checked themselves (check_inputs.hpp).
    engine::NamedCheck named = engine::check_named_file(input.path, options, !args.alone && !input.found_in_folder);
    for (std::size_t k = 0; k < named.included_by.size(); ++k)
        out.included_by += fmt::format("{}{}", k == 0 ? "" : ", ", named.included_by[k]);
    out.checked = std::move(named.checked);
    return out;
}

// Many decks in one run: the memory a deck frees stays with the process for the next deck instead of
// going back to the kernel (arrays of up to 32 MiB from the heap, its top never trimmed), so the next
// deck's arrays are not faulted in page by page again: a third of the CPU of 32 decks over one 100 MB
// mesh once their decoding and geometry are shared (bench/README.md). The peak stays one deck's.
void keep_freed_memory_between_decks() {
    constexpr int largest_heap_block = 32 << 20;  // glibc's upper bound for M_MMAP_THRESHOLD on 64 bits
    mallopt(M_MMAP_THRESHOLD, largest_heap_block);
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
}

// What --fix and --diff did over all decks.
struct FixTotals {
    std::size_t fixed = 0, remaining = 0, files = 0;
    bool write_failed = false;
};

// --fix: mends the deck read from `path` and its includes (edit::fix_deck) and writes the files that
// changed; --diff prints their diff instead and writes nothing. Returns the check of the fixed texts.
engine::CheckResult fix_deck(const std::string& path, engine::Documents& documents, const engine::CheckOptions& options,
                             const CheckArgs& args, FixTotals& totals) {
    if (path == "-") throw std::runtime_error("--fix and --diff mend files, not standard input");
    const edit::FixLevel level = args.unsafe_fixes ? edit::FixLevel::Unsafe : edit::FixLevel::Safe;
    edit::FixOutcome outcome = edit::fix_deck(path, documents, options, level);
    totals.fixed += outcome.fixed;
    totals.remaining += outcome.remaining.diagnostics.size();
    totals.files += outcome.files.size();
    for (const edit::FixedFile& file : outcome.files) {
        if (args.diff) {
            fmt::print("{}", fixed_file_diff(file));
        } else if (std::string error = write_fixed_file(file); !error.empty()) {
            fmt::print(stderr, "sphdeck: error: {}\n", error);
            totals.write_failed = true;
        }
    }
    return std::move(outcome.remaining);
}

// "REF003", "SPH030", "DK001": two to three capitals and three digits.
bool looks_like_rule_code(const std::string& word) {
    std::size_t letters = 0;
    while (letters < word.size() && std::isupper(static_cast<unsigned char>(word[letters]))) ++letters;
    if (letters < 2 || letters > 3 || word.size() != letters + 3) return false;
    return std::all_of(word.begin() + static_cast<std::ptrdiff_t>(letters), word.end(),
                       [](unsigned char c) { return std::isdigit(c); });
}

int run_check(const CheckArgs& args) {
    if (args.unsafe_fixes && !args.fix && !args.diff) {
        fmt::print(stderr, "sphdeck: error: --unsafe-fixes widens --fix or --diff; give one of them\n");
        return exit_usage;
    }
    // `--ignore SPH030 REF003 deck.k`: a list option takes one value (A,B) per flag, so REF003 came as a deck.
    for (const std::string& deck : args.decks) {
        std::error_code ec;
        if (deck != "-" && !std::filesystem::exists(deck, ec) && looks_like_rule_code(deck)) {
            fmt::print(stderr,
                       "sphdeck check: error: '{}' is no file but looks like a rule code: a list option takes its "
                       "codes joined by commas (--ignore A,B) or repeated (--ignore A --ignore B)\n",
                       deck);
            return exit_usage;
        }
    }
    auto start = std::chrono::steady_clock::now();
    const ExpandedInputs expanded = expand_inputs(args.decks, args.exclude);
    if (expanded.error) {
        fmt::print(stderr, "sphdeck: error: {}\n", *expanded.error);
        return exit_usage;
    }
    const std::vector<CheckInput> inputs = drop_included(expanded.inputs);
    if (!args.output_file.empty() && !std::freopen(args.output_file.c_str(), "w", stdout)) {
        fmt::print(stderr, "sphdeck: error: cannot write '{}'\n", args.output_file);
        return exit_usage;
    }
    auto configs = resolve_configs(args, inputs);
    if (!configs) return exit_usage;
    std::unique_ptr<diag::Report> report;
    if (args.format == "json") report = diag::make_json_report(lint::rule_catalog());
    if (args.format == "sarif") report = diag::make_sarif_report(lint::rule_catalog());
    const bool colour = args.format == "full" && diag::colour_wanted(STDOUT_FILENO);

    diag::RunSummary totals;
    FindingStatistics statistics;
    FixTotals fix_totals;
    engine::Documents fixed_texts;  // the texts --fix and --diff mended, seen by the next decks
    grammar::FileCache file_cache;  // each file read once in the run, whatever number of decks include it
    engine::RunShare run_share;     // and its bulk blocks decoded once, its preview computed once
    if (inputs.size() > 1) keep_freed_memory_between_decks();
    const bool fixing = args.fix || args.diff;
    bool failed = false;
    const bool text_format = args.format == "full" || args.format == "concise";
    // --fix mends the decks one after the other: each sees the texts the ones before mended.
    const unsigned jobs = fixing ? 1u : args.jobs > 0 ? args.jobs : std::max(1u, std::thread::hardware_concurrency());
    const unsigned decks_at_once =
        static_cast<unsigned>(std::min<std::size_t>(jobs, std::max<std::size_t>(inputs.size(), 1)));
    const int threads_per_deck = std::max(1, omp_get_max_threads() / static_cast<int>(decks_at_once));
    const auto check_input = [&](std::size_t i) {
        InputOutcome out;
        try {
            if (decks_at_once > 1) omp_set_num_threads(threads_per_deck);  // this thread's decoding and geometry
            // --fix mends each deck as the deck read from its file, with its includes (name the main deck
            // to mend an include in its context).
            engine::CheckOptions options = options_for((*configs)[i], args);
            if (fixing) {
                out.checked.push_back(fix_deck(inputs[i].path, fixed_texts, options, args, fix_totals));
            } else {
                options.reader.cache = &file_cache;
                if (inputs.size() > 1) options.share = &run_share;  // a deck alone keeps no copy of its mesh
                out = check_named_file(inputs[i], options, args);
            }
        } catch (const std::exception& e) {
            out.checked.clear();
            out.error = e.what();
        }
        return out;
    };
    const auto report_input = [&](std::size_t i, InputOutcome& outcome) {
        const lint::Config& config = (*configs)[i];
        if (!outcome.error.empty()) {
            std::fflush(stdout);
            fmt::print(stderr, "sphdeck: error: {}\n", outcome.error);
            totals.complete = false;
            return;
        }
        if (!outcome.included_by.empty()) {
            std::fflush(stdout);
            fmt::print(text_format ? stdout : stderr, "{}: checked as included by {}\n", inputs[i].path,
                       outcome.included_by);
        }
        for (const engine::CheckResult& r : outcome.checked) {
            if (args.diff) {
                // stdout holds the diff only, as with `diff -u`
            } else if (report) {
                report->add(r.deck.sources, r.diagnostics);
            } else if (args.format == "github") {
                for (const diag::Diagnostic& d : r.diagnostics)
                    fmt::print("{}", diag::render_github(d, r.deck.sources));
            } else {
                print_text(r, args, colour);
            }
            failed = failed || lint::fails(config, r.diagnostics);
            add_totals(r, totals);
            statistics.add(inputs[i].path, r.diagnostics);
        }
        if (text_format && inputs.size() > 1 && !args.diff) fmt::print("{}\n", statistics.file_summary(inputs[i].path));
    };
    run_in_order<InputOutcome>(inputs.size(), jobs, check_input, report_input);
    if (args.statistics) fmt::print(text_format ? stdout : stderr, "{}", statistics.table(lint::rule_catalog()));
    totals.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (report) fmt::print("{}", report->finish(totals));
    std::fflush(stdout);
    // When no deck could be read, its error message is the last word, not a summary of nothing.
    const bool nothing_read = !totals.complete && totals.files == 0;
    std::string fixes;  // ruff's "(2 fixed, 1 remaining)"
    if (fixing)
        fixes = args.diff ? fmt::format("; would fix {}, {} remaining", fix_totals.fixed, fix_totals.remaining)
                          : fmt::format("; {} fixed, {} remaining", fix_totals.fixed, fix_totals.remaining);
    if (!nothing_read)
        fmt::print(args.format == "full" && args.output_file.empty() && !args.diff ? stdout : stderr,
                   "checked {} file(s): {} keywords, {} cards, {} particles; {} error(s), {} warning(s), {} info(s) "
                   "in {:.2f} s{}\n",
                   totals.files, totals.keywords, totals.cards, totals.particles, totals.counts.errors,
                   totals.counts.warnings, totals.counts.infos, totals.seconds, fixes);
    if (!totals.complete || fix_totals.write_failed) return exit_usage;
    if (args.exit_zero) return exit_clean;
    // --diff exits 1 when a file would change, as ruff's does; otherwise the remaining findings decide.
    if (args.diff && fix_totals.files > 0) return exit_findings;
    return failed ? exit_findings : exit_clean;
}

// Rejects unknown codes on the command line, with the registry's suggestions.
CLI::Validator rule_selector() {
    return CLI::Validator(
        [](std::string& value) {
            auto problem = lint::check_selector(value);
            return problem ? *problem : std::string();
        },
        "CODE", "rule selector");
}

}  // namespace

std::function<int()> setup_check(CLI::App& app) {
    auto args = std::make_shared<CheckArgs>();
    app.add_option("decks", args->decks,
                   "decks (LS-DYNA .k .key .dyn .inc, OpenRadioss _0000.rad), folders searched for them, or - "
                   "for standard input")
        ->required();
    app.add_option("--exclude", args->exclude,
                   "skip files and folders found in folders that match these patterns (a name, or a glob on the path)")
        ->type_name("PATTERN")
        ->allow_extra_args(false);
    app.add_option("--stdin-filename", args->stdin_filename,
                   "the name of the deck read from standard input (-): for messages and include resolution");
    app.add_flag("--statistics", args->statistics, "print the number of findings per rule and per file");
    app.add_flag("--exit-zero", args->exit_zero, "exit 0 even when findings would make it 1 (2 stays 2)");
    app.add_option("--output-file,-o", args->output_file, "write the report to this file instead of stdout");
    app.add_option("--format", args->format, "output format (json, sarif and github carry every finding)")
        ->check(CLI::IsMember({"full", "concise", "json", "sarif", "github"}))
        ->capture_default_str();
    app.add_option("-I,--include-path", args->include_paths,
                   "extra folder searched for *INCLUDE files, after the deck's own folders")
        ->allow_extra_args(false);  // `-I dir deck.k`: the deck stays a deck
    app.add_option("--max-per-code", args->max_per_code,
                   "text formats: show at most N findings of one rule per deck and fold more than 5 of one rule "
                   "on one block's lines (0: all, unfolded); json, sarif and github carry every finding")
        ->capture_default_str();
    args->select_option = app.add_option("--select", args->select,
                                         "check only these rules: codes, names or prefixes such as SPH "
                                         "(replaces select of sphdeck.toml)")
                              ->delimiter(',')
                              ->type_name("CODE,...")
                              ->allow_extra_args(false)  // one list per --select: decks are never codes
                              ->check(rule_selector());
    app.add_option("--ignore", args->ignore, "skip these rules (added to ignore of sphdeck.toml)")
        ->delimiter(',')
        ->type_name("CODE,...")
        ->allow_extra_args(false)
        ->check(rule_selector());
    app.add_option("--solver", args->solver, "the run type, for rules that depend on it")
        ->check(CLI::IsMember({"smp", "mpp"}));
    app.add_option("--fail-on", args->fail_on, "exit with 1 when a finding has at least this severity [default: error]")
        ->check(CLI::IsMember({"error", "warning", "info", "never"}));
    auto* config = app.add_option("--config", args->config_file,
                                  "read this configuration file instead of searching for sphdeck.toml");
    app.add_flag("--no-config", args->no_config, "ignore every sphdeck.toml")->excludes(config);
    app.add_flag("--no-geometry", args->no_geometry,
                 "skip the rules that need particle neighbours (SPH090, SPH113-SPH118): a quick syntax and "
                 "settings check of very large decks");
    app.add_option("--jobs,-j", args->jobs,
                   "check this many decks at once (default: one per core); the report keeps the order of the "
                   "decks, and files several decks include are read once either way")
        ->check(CLI::Range(1u, 1024u));
    app.add_flag("--alone", args->alone,
                 "check each file on its own, not as part of the decks around it that include it");
    app.add_flag("--fix", args->fix,
                 "apply the safe fixes the findings carry to the deck and its include files, in place; the "
                 "summary and exit code then report the findings that remain");
    app.add_flag("--unsafe-fixes", args->unsafe_fixes,
                 "with --fix or --diff: apply the unsafe fixes too (a judgement, such as a did-you-mean name)");
    app.add_flag("--diff", args->diff,
                 "print the unified diff --fix would make and write nothing (exit 1 when a file would change)");
    return [args] { return run_check(*args); };
}

}  // namespace sphdeck::cli
