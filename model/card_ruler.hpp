// A `$#` ruler (the comment line LS-PrePost and pydyna write above each card, naming its fields) read as
// evidence of which card the line under it was typed as. DK034 (model/blank_card.cpp) and DK035
// (model/missing_card.cpp) compare it with the card the line is read as.
#pragma once

#include <string_view>

#include "grammar/keywords/schema.hpp"

namespace sphdeck::model {

// How many of the ruler's words (after its `$#`, or its `$`: older decks and pydyna's tests write rulers as
// plain comments) are there, and how many name a field of `card` (by name or alias, case-insensitive:
// CardSpec::field).
struct RulerWords {
    std::size_t count = 0, named = 0;
    // Two words or more, and at least two thirds of them the card's fields.
    bool names_card() const { return count >= 2 && 3 * named >= 2 * count; }
};
RulerWords ruler_words(std::string_view ruler, const keywords::CardSpec& card);

// Whether `ruler` names the fields of `card`: two words or more, and at least two thirds of them its fields.
bool ruler_names(std::string_view ruler, const keywords::CardSpec& card);

}  // namespace sphdeck::model
