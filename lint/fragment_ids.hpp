// An include fragment checked on its own (issue 26 item 2): a file that cannot be a main deck (an
// LS-DYNA file without *KEYWORD, which the solver needs as the first card of its input; an OpenRadioss
// file without /BEGIN) names ids its including deck defines. Its REF findings about ids defined nowhere
// in it (and its definitions no keyword of it uses, REF007) become one REF010 note, not an error each.
#pragma once

#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::lint {

// Whether the deck's main file is such a fragment.
bool is_include_fragment(const grammar::RawDeck& deck);

// Folds the fragment's REF001-REF005, REF007, REF008 and REF009 findings (and SPH120, SPH121: they judge
// the including deck's *CONTROL_SPH) into one REF010 note at the first of them (their messages and places become its
// notes); nothing when the deck is no fragment.
void summarize_fragment_ids(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& diagnostics);

}  // namespace sphdeck::lint
