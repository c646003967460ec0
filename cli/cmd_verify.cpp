// sphdeck verify [sod|hydrostatic|dambreak|sedov|noh|all]: runs the verification decks of decks/verification/
// through the reference solver in-process and compares them with exact and experimental references
// (docs/verification.md): a table per case, PASS/FAIL, and Markdown + SVG reports in --out.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <system_error>

#include "cli/commands.hpp"
#include "cli/text_table.hpp"
#include "verify/cases.hpp"
#include "verify/report.hpp"

namespace sphdeck::cli {
namespace {

namespace fs = std::filesystem;
namespace verification = sphdeck::verify;

struct VerifyArgs {
    std::vector<std::string> which{"all"};
    bool quick = false;
    std::string out = "verification-out";
    std::string decks;
    int threads = 0;
};

// --decks, else decks/verification under the current folder, else under the parent of the folder holding
// the binary (the source tree when sphdeck was built in build/ or build-*/), else PREFIX/share/sphdeck.
std::optional<fs::path> find_decks(const std::string& given) {
    std::error_code ec;
    if (!given.empty()) return fs::is_directory(given, ec) ? std::optional<fs::path>(given) : std::nullopt;
    const fs::path here = "decks/verification";
    if (fs::is_directory(here, ec)) return here;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path beside = exe.parent_path().parent_path() / "decks" / "verification";
        if (fs::is_directory(beside, ec)) return beside;
        const fs::path installed = exe.parent_path().parent_path() / "share" / "sphdeck" / "decks" / "verification";
        if (fs::is_directory(installed, ec)) return installed;  // make install, the Debian package
    }
    return std::nullopt;
}

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(fmt::format("cannot open '{}' for writing", path.string()));
    out << text;
    out.close();
    if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", path.string()));
}

int run_verify(const VerifyArgs& args) {
    const std::optional<fs::path> decks = find_decks(args.decks);
    if (!decks) {
        fmt::print(stderr, "sphdeck verify: error: {}\n",
                   args.decks.empty() ? "no decks/verification folder under the current folder or the source tree; "
                                        "give it with --decks DIR"
                                      : fmt::format("--decks '{}' is not a folder", args.decks));
        return exit_usage;
    }
    std::error_code ec;
    fs::create_directories(args.out, ec);
    if (ec) {
        fmt::print(stderr, "sphdeck verify: error: cannot create '{}': {}\n", args.out, ec.message());
        return exit_usage;
    }
    verification::CaseOptions options;
    options.decks = *decks;
    options.quick = args.quick;
    options.threads = args.threads;
    options.progress = [](std::string_view line) {
        fmt::print(stderr, "  {}\n", line);
        std::fflush(stderr);
    };

    std::vector<verification::CaseResult> results;
    for (const verification::VerificationCase& c : verification::verification_cases()) {
        if (std::find(args.which.begin(), args.which.end(), "all") == args.which.end() &&
            std::find(args.which.begin(), args.which.end(), c.name) == args.which.end())
            continue;
        fmt::print("{} ({}{})\n", c.name, c.summary, args.quick ? ", quick" : "");
        std::fflush(stdout);
        verification::CaseResult r = c.run(options);
        if (!r.ran()) {
            fmt::print("  not run: {}\n\n", r.failure);
        } else {
            print_table(verification::check_table(r), WordColumn::First, "  ");
            fmt::print("  {}: {}\n\n", c.name, r.passed() ? "PASS" : "FAIL");
        }
        const fs::path svg = fs::path(args.out) / (r.name + ".svg");
        if (r.ran() && !r.svg.empty()) write_text(svg, r.svg);
        write_text(fs::path(args.out) / (r.name + ".md"),
                   verification::case_markdown(r, args.quick, r.svg.empty() ? "" : r.name + ".svg"));
        std::fflush(stdout);
        results.push_back(std::move(r));
    }
    // summary.md lists every case whose report is in --out: this run's, and the earlier runs' kept in
    // summary.json (a case run again replaces its row).
    verification::SummaryRows rows = verification::read_summary_rows(fs::path(args.out) / "summary.json");
    verification::merge_summary_rows(rows, results, args.quick);
    write_text(fs::path(args.out) / "summary.json", verification::summary_rows_json(rows));
    write_text(fs::path(args.out) / "summary.md", verification::summary_markdown(rows));

    bool all_ran = true, all_passed = true;
    for (const verification::CaseResult& r : results) {
        all_ran = all_ran && r.ran();
        all_passed = all_passed && r.passed();
    }
    fmt::print("{} case(s): {}; reports in {}\n", results.size(),
               !all_ran     ? "some did not run"
               : all_passed ? "all passed"
                            : "some failed",
               args.out);
    if (!all_ran) return exit_usage;
    return all_passed ? exit_clean : exit_findings;
}

}  // namespace

std::function<int()> setup_verify(CLI::App& app) {
    auto args = std::make_shared<VerifyArgs>();
    app.add_option("cases", args->which, "the cases to run (several may be named)")
        ->check(CLI::IsMember({"sod", "hydrostatic", "dambreak", "sedov", "noh", "radioss-waves", "all"}))
        ->capture_default_str();
    app.add_flag("--quick", args->quick, "the coarse, short variants (what `make test` runs, well under a minute)");
    app.add_option("--out", args->out, "folder for <case>.md, <case>.svg and summary.md")->capture_default_str();
    app.add_option("--decks", args->decks,
                   "folder with the verification decks (default: decks/verification under the current folder, "
                   "else under the source tree the binary was built in, else the installed "
                   "share/sphdeck/decks/verification)");
    app.add_option("--threads", args->threads, "OpenMP threads (0: the OpenMP default)")->check(CLI::NonNegativeNumber);
    app.footer(
        "Exit status: 0 when every gated check of every case passes (reference rows, such as the dam "
        "break's experiments, are reported, not gated), 1 when a case fails, 2 on bad usage or a deck that "
        "cannot be read or run.");
    return [args] { return run_verify(*args); };
}

}  // namespace sphdeck::cli
