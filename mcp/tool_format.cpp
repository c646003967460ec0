// format_deck: the deck in its canonical column layout (`sphdeck format`), as text and as a diff;
// nothing is written. Lines whose layout is in doubt are left as written.
#include "text/apply_edits.hpp"
#include "edit/format_deck.hpp"
#include "edit/unified_diff.hpp"
#include "mcp/deck_input.hpp"

namespace sphdeck::mcp {
namespace {
using json = nlohmann::json;

json format_tool_schema() {
    json properties = deck_schema_properties("deck");
    properties["headers"] = {{"type", "boolean"},
                             {"description", "write a `$#` line naming the fields above each card"}};
    properties["to_fixed"] = {{"type", "boolean"},
                              {"description", "rewrite free (comma) lines in fixed columns when every value fits"}};
    return {{"type", "object"}, {"properties", std::move(properties)}, {"additionalProperties", false}};
}

ToolResult run_format_tool(const Arguments& args, const ToolContext& context) {
    const DeckInput deck = deck_input(args, context);
    engine::CheckOptions options = check_options(deck, context);
    options.rules.geometry = false;  // the layout needs the reading's findings, not the particles' geometry
    const engine::CheckResult r = engine::check_deck(deck.path, deck.documents, options);
    confine_reads(r, context);
    edit::FormatOptions format;
    format.headers = args.boolean("headers");
    format.to_fixed = args.boolean("to_fixed");
    const auto files = edit::files_to_format(r.deck, false);  // the deck's own file
    const edit::FormatResult formatted = edit::format_deck(r.deck, r.diagnostics, files, format);
    std::vector<diag::TextEdit> edits;  // the main file's (the deck's own files may be more than one)
    for (const diag::TextEdit& e : formatted.edits)
        if (e.span.file == 0) edits.push_back(e);
    const grammar::SourceFile& file = r.deck.sources.file(0);
    std::string text = text::apply_edits(file.text, edits).text;
    std::string diff = edit::unified_diff(file.display_name, file.text, edits);
    json structured = {{"changed", !edits.empty()},
                       {"lines_changed", edits.size()},
                       {"lines_kept", formatted.kept},
                       {"diff", std::move(diff)},
                       {"text", std::move(text)}};
    return {std::move(structured), {}};
}
}  // namespace

Tool format_deck_tool() {
    return {"format_deck", "Format a deck",
            "Rewrites the deck's cards in their canonical column layout without changing a value, as `sphdeck "
            "format` does: returns the formatted text and the unified diff; writes nothing. Comments, titles and "
            "lines whose layout is in doubt are kept as written.",
            format_tool_schema(), run_format_tool};
}

}  // namespace sphdeck::mcp
