// Reports of verification results: the check table (shared by the terminal and Markdown), one Markdown
// page per case and the summary page of a `sphdeck verify` run.
#pragma once

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
std::string summary_markdown(std::span<const CaseResult> results, bool quick);

}  // namespace sphdeck::verify
