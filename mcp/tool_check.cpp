// check_deck: the findings of `sphdeck check --format json` for one deck, named by path or given as
// text: code, severity, message, file, line, column, notes and fixes. A named include file is checked
// as part of the decks around it that include it, as `sphdeck check` does.
#include "engine/include_context.hpp"
#include "mcp/deck_input.hpp"

namespace sphdeck::mcp {
namespace {
using json = nlohmann::json;

json check_tool_schema() {
    json properties = deck_schema_properties("deck");
    properties["select"] = {{"type", "array"},
                            {"items", {{"type", "string"}}},
                            {"description", "check only these rules: codes, names or prefixes such as SPH"}};
    properties["ignore"] = {{"type", "array"}, {"items", {{"type", "string"}}}, {"description", "skip these rules"}};
    properties["geometry"] = {{"type", "boolean"},
                              {"description",
                               "run the rules that need particle neighbours (default true; false "
                               "for a quick check of a very large deck)"}};
    return {{"type", "object"}, {"properties", std::move(properties)}, {"additionalProperties", false}};
}

lint::ConfigOverrides overrides_of(const Arguments& args) {
    lint::ConfigOverrides o;
    for (const char* key : {"select", "ignore"})
        for (const std::string& selector : args.strings(key))
            if (auto problem = lint::check_selector(selector)) throw InvalidParams(*problem);
    if (args.has("select")) o.select = args.strings("select");
    o.ignore = args.strings("ignore");
    return o;
}

ToolResult run_check_tool(const Arguments& args, const ToolContext& context) {
    const DeckInput deck = deck_input(args, context);
    engine::CheckOptions options = check_options(deck, context, overrides_of(args));
    options.rules.geometry = args.boolean("geometry", true);
    std::vector<engine::CheckResult> checked;
    std::vector<std::string> included_by;
    if (!deck.from_text) {
        engine::IncludeContext around = engine::check_in_context(deck.path, deck.documents, options);
        for (std::size_t k = 0; k < around.decks.size(); ++k) {
            if (!reads_inside_roots(around.decks[k], context)) continue;  // a deck around, outside the roots
            around.decks[k].diagnostics = std::move(around.findings[k]);
            included_by.push_back(around.decks[k].deck.sources.file(0).display_name);
            checked.push_back(std::move(around.decks[k]));
        }
    }
    if (checked.empty()) checked.push_back(engine::check_deck(deck.path, deck.documents, options));
    std::vector<const engine::CheckResult*> results;
    std::vector<diag::Diagnostic> all;
    std::size_t files = 0, particles = 0;
    for (const engine::CheckResult& r : checked) {
        confine_reads(r, context);
        results.push_back(&r);
        all.insert(all.end(), r.diagnostics.begin(), r.diagnostics.end());
        files += r.deck.stats.files;
        particles += r.summary.particles;
    }
    json summary = counts_json(all);
    summary["files"] = files;
    summary["particles"] = particles;
    json structured = {{"diagnostics", findings_json(results)}, {"summary", std::move(summary)}};
    if (!included_by.empty()) structured["included_by"] = included_by;
    return {std::move(structured), {}};
}
}  // namespace

Tool check_deck_tool() {
    return {"check_deck", "Check an SPH deck",
            "Checks an LS-DYNA keyword deck or OpenRadioss starter deck (and its includes) for the mistakes that make "
            "an SPH run fail or go wrong. Returns the findings of `sphdeck check --format json`: rule code, severity, "
            "message, file, line, column, notes and fixes (each fix: its text edits and whether it is safe).",
            check_tool_schema(), run_check_tool};
}

}  // namespace sphdeck::mcp
