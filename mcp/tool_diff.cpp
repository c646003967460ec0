// diff_decks: what the solver reads differently in two decks (`sphdeck diff --format json`): keywords
// added, removed or changed field by field, nodes and particles summarised.
#include "engine/deck_diff.hpp"
#include "mcp/deck_input.hpp"

namespace sphdeck::mcp {
namespace {
using json = nlohmann::json;

engine::CheckResult read_side(const Arguments& args, const ToolContext& context, std::string_view key) {
    const DeckInput deck = deck_input(args, context, key);
    engine::CheckOptions options = check_options(deck, context);
    options.rules.geometry = false;  // the values are what count, not the neighbour rules
    engine::CheckResult r = engine::check_deck(deck.path, deck.documents, options);
    confine_reads(r, context);
    return r;
}

ToolResult run_diff_tool(const Arguments& args, const ToolContext& context) {
    const engine::CheckResult before = read_side(args, context, "before");
    const engine::CheckResult after = read_side(args, context, "after");
    const engine::DeckDiff diff = engine::diff_decks(before, after, args.number("rtol").value_or(1e-12));
    json structured = json::parse(engine::to_json(diff).dump(-1, ' ', false, json::error_handler_t::replace));
    structured["equal"] = diff.equal();
    return {std::move(structured), {}};
}
}  // namespace

Tool diff_decks_tool() {
    json schema = {{"type", "object"},
                   {"properties",
                    {{"before",
                      {{"type", "string"}, {"description", "path of the first deck, relative to the first root"}}},
                     {"after", {{"type", "string"}, {"description", "path of the second deck"}}},
                     {"rtol",
                      {{"type", "number"},
                       {"minimum", 0},
                       {"description", "numbers closer than this relative tolerance are equal (default 1e-12)"}}}}},
                   {"required", {"before", "after"}},
                   {"additionalProperties", false}};
    return {"diff_decks", "Compare two decks",
            "Tells what the solver reads differently in two decks, as `sphdeck diff` does: keywords added, removed or "
            "changed (each field's effective value before and after, with its location), nodes and particles "
            "summarised. Formatting, comments and order do not count.",
            std::move(schema), run_diff_tool};
}

}  // namespace sphdeck::mcp
