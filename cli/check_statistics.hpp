// `sphdeck check --statistics` and the per-file summary line of a run over several decks (issue 33
// item 3): findings counted per rule and per file.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "diag/rule_catalog.hpp"

namespace sphdeck::cli {

class FindingStatistics {
public:
    void add(const std::string& file, const std::vector<diag::Diagnostic>& diagnostics);
    // "main.k: 2 error(s), 1 warning(s), 0 info(s)"
    std::string file_summary(const std::string& file) const;
    // One line per rule, most frequent first ("  12  DK003  error    not-a-number"), then one per file.
    std::string table(const diag::RuleCatalog& catalog) const;

private:
    std::map<std::string, std::size_t> by_code_;
    std::map<std::string, diag::Severity> severity_;  // as reported (settings may re-level a rule)
    std::map<std::string, diag::Counts> by_file_;
};

}  // namespace sphdeck::cli
