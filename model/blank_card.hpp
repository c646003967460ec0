// A blank line typed inside a keyword's cards for spacing: LS-DYNA reads a blank data line as a card
// whose fields are all blank (defaults), not as white space (lsdyna-format.md §5, "Blank data lines"), so
// the cards after it are read one card late: a required field left blank on the blank line, values in the
// fields of the card after theirs, the last card read as lines too many, a *PART's card 2 missing. The
// symptoms land after the line a person typed; the cause is the blank line (DK034).
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// Whether a card line is blank (spaces, tabs and a carriage return only).
bool blank_card_line(std::string_view text);

// A blank line a block read as a card read once, with a data line after it in the block.
struct BlankCardLine {
    grammar::CardLinePtr line = nullptr;
    const keywords::CardSpec* card = nullptr;
    bool text_card = false;  // a heading or title card: a blank one is a blank title, often meant
};

// Whether the block's lines, the blank line left out, read without a finding (the caller decodes them).
using ReadsWithout = std::function<bool(grammar::CardLinePtr blank)>;

// DK034 at one of `blanks` (in block order), when out[from, end) shows that it was read as a card too many:
// a required field blank on it (DK008); a reading finding of the block from it on (a value that does not
// fit its field, lines past the last card, the keyword missing a card) that the block read without it does
// not make; or, failing that, lines past the last card or a card missing. The findings it explains become
// its notes (all the block's reading findings after it only when the block reads cleanly without it).
// Returns whether it fired.
bool diagnose_blank_card(const grammar::RawDeck& deck, const grammar::Block& block,
                         std::span<const BlankCardLine> blanks, const ReadsWithout& reads_without,
                         std::vector<diag::Diagnostic>& out, std::size_t from);

}  // namespace sphdeck::model
