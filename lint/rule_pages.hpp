// The registry's documentation as text: `sphdeck rule CODE`, the `sphdeck rules` table, SARIF rule
// help, and docs/rules.md (generated from here; a test keeps the checked-in copy identical). The
// sections come from docs/rules/CODE.md (lint/rule_docs.hpp), the header and summary from the registry.
#pragma once

#include <string>
#include <string_view>

#include "lint/registry.hpp"

namespace sphdeck::lint {

// Where docs/rules.md is published; a rule's section is its lower-case code as anchor.
inline constexpr std::string_view project_url = "https://github.com/sphdeck/sphdeck";
inline constexpr std::string_view rules_doc_url = "https://github.com/sphdeck/sphdeck/blob/main/docs/rules.md";

// "; did you mean 'SPH030', 'SPH031'?" from similar_rules(), or "" when nothing is close.
std::string did_you_mean_rule(std::string_view query);

// rules_doc_url + "#sph030"
std::string rule_url(const RuleInfo& rule);

// The terminal page: header "SPH030 iavis-solid-in-2d (error)", summary, then "What it does",
// "Why it matters", "How to fix" and "Example" (before and after), wrapped for 80 columns.
std::string render_rule_page(const RuleInfo& rule);

// One line per rule: code, name, default severity, summary, in aligned columns.
std::string render_rules_table();

// A rule's documentation as Markdown, without its heading: SARIF help.markdown and docs/rules.md.
std::string rule_markdown_body(const RuleInfo& rule);
// The same as plain text: SARIF help.text.
std::string rule_text_body(const RuleInfo& rule);

// docs/rules.md: an index table, then one section per rule with an anchor.
std::string render_rules_markdown();

}  // namespace sphdeck::lint
