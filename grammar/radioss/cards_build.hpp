// Internal: short builders for the card tables (cards_*.cpp).
#pragma once

#include <initializer_list>

#include "grammar/radioss/cards.hpp"

namespace sphdeck::grammar::radioss::build {

inline FieldSpec I(std::string_view name) { return {name, Cell::Int}; }
inline FieldSpec R(std::string_view name) { return {name, Cell::Real}; }
inline FieldSpec T(std::string_view name) { return {name, Cell::Text}; }
inline FieldSpec T20(std::string_view name) { return {name, Cell::Text20}; }
inline FieldSpec L(std::string_view name) { return {name, Cell::Line}; }
inline FieldSpec I(std::string_view name, std::string_view note) { return {name, Cell::Int, 0, note}; }
inline FieldSpec R(std::string_view name, std::string_view note) { return {name, Cell::Real, 0, note}; }
inline FieldSpec S() { return {"", Cell::Skip}; }
inline FieldSpec S20() { return {"", Cell::Skip20}; }
// An unused run of `width` columns in every version (CFG formats that spell the blanks out).
inline FieldSpec gap(std::uint32_t width) { return {"", Cell::Skip, width}; }

inline CardSpec once(std::initializer_list<FieldSpec> fields) { return {fields, Repeat::Once}; }
inline CardSpec repeated(std::initializer_list<FieldSpec> fields) { return {fields, Repeat::Repeated}; }

// A card of `count` integer fields named `name` (node lists of groups).
inline CardSpec repeated_ints(std::string_view name, int count) {
    CardSpec c;
    c.repeat = Repeat::Repeated;
    for (int i = 0; i < count; ++i) c.fields.push_back(I(name));
    return c;
}

// A LIST card of `per_line` reals named `name`, its value count in field `count` of the group.
inline CardSpec list(std::string_view name, int per_line, std::string_view count) {
    CardSpec c;
    c.repeat = Repeat::Repeated;
    c.count = count;
    for (int i = 0; i < per_line; ++i) c.fields.push_back(R(name));
    return c;
}

// A card read once when `condition` holds, `words` saying it for `sphdeck keyword`.
inline CardSpec when(CardSpec card, CardCondition condition, std::string_view words) {
    card.present_if = condition;
    card.condition = words;
    return card;
}

// Lines kept as text, not decoded.
inline CardSpec opaque() { return repeated({L("text")}); }

}  // namespace sphdeck::grammar::radioss::build
