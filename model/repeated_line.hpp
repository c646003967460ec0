// A data line pasted twice (a copy slip) inside a keyword whose cards are read once: LS-DYNA reads the copy
// as the next card, and every line after it one card late, so the symptoms (a real in an integer field of
// the next card, the last card read as a line too many) land after the copy, never naming it (DK036).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"
#include "model/blank_card.hpp"

namespace sphdeck::model {

// A data line whose text is the data line's right above it (not blank), read as `card`.
struct RepeatedLine {
    grammar::CardLinePtr line = nullptr;
    const keywords::CardSpec* card = nullptr;
};

// Whether `line` repeats the block's data line before it (the same text but trailing blanks, not blank; comment
// lines between them are no matter): a copy candidate.
bool repeats_line_above(const grammar::RawDeck& deck, const grammar::Block& block, grammar::CardLinePtr line);

// DK036 at the first of `copies` (in block order) from whose line on the block misreads (a reading finding of
// out[from, end): a value that does not fit its field, lines past the last card, a card missing) and that the
// block read without it does not make: the copy was read as a card too many. Those findings become its notes.
// Returns whether it fired.
bool diagnose_repeated_line(const grammar::RawDeck& deck, const grammar::Block& block,
                            std::span<const RepeatedLine> copies, const ReadsWithout& reads_without,
                            std::vector<diag::Diagnostic>& out, std::size_t from);

}  // namespace sphdeck::model
