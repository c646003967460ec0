// An OpenRadioss block whose title line holds its first card: the line end after the title deleted
// ("Part number 2       122        62         0" under /PART/5, the block then without a card line). The starter
// reads the title whole and the missing card as blanks (a part of property 0 and material 0); the symptoms land
// elsewhere ("section 122 is not used"). The cause is found by trying the mend: the title's tail, from a column
// in the blanks before its first number, read as the first card, without a finding and its numbers at the
// ends of their cells (the right-aligned habit of the CFG formats).
#pragma once

#include <optional>

#include "diag/diagnostic.hpp"
#include "grammar/radioss/cards.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// DK037 (warning, unsafe fix: the line end put back) at `title`, the title line of `keyword`'s block, when the
// block has no card line after it and the title's tail reads as `card` (its first card, of numbers) in the
// deck's `version`; nothing otherwise.
std::optional<diag::Diagnostic> diagnose_joined_title(const grammar::RawDeck& deck, const grammar::CardLine& title,
                                                      const grammar::radioss::CardSpec& card, int version,
                                                      std::string_view keyword);

}  // namespace sphdeck::model
