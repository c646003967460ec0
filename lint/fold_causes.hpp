// One finding for one cause: the findings of the rules (a reference to nothing, a value out of
// range...) whose field is on a line shifted off its fields (DK029, an error: the shift changes what
// is read) or in a block written in other widths (DK030) become notes of that finding, as the
// reading findings of those lines already are (model/shift_diagnosis.hpp).
#pragma once

#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::lint {

void fold_into_causes(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& diagnostics);

}  // namespace sphdeck::lint
