// The decoded model as JSON (`sphdeck dump --format json`, documented in docs/json.md).
#pragma once

#include <nlohmann/json.hpp>

#include "grammar/raw_deck.hpp"
#include "model/model.hpp"

namespace sphdeck::model {

struct DumpOptions {
    bool particles = false;  // list every particle, not only counts
};

// Fields keep the schema order (ordered_json), as a user reads the card.
// `particles`: the count, the count per part and, with `list_each`, every particle.
nlohmann::ordered_json particles_json(const Model& model, bool list_each);

nlohmann::ordered_json to_json(const Model& model, const grammar::RawDeck& deck, const DumpOptions& options = {});

}  // namespace sphdeck::model
