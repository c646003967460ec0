// *PARAMETER, *PARAMETER_EXPRESSION, *PARAMETER_DUPLICATION (and _LOCAL, _MUTABLE, _NOECHO, _TYPE):
// read when their block closes, so later blocks see them (lsdyna-format.md §14).
#pragma once

#include "grammar/raw_deck.hpp"

namespace sphdeck::grammar::dyna {

void define_parameters(RawDeck& deck, const Block& block);

// After reading: the DK014 warnings of one file are one finding (the "defaults in an include" that
// another file overrides redefine many parameters at once), naming every parameter; a DK024 on the
// line of a DK014 joins it as a note (one finding per line).
void group_redefinitions(RawDeck& deck);

}  // namespace sphdeck::grammar::dyna
