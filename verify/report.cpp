#include "verify/report.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>

namespace sphdeck::verify {
namespace {

std::string g4(double v) { return std::isfinite(v) ? fmt::format("{:.4g}", v) : "n/a"; }

std::string markdown_cell(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '|')
            out += "\\|";
        else
            out += c;
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
                        !c.gated     ? (c.passed() ? "within (reference, not gated)" : "outside (reference, not gated)")
                        : c.passed() ? "PASS"
                                     : "FAIL"});
    }
    return rows;
}

std::string case_markdown(const CaseResult& result, bool quick, std::string_view figure) {
    std::string md = fmt::format("# {}\n\n", result.title);
    md += fmt::format("Result: **{}** ({} version).\n\n", verdict(result), quick ? "quick" : "full");
    if (!result.ran()) return md + fmt::format("The case did not run: {}\n", result.failure);
    md += "## Runs\n\n";
    std::vector<std::vector<std::string>> runs = {
        {"deck", "particles", "steps", "end time", "wall time [s]", "particle updates / s", "threads"}};
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
    if (!result.details.empty()) md += "\n" + result.details;
    if (!figure.empty()) md += fmt::format("\n![{}]({})\n", result.name, figure);
    return md;
}

SummaryRow summary_row(const CaseResult& r, bool quick) {
    SummaryRow row{r.name, verdict(r), 0, 0, wall_time(r), quick, r.failure};
    for (const Check& c : r.checks)
        if (c.gated) ++row.gated, row.gated_passed += c.passed();
    return row;
}

void merge_summary_rows(SummaryRows& rows, std::span<const CaseResult> results, bool quick) {
    for (const CaseResult& r : results) {
        SummaryRow row = summary_row(r, quick);
        const auto same = std::find_if(rows.begin(), rows.end(), [&](const SummaryRow& o) { return o.name == r.name; });
        if (same != rows.end())
            *same = std::move(row);
        else
            rows.push_back(std::move(row));
    }
    std::sort(rows.begin(), rows.end(), [](const SummaryRow& a, const SummaryRow& b) { return a.name < b.name; });
}

SummaryRows read_summary_rows(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    SummaryRows rows;
    try {
        const nlohmann::json doc = nlohmann::json::parse(in);
        for (const nlohmann::json& r : doc.at("cases"))
            rows.push_back({r.at("name").get<std::string>(), r.at("result").get<std::string>(),
                            r.at("gated_passed").get<std::size_t>(), r.at("gated").get<std::size_t>(),
                            r.at("wall_seconds").get<double>(), r.at("quick").get<bool>(),
                            r.value("failure", std::string())});
    } catch (const nlohmann::json::exception&) {
        return {};  // not ours or damaged: the summary starts again from this run
    }
    return rows;
}

std::string summary_rows_json(const SummaryRows& rows) {
    nlohmann::json cases = nlohmann::json::array();
    for (const SummaryRow& r : rows)
        cases.push_back({{"name", r.name},
                         {"result", r.verdict},
                         {"gated_passed", r.gated_passed},
                         {"gated", r.gated},
                         {"wall_seconds", r.wall_seconds},
                         {"quick", r.quick},
                         {"failure", r.failure}});
    return nlohmann::json{{"cases", cases}}.dump(2) + "\n";
}

std::string summary_markdown(const SummaryRows& rows) {
    std::string md = "# sphdeck verify: summary\n\n";
    std::vector<std::vector<std::string>> table = {
        {"case", "result", "gated checks passed", "version", "wall time [s]", "details"}};
    for (const SummaryRow& r : rows)
        table.push_back({r.name, r.verdict, fmt::format("{}/{}", r.gated_passed, r.gated), r.quick ? "quick" : "full",
                         fmt::format("{:.2f}", r.wall_seconds), fmt::format("[{0}.md]({0}.md)", r.name)});
    md += markdown_table(table);
    for (const SummaryRow& r : rows)
        if (!r.failure.empty()) md += fmt::format("\n- {}: {}\n", r.name, r.failure);
    return md;
}

}  // namespace sphdeck::verify
