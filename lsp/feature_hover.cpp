// textDocument/hover: what the keyword, field or id under the cursor is, from the schema tables
// (the same data `sphdeck keyword` prints) and the deck's decoded values.
#include <fmt/format.h>
#include <optional>
#include <string>

#include "grammar/radioss/cell_names.hpp"
#include "grammar/keywords/schema.hpp"
#include "engine/id_lookup.hpp"
#include "engine/position_index.hpp"
#include "lsp/display_text.hpp"
#include "lsp/features.hpp"

namespace sphdeck::lsp {

using namespace engine;  // the position index: engine/position_index.hpp, engine/id_lookup.hpp
namespace {

using keywords::FieldSpec;
using keywords::FieldType;
namespace rad = grammar::radioss;

constexpr std::size_t kMaxChoices = 24;  // enum values listed in a hover; the rest are counted

std::string hover_number(double v) { return fmt::format("{:g}", v); }

nlohmann::json hover_json(std::string markdown, const grammar::SourceMap& sources, const grammar::Span& span) {
    return {{"contents", {{"kind", "markdown"}, {"value", display_text(markdown)}}},
            {"range", range_json(sources, span)}};
}

std::string default_text(const FieldSpec& f) {
    if (f.default_value)
        return f.zero_is_default ? fmt::format("{} (0 means the default)", hover_number(*f.default_value))
                                 : hover_number(*f.default_value);
    if (!f.default_text.empty()) return std::string(f.default_text);
    return f.required ? "none (required)" : "none";
}

std::string allowed_text(const FieldSpec& f) {
    std::string out;
    if (!f.choices.empty()) {
        out += "\n\nallowed values:";
        std::size_t shown = 0;
        for (const auto& c : f.choices) {
            if (shown++ == kMaxChoices) {
                out += fmt::format("\n- ... {} more", f.choices.size() - kMaxChoices);
                break;
            }
            out += fmt::format("\n- `{}`: {}{}", c.value, c.meaning,
                               c.since.empty() ? "" : fmt::format(" (since {})", c.since));
        }
    } else if (!f.text_choices.empty()) {
        out += fmt::format("\n\nallowed values: {}", fmt::join(f.text_choices, ", "));
    } else if (f.min || f.max) {
        out += fmt::format("\n\nrange: [{}, {}]", f.min ? hover_number(*f.min) : "-inf",
                           f.max ? hover_number(*f.max) : "inf");
    }
    return out;
}

// "names SECTION 3: `*SECTION_SPH 3`, line 40" or "defines PART 1 (named 12 times)".
std::string id_text_of(const CheckedDeck& deck, const std::optional<IdRole>& role, const std::string& id) {
    if (!role || id.empty()) return {};
    if (role->defines) return fmt::format("\n\ndefines {} {}", role->kind, id);
    const auto definitions = find_definitions(deck.result, role->kind, id);
    if (definitions.empty()) return fmt::format("\n\nnames {} {}, which the deck does not define", role->kind, id);
    return fmt::format("\n\nnames {} {}: `{}`", role->kind, id,
                       display_text(describe(deck.result, definitions.front())));
}

// The cards of a keyword and their fields, one line a card ("Card 1: NCBS, BOXID, DT..."), up to
// the first card whose layout is not known.
std::string card_overview(const keywords::KeywordMatch& match) {
    constexpr std::size_t kMaxCards = 12;
    std::string out;
    const auto cards = keywords::cards_for(match);
    for (std::size_t i = 0; i < cards.size() && i < kMaxCards; ++i) {
        const keywords::CardSpec& card = *cards[i];
        if (card.unknown_layout) break;
        std::vector<std::string_view> names;
        for (const auto& f : card.fields)
            if (f.type != FieldType::Unused) names.push_back(f.name);
        out += fmt::format("\n- {}{}: {}", card.name.empty() ? "card" : card.name,
                           card.repeat == keywords::CardRepeat::Repeated ? " (repeated)" : "", fmt::join(names, ", "));
    }
    if (cards.size() > kMaxCards) out += fmt::format("\n- ... {} more cards", cards.size() - kMaxCards);
    return out.empty() ? out : "\n\ncards:" + out;
}

nlohmann::json dyna_keyword_hover(const CheckedDeck& deck, const grammar::Block& block) {
    const auto& sources = deck.result.deck.sources;
    auto match = keywords::find_keyword(block.keyword);
    if (!match || !match->unknown_options.empty()) {
        std::string text = fmt::format("`{}`: unknown keyword (LS-DYNA stops at it), not checked", block.keyword);
        if (auto better = keywords::suggest_keyword(block.keyword))
            text += fmt::format("; did you mean `{}`?", *better);
        return hover_json(std::move(text), sources, block.span);
    }
    const auto& schema = *match->schema;
    std::string text = fmt::format("**`{}`**", block.keyword);
    if (!schema.doc.empty()) text += fmt::format(": {}", schema.doc);
    if (schema.generated) text += "\n\n(layout generated from pydyna: cards are checked, not read into the model)";
    for (const auto* option : match->options)
        if (!option->doc.empty()) text += fmt::format("\n- `_{}`: {}", option->suffix, option->doc);
    if (schema.unique) text += "\n\nat most once per deck";
    text += card_overview(*match);
    if (block.format != grammar::CardFormat::Standard)
        text += fmt::format("\n\ncards in {} format", to_string(block.format));
    return hover_json(std::move(text), sources, block.span);
}

nlohmann::json dyna_field_hover(const CheckedDeck& deck, const CardAt& at, std::uint32_t column) {
    const auto& raw = deck.result.deck;
    if (!at.dyna) return nullptr;
    const DynaCard& card = *at.dyna;
    auto index = at.field_under(column);
    if (!index) return nullptr;
    const model::FieldValue& v = card.values[*index];
    const FieldSpec& f = *v.spec;
    const ColumnRange columns = dyna_field_columns(*card.card, at.block->format, *index).value_or(ColumnRange{});
    std::string text = fmt::format("**{}** (`{}`, {})", f.name, card.match.schema->name,
                                   card.card->name.empty() ? "card" : card.card->name);
    if (!f.doc.empty()) text += fmt::format(": {}", f.doc);
    text += fmt::format("\n\ncolumns {}-{}, type {}, default {}", columns.first, columns.end - 1,
                        keywords::to_string(f.type), default_text(f));
    if (!f.since.empty()) text += fmt::format(", since {}", f.since);
    text += fmt::format("\n\nvalue: {}", effective_value(v));
    text += allowed_text(f);
    text += id_text_of(deck, dyna_id_role(card.match.schema->name, f), id_text(v));
    grammar::Span span = v.span;
    if (!v.explicit_value) {
        span.column = columns.first;
        span.end_column = columns.end;
    }
    return hover_json(std::move(text), raw.sources, span);
}

nlohmann::json radioss_hover(const CheckedDeck& deck, const grammar::Block& block, std::uint32_t line,
                             std::uint32_t column) {
    const auto& raw = deck.result.deck;
    const rad::KeywordSpec* spec = radioss_keyword(block);
    if (line == block.span.line) {
        std::string text;
        if (!spec) {
            text = fmt::format("`{}`: keyword sphdeck does not read, kept as is", block.keyword);
        } else {
            text = fmt::format("**`{}`**", spec->name);
            if (!spec->summary.empty()) text += fmt::format(": {}", spec->summary);
            if (!spec->decoded) text += "\n\n(known, kept as is: its cards are not read)";
        }
        grammar::Span span = block.span;
        if (auto id = id_at(deck.result, block.span.file, line, column)) {
            text += id_text_of(deck, IdRole{id->kind, id->defines}, id->id);
            span = id->span;
        }
        return hover_json(std::move(text), raw.sources, span);
    }
    const std::optional<CardAt> at = spec ? card_at(raw, block, line, true) : std::nullopt;
    if (!at) return nullptr;
    const RadiossCard* card = &*at->radioss;
    grammar::CardLinePtr card_line = at->line;
    if (card->title) {
        grammar::Span span{card_line->file, card_line->line, 1, raw.length(*card_line) + 1};
        return hover_json(fmt::format("title of `{}`", spec->name), raw.sources, span);
    }
    auto index = at->field_under(column);
    if (!index) return nullptr;
    const model::RadiossValue& v = card->values[*index];
    grammar::Span span = v.span;
    std::string columns;
    if (auto cells = radioss_field_columns(*card, at->text, *index)) {
        columns = fmt::format(", columns {}-{}", cells->first, cells->end - 1);
        if (!v.explicit_value) span.column = cells->first, span.end_column = cells->end;
    }
    std::string text = fmt::format("**{}** (`{}`, format {}): {}{}", v.spec->name, spec->name,
                                   spec->format_for(card->version).since, rad::cell_kind_name(v.spec->cell), columns);
    if (!v.spec->note.empty()) text += fmt::format("\n\n{}", v.spec->note);
    if (!v.explicit_value) {
        text += "\n\nvalue: blank (the starter's default applies)";
    } else if (!v.valid) {
        text += fmt::format("\n\nvalue: `{}` cannot be read (see the diagnostic)", v.text);
    } else if (v.spec->cell == rad::Cell::Int || v.spec->cell == rad::Cell::Real) {
        text += fmt::format("\n\nvalue: {}", hover_number(v.number));
        if (v.number == 0.0) text += " (zero: the starter's default applies)";
    } else {
        text += fmt::format("\n\nvalue: `{}`", v.text);
    }
    text += id_text_of(deck, radioss_id_role(*v.spec), id_text(v));
    return hover_json(std::move(text), raw.sources, span);
}

// `&name` under the cursor: the parameter's value and where it is defined.
std::optional<nlohmann::json> parameter_hover(const CheckedDeck& deck, const grammar::Block& block,
                                              grammar::FileId file, std::uint32_t line, std::uint32_t column);

}  // namespace

nlohmann::json hover(const CheckedDeck& deck, grammar::FileId file, TextPosition position) {
    const auto& raw = deck.result.deck;
    if (file >= raw.sources.size()) return nullptr;
    const LineColumn at = line_column(raw.sources, file, position);
    if (auto child = included_file(raw.sources, file, at.line)) {
        const auto& f = raw.sources.file(*child);
        const grammar::Span span{file, at.line, 1,
                                 static_cast<std::uint32_t>(raw.sources.line_text(file, at.line).size()) + 1};
        return hover_json(fmt::format("includes `{}` ({} lines)", f.path, raw.sources.line_count(*child)), raw.sources,
                          span);
    }
    const grammar::Block* block = block_at(raw, file, at.line);
    if (!block) return nullptr;
    if (deck.result.model.radioss) return radioss_hover(deck, *block, at.line, at.column);
    if (at.line == block->span.line) return dyna_keyword_hover(deck, *block);
    if (auto parameter = parameter_hover(deck, *block, file, at.line, at.column)) return *parameter;
    const std::optional<CardAt> card = card_at(raw, *block, at.line, false);
    if (!card) return nullptr;
    return dyna_field_hover(deck, *card, at.column);
}

namespace {
std::optional<nlohmann::json> parameter_hover(const CheckedDeck& deck, const grammar::Block& block,
                                              grammar::FileId file, std::uint32_t line, std::uint32_t column) {
    const auto& raw = deck.result.deck;
    auto reference = parameter_reference_at(raw.sources, file, line, column);
    std::uint32_t epoch = block.parameter_epoch;
    if (!reference) {
        reference = parameter_definition_at(raw, file, line, column);
        epoch = raw.parameters.epoch();
    }
    if (!reference) return std::nullopt;
    auto found = raw.parameters.find(reference->name, file, epoch);
    if (!found.parameter) {
        return hover_json(fmt::format("parameter `&{}` is not defined before this line", reference->name), raw.sources,
                          reference->span);
    }
    const grammar::Parameter& p = *found.parameter;
    std::string value =
        p.type == grammar::ParameterType::Character ? fmt::format("`{}`", p.text) : hover_number(p.number);
    std::string text = fmt::format("parameter **{}** = {} ({}), `*PARAMETER` line {}", p.name, value,
                                   p.type == grammar::ParameterType::Real      ? "real"
                                   : p.type == grammar::ParameterType::Integer ? "integer"
                                                                               : "character",
                                   p.span.line);
    if (p.span.file != file && p.span.file < raw.sources.size())
        text += fmt::format(" of {}", raw.sources.file(p.span.file).display_name);
    return hover_json(std::move(text), raw.sources, reference->span);
}
}  // namespace

}  // namespace sphdeck::lsp
