#include "lint/rule_catalog.hpp"

#include "lint/registry.hpp"
#include "lint/rule_pages.hpp"

namespace sphdeck::lint {
namespace {
diag::RuleCatalog build_catalog() {
    diag::RuleCatalog catalog;
    catalog.project_url = std::string(project_url);
    for (const RuleInfo& rule : all_rules()) {
        catalog.rules.push_back({std::string(rule.code), std::string(rule.name), rule.severity,
                                 std::string(rule.summary), std::string(rule.doc.what), rule_text_body(rule),
                                 rule_markdown_body(rule), rule_url(rule)});
    }
    return catalog;
}
}  // namespace

const diag::RuleCatalog& rule_catalog() {
    static const diag::RuleCatalog catalog = build_catalog();
    return catalog;
}

}  // namespace sphdeck::lint
