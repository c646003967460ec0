#include "cli/check_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace sphdeck::cli {

void FindingStatistics::add(const std::string& file, const std::vector<diag::Diagnostic>& diagnostics) {
    diag::Counts& counts = by_file_[file];
    for (const diag::Diagnostic& d : diagnostics) {
        ++by_code_[d.code];
        severity_[d.code] = std::max(severity_[d.code], d.severity);
        switch (d.severity) {
            case diag::Severity::Error: ++counts.errors; break;
            case diag::Severity::Warning: ++counts.warnings; break;
            case diag::Severity::Info: ++counts.infos; break;
        }
    }
}

std::string FindingStatistics::file_summary(const std::string& file) const {
    const auto it = by_file_.find(file);
    const diag::Counts counts = it == by_file_.end() ? diag::Counts{} : it->second;
    return fmt::format("{}: {} error(s), {} warning(s), {} info(s)", file, counts.errors, counts.warnings,
                       counts.infos);
}

std::string FindingStatistics::table(const diag::RuleCatalog& catalog) const {
    std::vector<std::pair<std::string, std::size_t>> rows(by_code_.begin(), by_code_.end());
    std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    std::string out = "findings per rule:\n";
    if (rows.empty()) out += "  (none)\n";
    for (const auto& [code, count] : rows) {
        const diag::RuleMeta* rule = catalog.find(code);
        out += fmt::format("{:>8}  {:<7} {:<8} {}\n", count, code, diag::to_string(severity_.at(code)),
                           rule ? rule->name : "");
    }
    out += "findings per file:\n";
    for (const auto& [file, counts] : by_file_)
        out += fmt::format("{:>8}  {} ({} error(s), {} warning(s), {} info(s))\n",
                           counts.errors + counts.warnings + counts.infos, file, counts.errors, counts.warnings,
                           counts.infos);
    return out;
}

}  // namespace sphdeck::cli
