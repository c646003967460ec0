// NEND ranges of *ELEMENT_SPH (NID..NEND, one particle per node) are bounded by the nodes the
// deck defines: a range longer than that is a located error, not an allocation of that many
// particles (a 40-column card with NEND 1e15 once asked for 1e15 of them).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"
#include "model/card_decoder.hpp"

namespace sphdeck::model {

// Lines of the deck's *NODE blocks: an upper bound of the nodes it defines, known before decoding.
std::size_t node_lines(const grammar::RawDeck& deck);

// Particles an *ELEMENT_SPH card's range generates beyond NID itself (NEND - NID), 0 without a
// range. `values` are the card's decoded NID, PID, MASS, NEND.
std::size_t range_extra(const std::vector<FieldValue>& values);

// The deck's budget of range-generated particles, spent range by range in deck order: one range
// may generate at most as many particles as the deck has node lines, all ranges together twice that.
class RangeBudget {
public:
    explicit RangeBudget(const grammar::RawDeck& deck) : deck_(deck) {}

    // The problem with a range of `extra` particles at this point of the deck (nullopt: taken
    // from the budget). Lines are counted on the first range: most decks have none.
    std::optional<std::string> take(std::size_t extra);
    // Only the one-range bound (a range alone longer than the node lines): safe on several
    // threads at once after nodes() has been called once.
    std::optional<std::string> check_alone(std::size_t extra);
    std::size_t nodes();

private:
    const grammar::RawDeck& deck_;
    std::optional<std::size_t> nodes_;
    std::size_t spent_ = 0;
};

// The error for a refused range, at NEND (`nend`: its span).
diag::Diagnostic range_error(grammar::Span nend, const std::string& problem);

}  // namespace sphdeck::model
