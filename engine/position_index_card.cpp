// The card and field at a position (engine/position_index.hpp): what completion, signature help,
// hover, inlay hints and engine::id_at ask about one line and column.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "engine/field_at_column.hpp"
#include "engine/position_index.hpp"
#include "grammar/fields.hpp"
#include "grammar/number_cast.hpp"
#include "grammar/value.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::engine {
namespace {

std::string number_text(double v) { return fmt::format("{:g}", v); }

// The card line of `block` just above `line` (nullptr: none), for a line the last check did not read.
grammar::CardLinePtr card_line_above(const grammar::RawDeck& deck, const grammar::Block& block, std::uint32_t line) {
    grammar::CardLinePtr before = nullptr;
    for (grammar::CardLinePtr l = deck.begin_lines(block); l != deck.end_lines(block) && l->line < line; ++l)
        before = l;
    return before;
}

}  // namespace

std::optional<ColumnRange> dyna_field_columns(const keywords::CardSpec& card, grammar::CardFormat format,
                                              std::size_t index) {
    const auto slots = keywords::layout(card, format);
    if (index >= slots.size()) return std::nullopt;
    return ColumnRange{slots[index].start + 1, slots[index].start + 1 + slots[index].width};
}

std::optional<ColumnRange> radioss_field_columns(const RadiossCard& card, std::string_view text, std::size_t index) {
    if (!card.card || card.engine || grammar::is_free_format(text)) return std::nullopt;
    const auto cells = grammar::radioss::layout(*card.card, card.version);
    if (index >= cells.size()) return std::nullopt;
    return ColumnRange{cells[index].start + 1, cells[index].start + 1 + cells[index].width};
}

std::optional<CardAt> card_at(const grammar::RawDeck& deck, const grammar::Block& block, std::uint32_t line,
                              bool radioss) {
    if (line <= block.span.line) return std::nullopt;  // the keyword line, or before the block
    CardAt at;
    at.block = &block;
    at.line_number = line;
    at.line = card_line_at(deck, block, line);
    at.text = at.line ? deck.text(*at.line) : deck.sources.line_text(block.span.file, line);
    if (radioss) {
        if (!at.line) return std::nullopt;
        at.radioss = radioss_card_at(deck, block, at.line, model::radioss_version(deck));
        if (!at.radioss) return std::nullopt;
        return at;
    }
    if (at.line) {
        at.dyna = dyna_card_at(deck, block, at.line);
        if (!at.dyna) return std::nullopt;
        at.dyna_card = at.dyna->card;
        return at;
    }
    // A line typed since the last check (or a comment): the card after the card line just above it.
    at.dyna_card = dyna_card_after(deck, block, card_line_above(deck, block, line));
    if (!at.dyna_card) return std::nullopt;
    return at;
}

std::optional<std::size_t> CardAt::field_under(std::uint32_t column) const {
    if (dyna) return dyna_field_at_column(*dyna->card, block->format, dyna->values, text, column);
    if (radioss) return radioss_field_at_column(*radioss, text, column);
    return std::nullopt;
}

std::optional<std::size_t> CardAt::typed_slot(std::uint32_t column) const {
    if (!dyna_card || column == 0) return std::nullopt;
    const keywords::CardSpec& card = *dyna_card;
    const std::uint32_t byte = column - 1;  // 0-based: the cursor stands before this byte
    if (grammar::is_free_format(text)) {
        const std::string_view before = text.substr(0, std::min<std::size_t>(byte, text.size()));
        const auto commas = static_cast<std::size_t>(std::count(before.begin(), before.end(), ','));
        return commas < card.fields.size() ? std::optional<std::size_t>(commas) : std::nullopt;
    }
    std::uint32_t at = byte;
    if (at > 0 && at <= text.size() && text[at - 1] != ' ') --at;  // still typing the value before
    const auto slots = keywords::layout(card, block->format);
    for (std::size_t i = 0; i < slots.size() && i < card.fields.size(); ++i)
        if (at >= slots[i].start && at < slots[i].start + slots[i].width) return i;
    return std::nullopt;
}

std::optional<std::size_t> CardAt::field_at_cursor(std::uint32_t column) const {
    if (radioss) {
        if (auto index = field_under(column)) return index;
        return column > 1 ? field_under(column - 1) : std::nullopt;
    }
    if (!dyna) return typed_slot(column);
    const std::uint32_t byte = column - 1;
    const bool typing = byte > 0 && byte <= text.size() && text[byte - 1] != ' ' && text[byte - 1] != ',';
    if (typing)
        if (auto index = field_under(byte)) return index;
    return field_under(column);
}

std::optional<std::uint32_t> blank_field_start(const DynaCard& card, grammar::CardFormat format, std::string_view text,
                                               std::size_t index) {
    if (grammar::is_free_format(text)) return std::nullopt;
    const auto columns = dyna_field_columns(*card.card, format, index);
    if (!columns || columns->first - 1 >= text.size()) return std::nullopt;
    return columns->first;
}

std::string effective_value(const model::FieldValue& v) {
    using keywords::FieldType;
    const keywords::FieldSpec& f = *v.spec;
    if (f.type == FieldType::Text) {
        if (v.explicit_value) return fmt::format("`{}`", v.text);
        return f.default_text.empty() ? "blank" : fmt::format("`{}` (default)", f.default_text);
    }
    if (!v.explicit_value)
        return v.valid ? fmt::format("{} (default: left blank)", number_text(v.number)) : "blank (no default)";
    if (!v.valid) return fmt::format("`{}` cannot be read (see the diagnostic)", v.text);
    if (f.type == FieldType::Label && grammar::classify_value(v.text).shape == grammar::ValueShape::Other)
        return fmt::format("label `{}`", v.text);
    std::string value = number_text(v.number);
    const grammar::ValueToken token = grammar::classify_value(v.text);
    if (token.shape == grammar::ValueShape::Parameter) value = fmt::format("{} (from `{}`)", value, v.text);
    if (f.zero_is_default && f.default_value && v.number == *f.default_value &&
        grammar::parse_real(v.text).status == grammar::NumberStatus::Ok && grammar::parse_real(v.text).value == 0.0)
        return fmt::format("{} (default: 0 means the default)", value);
    // No conversion of a value outside long long (1e20 in FORM: undefined behaviour, issue 32).
    if (const std::optional<long long> n = grammar::checked_integer<long long>(v.number);
        n && v.number == std::trunc(v.number))
        if (const auto* choice = f.choice(*n)) value += fmt::format(": {}", choice->meaning);
    return value;
}

}  // namespace sphdeck::engine
