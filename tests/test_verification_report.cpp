// The verification reports: the SVG line/scatter plot (well-formed XML read back by Python's standard
// library, the series present), the check table and Markdown pages, and `sphdeck verify` end to end.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/svg_plot.hpp"
#include "verify/report.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_verification_report_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using namespace sphdeck::verify;

namespace {

std::size_t occurrences(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

bool python_parses_xml(const std::string& path) {
    if (std::system("python3 -c 'import xml.etree.ElementTree' >/dev/null 2>&1") != 0) return true;  // no python
    const std::string command =
        "python3 -c 'import sys, xml.etree.ElementTree as ET; ET.parse(sys.argv[1])' '" + path + "' >/dev/null 2>&1";
    return std::system(command.c_str()) == 0;
}

std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST_CASE("verification svg plot: well-formed XML with every series, escaped text, one dot per point") {
    io::PlotPanel panel;
    panel.title = "density <rho> & more";
    panel.x_label = "x";
    panel.y_label = "rho";
    panel.series.push_back(
        {"SPH \"particles\"", {0.1, 0.2, 0.3, NAN}, {1.0, 0.5, 0.25, 1.0}, io::SeriesStyle::Dots, ""});
    panel.series.push_back({"exact", {0.0, 0.5, 1.0}, {1.0, 0.6, 0.2}, io::SeriesStyle::Line, "#222222"});
    panel.series.push_back({"experiment", {0.4}, {0.7}, io::SeriesStyle::Markers, ""});
    io::PlotPanel empty{"no data", "t", "f", {}, std::nullopt, std::nullopt};
    const std::vector<io::PlotPanel> panels = {panel, empty};
    io::PlotOptions options;
    options.title = "a & b";
    const std::string svg = io::svg_plot(panels, options);

    CHECK(svg.find("density &lt;rho&gt; &amp; more") != std::string::npos);
    CHECK(svg.find("SPH &quot;particles&quot;") != std::string::npos);
    CHECK(svg.find("a &amp; b") != std::string::npos);
    CHECK(svg.find("<rho>") == std::string::npos);
    // Three finite dots plus the legend's sample dot; the line with its 3 points; 1 marker + legend marker.
    CHECK(occurrences(svg, "h0") == 4);
    CHECK(occurrences(svg, "class=\"dots\"") == 2);
    CHECK(occurrences(svg, "class=\"marker\"") == 2);
    CHECK(occurrences(svg, ">exact</text>") == 1);
    CHECK(occurrences(svg, ">experiment</text>") == 1);
    CHECK(occurrences(svg, "<g>") == 2);  // one group per panel
    CHECK(occurrences(svg, "<g>") == occurrences(svg, "</g>"));

    sphdeck::test::TempDir dir;
    const std::string path = (dir.path() / "plot.svg").string();
    io::write_svg_plot_file(path, panels, options);
    CHECK(slurp(path) == svg);
    CHECK(python_parses_xml(path));
    CHECK_THROWS_AS(io::write_svg_plot_file((dir.path() / "missing" / "plot.svg").string(), panels, options),
                    std::runtime_error);
}

TEST_CASE("verification report: checks pass only with a finite error on the right side of the tolerance") {
    CaseResult r;
    r.name = "demo";
    r.title = "Demo | case";
    r.checks.push_back({"L1(rho)", 0.01, std::nullopt, 0.01, 0.02});
    r.checks.push_back({"order", 0.9, std::nullopt, 0.9, 0.5, Check::Bound::AtLeast});
    r.runs.push_back({"demo.k", 100, 50, 0.2, 0.5, 1});
    CHECK(r.passed());
    r.checks.push_back({"shock position", NAN, 0.85, NAN, 0.01});  // not found: fails
    CHECK_FALSE(r.checks.back().passed());
    CHECK_FALSE(r.passed());

    const auto rows = check_table(r);
    REQUIRE(rows.size() == 4);
    CHECK(rows[0] == std::vector<std::string>{"quantity", "value", "reference", "error", "tolerance", "result"});
    CHECK(rows[1] == std::vector<std::string>{"L1(rho)", "0.01", "-", "0.01", "<= 0.02", "PASS"});
    CHECK(rows[2][4] == ">= 0.5");
    CHECK(rows[3][1] == "n/a");
    CHECK(rows[3][5] == "FAIL");

    const std::string md = case_markdown(r, true, "demo.svg");
    CHECK(md.find("# Demo | case") != std::string::npos);
    CHECK(md.find("Result: **FAIL** (quick version)") != std::string::npos);
    CHECK(md.find("| `demo.k` | 100 | 50 |") != std::string::npos);
    CHECK(md.find("![demo](demo.svg)") != std::string::npos);
    CaseResult broken;
    broken.name = "broken";
    broken.failure = "cannot read x.k";
    const std::vector<CaseResult> all = {r, broken};
    SummaryRows summary_rows;
    merge_summary_rows(summary_rows, all, false);
    const std::string summary = summary_markdown(summary_rows);
    CHECK(summary.find("| demo | FAIL | 2/3 | full |") != std::string::npos);
    CHECK(summary.find("| broken | NOT RUN | 0/0 | full |") != std::string::npos);
    CHECK(summary.find("cannot read x.k") != std::string::npos);
    // A second run of one case replaces its row and keeps the other; the rows survive summary.json.
    CaseResult again = r;
    for (Check& c : again.checks) c.error = c.bound == Check::Bound::AtMost ? 0.0 : 1.0;
    const std::vector<CaseResult> second = {again};
    merge_summary_rows(summary_rows, second, true);
    sphdeck::test::TempDir dir;
    const auto path = dir.path() / "summary.json";
    std::ofstream(path) << summary_rows_json(summary_rows);
    const SummaryRows read = read_summary_rows(path);
    REQUIRE(read.size() == 2);
    CHECK(read[0].name == "broken");
    CHECK(read[1].verdict == "PASS");
    CHECK(read[1].quick);
    // A reference row (not gated) is reported but does not decide the verdict.
    CaseResult with_reference = again;
    with_reference.checks.push_back({"experiment", 1.0, 2.0, 0.5, 0.1});
    with_reference.checks.back().gated = false;
    CHECK(with_reference.passed());
    CHECK(check_table(with_reference).back()[5] == "outside (reference, not gated)");
}

TEST_CASE("verification cli: bad usage and a missing deck folder exit 2") {
    sphdeck::test::TempDir dir;
    CHECK(sphdeck::test::run_sphdeck(dir, "verify nosuchcase").exit_code == 2);
    const auto missing = sphdeck::test::run_sphdeck(dir, "verify sod --decks nowhere --out out");
    CHECK(missing.exit_code == 2);
    CHECK(missing.err.find("--decks 'nowhere' is not a folder") != std::string::npos);
    // A deck folder without the decks: the case reports why it did not run.
    std::filesystem::create_directories(dir.path() / "empty");
    const auto empty = sphdeck::test::run_sphdeck(dir, "verify sod --quick --decks empty --out out");
    CHECK(empty.exit_code == 2);
    CHECK(empty.out.find("not run: cannot read") != std::string::npos);
    CHECK(std::filesystem::exists(dir.path() / "out" / "summary.md"));
    CHECK(std::filesystem::exists(dir.path() / "out" / "sod.md"));
}

#ifdef SPHDECK_SANITIZED
constexpr bool sanitized = true;
#else
constexpr bool sanitized = false;
#endif

TEST_CASE("verification cli: verify sod --quick runs the decks and writes the reports" * doctest::skip(sanitized)) {
    sphdeck::test::TempDir dir;
    const std::string decks = std::string(SPHDECK_SOURCE_DIR) + "/decks/verification";
    const auto run =
        sphdeck::test::run_sphdeck(dir, "verify sod --quick --threads 1 --out out --decks '" + decks + "'");
    INFO(run.out, run.err);
    // Since the decks keep h about 2 spacings along x (make_sod.py), the quick Sod case passes every gate:
    // a FAIL here is a regression of the solver or of the decks.
    CHECK(run.exit_code == 0);
    CHECK(run.out.find("quantity") != std::string::npos);
    CHECK(run.out.find("sod: PASS") != std::string::npos);
    CHECK(run.out.find("L1(rho), 200 along x") != std::string::npos);
    CHECK(run.out.find("n/a") == std::string::npos);
    const std::string svg = slurp(dir.path() / "out" / "sod.svg");
    CHECK(svg.find("exact (Toro)") != std::string::npos);
    CHECK(python_parses_xml((dir.path() / "out" / "sod.svg").string()));
    CHECK(slurp(dir.path() / "out" / "sod.md").find("## Checks") != std::string::npos);
    CHECK(slurp(dir.path() / "out" / "summary.md").find("| sod |") != std::string::npos);
}
}  // namespace test_verification_report_cpp
