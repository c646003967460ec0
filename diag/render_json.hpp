// `sphdeck check --format json`: one document for the whole run (documented in docs/json.md).
#pragma once

#include <memory>

#include "diag/report.hpp"
#include "diag/rule_catalog.hpp"

namespace sphdeck::diag {

// {"version", "diagnostics": [...], "summary": {...}}; see docs/json.md for every field.
// `rules` names the findings' rules and links their pages; it must outlive the report.
std::unique_ptr<Report> make_json_report(const RuleCatalog& rules);

}  // namespace sphdeck::diag
