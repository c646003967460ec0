// *PARAMETER, *PARAMETER_EXPRESSION, *PARAMETER_DUPLICATION (and _LOCAL, _MUTABLE, _NOECHO, _TYPE):
// read when their block closes, so later blocks see them (lsdyna-format.md §14).
#pragma once

#include "grammar/raw_deck.hpp"

namespace sphdeck::grammar::dyna {

void define_parameters(RawDeck& deck, const Block& block);

}  // namespace sphdeck::grammar::dyna
