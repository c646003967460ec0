// `sphdeck check --format json`: one document for the whole run (documented in docs/json.md).
#pragma once

#include <memory>

#include "diag/report.hpp"

namespace sphdeck::diag {

// {"version", "diagnostics": [...], "summary": {...}}; see docs/json.md for every field.
std::unique_ptr<Report> make_json_report();

}  // namespace sphdeck::diag
