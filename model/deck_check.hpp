// The syntax pass over a read deck: every block with a schema has its cards decoded and
// checked (types, widths, ranges, card counts); unknown keywords are counted (DK001).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"
#include "model/card_decoder.hpp"

namespace sphdeck::model {

struct DeckSummary {
    std::size_t particles = 0;        // *ELEMENT_SPH particles, NEND ranges expanded
    std::size_t unknown_keywords = 0; // blocks without a schema
};

// Called for every decoded card: the block, its keyword match, the card spec and the values.
using CardVisitor = std::function<void(const grammar::Block&, const keywords::KeywordMatch&,
                                       const keywords::CardSpec&, const grammar::CardLine&,
                                       const std::vector<FieldValue>&)>;

// Decodes every card of every known block, reporting into `out`; `visit` (optional) sees each
// decoded card in deck order, which is how the model is built without decoding twice.
DeckSummary check_deck(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out,
                       const CardVisitor& visit = {});

}  // namespace sphdeck::model
