// The rule metadata the machine-readable reports print (JSON: name and URL; SARIF: the driver's rule
// descriptors), as data. The caller builds it from the lint registry (lint::rule_catalog()), so diag/
// renders findings without knowing where rules come from.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"

namespace sphdeck::diag {

struct RuleMeta {
    std::string code;                       // "SPH030"
    std::string name;                       // "iavis-solid-in-2d"
    Severity severity = Severity::Warning;  // the default level
    std::string summary;                    // one line
    std::string what;                       // the "what it does" paragraph
    std::string help_text;                  // the whole documentation as plain text
    std::string help_markdown;              // the same as Markdown
    std::string url;                        // where the documentation is published
};

struct RuleCatalog {
    std::vector<RuleMeta> rules;  // in the order reports list them (by code)
    std::string project_url;      // the tool's home page (SARIF informationUri)

    // The position of the rule with exactly this code in `rules`, or nullopt.
    std::optional<std::size_t> index_of(std::string_view code) const;
    const RuleMeta* find(std::string_view code) const;
};

}  // namespace sphdeck::diag
