// `sphdeck check --format sarif`: SARIF 2.1.0 for GitHub code scanning and other viewers. One run;
// the driver lists every registered rule with its documentation; results point at the finding's
// field, with notes as related locations.
#pragma once

#include <memory>

#include "diag/report.hpp"
#include "diag/rule_catalog.hpp"

namespace sphdeck::diag {

// `rules` (every rule, listed in the driver) must outlive the report.
std::unique_ptr<Report> make_sarif_report(const RuleCatalog& rules);

// A file's artifactLocation.uri: percent-encoded, relative to the working directory (uriBaseId
// %SRCROOT%) when the file lies below it, else an absolute file:// URI.
std::string sarif_uri(const text::SourceFile& file, bool& relative);

}  // namespace sphdeck::diag
