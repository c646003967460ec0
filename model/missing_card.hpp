// A card line cut from a keyword whose cards are read once, the `$#` ruler of the card after it left
// standing: LS-DYNA reads the cards in order, so the line under that ruler is read as the cut card, and
// every line after it one card early. The symptoms (a real in an integer field, a required field read as
// blank, "missing its Card 2" on the keyword line, a rule's finding on a value read from the wrong field)
// say nothing of the cut; the ruler says which card the line was typed as (DK035).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// A data line whose `$#` ruler names a card after the one it is read as (and not that one).
struct EarlyCardLine {
    grammar::CardLinePtr line = nullptr;
    std::vector<const keywords::CardSpec*> missing;  // the cards from the one it is read as to the named one
    const keywords::CardSpec* named = nullptr;       // the card the ruler names
    std::size_t read_as_index = 0;                   // the card it is read as, in the keyword's cards
};

// The line's ruler (the `$#` or `$` comment right above it) names a card of the keyword's `cards` after `read_as`,
// the card the line is read as, and not that one: what it was typed as. Nothing otherwise, and nothing when
// the rulers stacked above the line are a header of several lines, one of them naming `read_as` and as many
// data lines under them as rulers (`$# n1 n2`, `$# lcid mlc1` above both cards).
std::optional<EarlyCardLine> early_card_line(const grammar::RawDeck& deck, const grammar::Block& block,
                                             grammar::CardLinePtr line, const keywords::CardSpec& read_as,
                                             std::span<const keywords::CardSpec* const> cards);

// DK035 at `early.line`, folding the block's reading findings of out[from, end) from that line on (and the
// keyword's missing card on its keyword line). Its fix (unsafe: the cut card's values are lost) inserts a
// blank line (a card of defaults) above the ruler for each card missing, when a blank card is read
// without an error (no required field without a default).
void diagnose_missing_card(const grammar::RawDeck& deck, const grammar::Block& block, const EarlyCardLine& early,
                           std::vector<diag::Diagnostic>& out, std::size_t from);

}  // namespace sphdeck::model
