// The field of a decoded card line under a column, blank part included: a right-aligned value
// ("        12") answers on its leading blanks too, and a free-format line answers between its
// commas. Every editor feature asks here: hover, inlay hints, signature help, completion, and
// definition and references through engine::id_at.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"
#include "engine/position_index.hpp"
#include "model/card_decoder.hpp"

namespace sphdeck::engine {

// Index of the LS-DYNA field of `card` (decoded into `values` from the line `text`) under 1-based
// byte `column`: a written value's span, else the fixed slot holding the column when the field
// decoded there (its value, if any, lies inside the slot), else in free format the field between
// the commas around the column. nullopt: an unused field, or past the card's fields.
std::optional<std::size_t> dyna_field_at_column(const keywords::CardSpec& card, grammar::CardFormat format,
                                                const std::vector<model::FieldValue>& values, std::string_view text,
                                                std::uint32_t column);

// The same for a Radioss card line (fixed cells, or commas in free format).
std::optional<std::size_t> radioss_field_at_column(const RadiossCard& card, std::string_view text,
                                                   std::uint32_t column);

}  // namespace sphdeck::engine
