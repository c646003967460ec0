#include "engine/field_at_column.hpp"

#include <algorithm>

#include "grammar/fields.hpp"

namespace sphdeck::engine {
namespace {

// Index of the comma-separated item holding 0-based byte `byte` of a free-format line.
std::size_t comma_item(std::string_view text, std::uint32_t byte) {
    const std::string_view before = text.substr(0, std::min<std::size_t>(byte, text.size()));
    return static_cast<std::size_t>(std::count(before.begin(), before.end(), ','));
}

bool inside(const grammar::Span& span, std::uint32_t first, std::uint32_t end) {
    return span.column >= first && span.end_column <= end;
}

}  // namespace

std::optional<std::size_t> dyna_field_at_column(const keywords::CardSpec& card, grammar::CardFormat format,
                                                const std::vector<model::FieldValue>& values, std::string_view text,
                                                std::uint32_t column) {
    const auto used = [&](std::size_t i) {
        return i < values.size() && values[i].spec && values[i].spec->type != keywords::FieldType::Unused;
    };
    for (std::size_t i = 0; i < values.size(); ++i)
        if (used(i) && values[i].explicit_value && column >= values[i].span.column &&
            column < values[i].span.end_column)
            return i;
    if (grammar::is_free_format(text)) {
        const std::size_t item = comma_item(text, column - 1);
        return used(item) ? std::optional<std::size_t>(item) : std::nullopt;
    }
    const auto slots = keywords::layout(card, format);
    for (std::size_t i = 0; i < slots.size() && i < card.fields.size(); ++i) {
        const std::uint32_t first = slots[i].start + 1, end = first + slots[i].width;
        if (column < first || column >= end) continue;
        if (!used(i)) return std::nullopt;
        // A value decoded elsewhere (a line the decoder read otherwise): the slot is not this field's.
        if (values[i].explicit_value && !inside(values[i].span, first, end)) return std::nullopt;
        return i;
    }
    return std::nullopt;
}

std::optional<std::size_t> radioss_field_at_column(const RadiossCard& card, std::string_view text,
                                                   std::uint32_t column) {
    const auto used = [&](std::size_t i) {
        if (i >= card.values.size() || !card.values[i].spec) return false;
        const auto cell = card.values[i].spec->cell;
        return cell != grammar::radioss::Cell::Skip && cell != grammar::radioss::Cell::Skip20;
    };
    for (std::size_t i = 0; i < card.values.size(); ++i) {
        const auto& v = card.values[i];
        if (used(i) && v.explicit_value && column >= v.span.column && column < v.span.end_column) return i;
    }
    if (grammar::is_free_format(text)) {
        const std::size_t item = comma_item(text, column - 1);
        return used(item) ? std::optional<std::size_t>(item) : std::nullopt;
    }
    if (!card.card || card.engine) return std::nullopt;
    const auto cells = grammar::radioss::layout(*card.card, card.version);
    for (std::size_t i = 0; i < cells.size() && i < card.values.size(); ++i) {
        const std::uint32_t first = cells[i].start + 1, end = first + cells[i].width;
        if (column >= first && column < end) return used(i) ? std::optional<std::size_t>(i) : std::nullopt;
    }
    return std::nullopt;
}

}  // namespace sphdeck::engine
