// Reports of verification results: the check table (shared by the terminal and Markdown), one Markdown
// page per case and the summary page of a `sphdeck verify` run.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "verify/case_result.hpp"

namespace sphdeck::verify {

// Header row, then one row per check: quantity, value, reference, error, tolerance, PASS/FAIL.
std::vector<std::vector<std::string>> check_table(const CaseResult& result);

// `figure`: the SVG file name to link, empty for none.
std::string case_markdown(const CaseResult& result, bool quick, std::string_view figure);

// One case's line of summary.md; kept in summary.json so that the summary lists every case run into the
// same folder, not only the last run's.
struct SummaryRow {
    std::string name;
    std::string verdict;  // PASS, FAIL, NOT RUN
    std::size_t gated_passed = 0, gated = 0;
    double wall_seconds = 0;
    bool quick = false;
    std::string failure;  // why it did not run
};
using SummaryRows = std::vector<SummaryRow>;

SummaryRow summary_row(const CaseResult& result, bool quick);
// Replaces the rows of the cases in `results` (or adds them), keeping the others, sorted by name.
void merge_summary_rows(SummaryRows& rows, std::span<const CaseResult> results, bool quick);
// summary.json: empty rows when the file is missing or not what this writes.
SummaryRows read_summary_rows(const std::filesystem::path& path);
std::string summary_rows_json(const SummaryRows& rows);
std::string summary_markdown(const SummaryRows& rows);

}  // namespace sphdeck::verify
