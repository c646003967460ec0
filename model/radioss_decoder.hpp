// Decodes a Radioss RawDeck (grammar/radioss/) into the format-neutral Model, with the
// Radioss-only facts in Model::radioss (model/radioss_facts.hpp says what lands where).
#pragma once

#include <map>
#include <set>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"
#include "model/deck_check.hpp"
#include "model/model.hpp"

namespace sphdeck::model {

// Reads every block through the card tables of grammar/radioss/cards.hpp, in the deck's format
// version (Invers of /BEGIN). Card-level problems (DK002-DK009, DK016, DK018, RAD025) and
// unknown keywords (DK001) go to `out`.
Model build_radioss_model(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out,
                          DeckSummary* summary = nullptr);

// The deck version a Radioss RawDeck is read in: Invers on its /BEGIN, or the latest.
int radioss_version(const grammar::RawDeck& deck);

// The id cells of the starter's /NODE lines defining each of `ids`, in reading order (a scan of
// the /NODE blocks, for rare reports such as duplicated ids).
std::map<long long, std::vector<grammar::Span>> radioss_node_lines(const grammar::RawDeck& deck,
                                                                   const std::set<long long>& ids);

}  // namespace sphdeck::model
