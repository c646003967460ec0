// keyword_layout: an LS-DYNA keyword's cards as data, from the schema tables `sphdeck keyword` prints:
// per card its fields with columns, type, default, allowed values and a one-line doc.
#include "grammar/keywords/schema.hpp"
#include "mcp/tool.hpp"

namespace sphdeck::mcp {
namespace {
using json = nlohmann::json;

grammar::CardFormat format_of(const std::string& s) {
    if (s == "long") return grammar::CardFormat::Long;
    if (s == "i10") return grammar::CardFormat::I10;
    return grammar::CardFormat::Standard;
}

json field_json(const keywords::FieldSpec& f, const keywords::FieldSlot& slot) {
    json out = {{"name", f.name},
                {"columns", {slot.start + 1, slot.start + slot.width}},
                {"type", keywords::to_string(f.type)},
                {"doc", f.doc}};
    if (f.default_value)
        out["default"] = *f.default_value;
    else if (!f.default_text.empty())
        out["default"] = f.default_text;
    if (f.zero_is_default) out["zero_is_default"] = true;
    if (f.required) out["required"] = true;
    if (!f.choices.empty()) {
        json choices = json::array();
        for (const auto& c : f.choices) choices.push_back({{"value", c.value}, {"meaning", c.meaning}});
        out["choices"] = std::move(choices);
    }
    if (!f.text_choices.empty()) out["choices"] = f.text_choices;
    if (f.min) out["min"] = *f.min;
    if (f.max) out["max"] = *f.max;
    if (!f.refers_to.empty()) out["refers_to"] = f.refers_to;
    if (!f.aliases.empty()) out["aliases"] = f.aliases;
    if (!f.since.empty()) out["since"] = f.since;
    return out;
}

ToolResult run_keyword_tool(const Arguments& args, const ToolContext&) {
    const std::string name = *args.string("name");
    if (!name.empty() && name.front() == '/')
        throw ToolFailure("OpenRadioss cards are not served here yet: run `sphdeck keyword " + name + "`");
    const auto match = keywords::find_keyword(name);
    if (!match || !match->unknown_options.empty()) {
        std::string hint;
        for (std::string_view s : keywords::similar_keywords(name)) hint += (hint.empty() ? "" : ", ") + std::string(s);
        throw ToolFailure("unknown keyword '" + name + "'" + (hint.empty() ? "" : "; did you mean " + hint + "?"));
    }
    const keywords::KeywordSchema& k = *match->schema;
    std::string title(k.name);
    for (const auto* o : match->options) title += "_" + std::string(o->suffix);
    const grammar::CardFormat format = format_of(args.string("format").value_or("standard"));
    json cards = json::array();
    for (const keywords::CardSpec* card : keywords::cards_for(*match)) {
        if (card->unknown_layout) break;  // further lines depend on values: not checked, not shown
        const auto slots = keywords::layout(*card, format);
        json fields = json::array();
        for (std::size_t i = 0; i < card->fields.size(); ++i) fields.push_back(field_json(card->fields[i], slots[i]));
        json c = {{"name", card->name}, {"repeat", keywords::to_string(card->repeat)}, {"fields", std::move(fields)}};
        if (!card->doc.empty()) c["doc"] = card->doc;
        if (card->present_if) c["conditional"] = true;
        cards.push_back(std::move(c));
    }
    json options = json::array();
    for (const auto& o : k.options) options.push_back({{"suffix", o.suffix}, {"doc", o.doc}});
    json structured = {{"keyword", title},
                       {"doc", k.doc},
                       {"unique", k.unique},
                       {"free_text", k.free_text},
                       {"options", std::move(options)},
                       {"cards", std::move(cards)}};
    return {std::move(structured), {}};
}
}  // namespace

Tool keyword_layout_tool() {
    json schema = {
        {"type", "object"},
        {"properties",
         {{"name",
           {{"type", "string"},
            {"description", "LS-DYNA keyword, with or without '*' and options: *CONTROL_SPH, *SECTION_SPH_ELLIPSE"}}},
          {"format",
           {{"type", "string"},
            {"enum", {"standard", "long", "i10"}},
            {"description", "the card format whose columns are given (default standard)"}}}}},
        {"required", {"name"}},
        {"additionalProperties", false}};
    return {"keyword_layout",
            "An LS-DYNA keyword's card layout",
            "Gives an LS-DYNA keyword's cards: per field its columns, type, default, allowed values and meaning, as "
            "`sphdeck keyword` prints them. Use it to write a card in the right columns.",
            std::move(schema),
            run_keyword_tool,
            /*reads_files=*/false};
}

}  // namespace sphdeck::mcp
