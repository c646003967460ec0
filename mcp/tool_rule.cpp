// explain_rule: one rule's page, as `sphdeck rule CODE` prints it: what it checks, why it matters,
// how to fix it, an example.
#include "lint/registry.hpp"
#include "lint/rule_pages.hpp"
#include "mcp/tool.hpp"

namespace sphdeck::mcp {
namespace {
using json = nlohmann::json;

ToolResult run_rule_tool(const Arguments& args, const ToolContext&) {
    const std::string query = *args.string("rule");
    const lint::RuleInfo* rule = lint::find_rule(query);
    if (!rule) throw ToolFailure("unknown rule '" + query + "'" + lint::did_you_mean_rule(query));
    json structured = {{"code", rule->code},
                       {"name", rule->name},
                       {"severity", diag::to_string(rule->severity)},
                       {"url", lint::rule_url(*rule)},
                       {"page", lint::render_rule_page(*rule)}};
    return {std::move(structured), lint::render_rule_page(*rule)};
}
}  // namespace

Tool explain_rule_tool() {
    json schema = {{"type", "object"},
                   {"properties",
                    {{"rule",
                      {{"type", "string"}, {"description", "rule code (SPH030) or name (iavis-solid-in-2d)"}}}}},
                   {"required", {"rule"}},
                   {"additionalProperties", false}};
    return {"explain_rule",
            "Explain a rule",
            "Explains one of sphdeck's rules (the code of a finding, such as SPH030): what it checks, why it matters, "
            "how to fix it, and an example.",
            std::move(schema),
            run_rule_tool,
            /*reads_files=*/false};
}

}  // namespace sphdeck::mcp
