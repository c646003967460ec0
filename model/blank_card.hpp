// A blank line typed inside a keyword's cards for spacing: LS-DYNA reads a blank data line as a card
// whose fields are all blank (defaults), not as white space (lsdyna-format.md §5, "Blank data lines"), so
// the cards after it are read one card late: a required field left blank on the blank line, the last card
// read as lines too many, a *PART's card 2 missing. The symptoms land after the line a person typed;
// the cause is the blank line (DK034).
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// Whether a card line is blank (spaces, tabs and a carriage return only).
bool blank_card_line(std::string_view text);

// DK034 at `blank` (a blank line the block read as `card`, a card read once, with a data line after it in
// the block), when out[from, end) shows a card too many: a required field blank on it (DK008), lines past
// the keyword's last card (DK009), the keyword missing a card (DK008); those findings become its notes.
// Returns whether it fired.
bool diagnose_blank_card(const grammar::RawDeck& deck, const grammar::Block& block, const grammar::CardLine& blank,
                         const keywords::CardSpec& card, std::vector<diag::Diagnostic>& out, std::size_t from);

}  // namespace sphdeck::model
