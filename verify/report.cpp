#include "verify/report.hpp"

#include <cmath>
#include <fmt/format.h>

namespace sphdeck::verify {
namespace {

std::string g4(double v) { return std::isfinite(v) ? fmt::format("{:.4g}", v) : "n/a"; }

std::string markdown_cell(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '|') out += "\\|";
        else out += c;
    }
    return out;
}

std::string markdown_table(const std::vector<std::vector<std::string>>& rows) {
    std::string out;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        out += "|";
        for (const std::string& cell : rows[r]) out += " " + markdown_cell(cell) + " |";
        out += "\n";
        if (r == 0) {
            out += "|";
            for (std::size_t c = 0; c < rows[r].size(); ++c) out += c == 0 ? "---|" : "---:|";
            out += "\n";
        }
    }
    return out;
}

std::string verdict(const CaseResult& r) {
    if (!r.ran()) return "NOT RUN";
    return r.passed() ? "PASS" : "FAIL";
}

double wall_time(const CaseResult& r) {
    double total = 0;
    for (const RunRecord& run : r.runs) total += run.wall_seconds;
    return total;
}

}  // namespace

std::vector<std::vector<std::string>> check_table(const CaseResult& result) {
    std::vector<std::vector<std::string>> rows = {{"quantity", "value", "reference", "error", "tolerance", "result"}};
    for (const Check& c : result.checks) {
        rows.push_back({c.quantity, g4(c.value), c.reference ? g4(*c.reference) : "-", g4(c.error),
                        fmt::format("{} {}", c.bound == Check::Bound::AtMost ? "<=" : ">=", g4(c.tolerance)),
                        c.passed() ? "PASS" : "FAIL"});
    }
    return rows;
}

std::string case_markdown(const CaseResult& result, bool quick, std::string_view figure) {
    std::string md = fmt::format("# {}\n\n", result.title);
    md += fmt::format("Result: **{}** ({} version).\n\n", verdict(result), quick ? "quick" : "full");
    if (!result.ran()) return md + fmt::format("The case did not run: {}\n", result.failure);
    md += "## Runs\n\n";
    std::vector<std::vector<std::string>> runs = {{"deck", "particles", "steps", "end time", "wall time [s]",
                                                   "particle updates / s", "threads"}};
    for (const RunRecord& r : result.runs) {
        const double rate = r.wall_seconds > 0 ? static_cast<double>(r.particles * r.steps) / r.wall_seconds : 0.0;
        runs.push_back({fmt::format("`{}`", r.deck), std::to_string(r.particles), std::to_string(r.steps),
                        g4(r.end_time), fmt::format("{:.2f}", r.wall_seconds), g4(rate),
                        r.threads > 0 ? std::to_string(r.threads) : "default"});
    }
    md += markdown_table(runs);
    md += "\n## Checks\n\n" + markdown_table(check_table(result));
    md += "\n## Method\n\n";
    for (const std::string& line : result.method) md += fmt::format("- {}\n", line);
    if (!figure.empty()) md += fmt::format("\n![{}]({})\n", result.name, figure);
    return md;
}

std::string summary_markdown(std::span<const CaseResult> results, bool quick) {
    std::string md = fmt::format("# sphdeck verify: summary ({} version)\n\n", quick ? "quick" : "full");
    std::vector<std::vector<std::string>> rows = {{"case", "result", "checks passed", "wall time [s]", "details"}};
    for (const CaseResult& r : results) {
        std::size_t passed = 0;
        for (const Check& c : r.checks) passed += c.passed();
        rows.push_back({r.name, verdict(r), fmt::format("{}/{}", passed, r.checks.size()),
                        fmt::format("{:.2f}", wall_time(r)), fmt::format("[{0}.md]({0}.md)", r.name)});
    }
    md += markdown_table(rows);
    for (const CaseResult& r : results)
        if (!r.ran()) md += fmt::format("\n- {}: {}\n", r.name, r.failure);
    return md;
}

}  // namespace sphdeck::verify
