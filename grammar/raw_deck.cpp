#include "grammar/raw_deck.hpp"

namespace sphdeck::grammar {

RawDeck::RawDeck() = default;
RawDeck::RawDeck(const RawDeck&) = default;
RawDeck::RawDeck(RawDeck&&) = default;
RawDeck& RawDeck::operator=(const RawDeck&) = default;
RawDeck& RawDeck::operator=(RawDeck&&) noexcept = default;
RawDeck::~RawDeck() = default;

}  // namespace sphdeck::grammar
