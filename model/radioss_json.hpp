// An OpenRadioss deck as JSON for `sphdeck dump` (docs/json.md): each decoded block with the
// fields of its single cards as read, unknown keywords, node and particle counts.
#pragma once

#include <nlohmann/json.hpp>

#include "grammar/raw_deck.hpp"
#include "model/model.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::model {

// `list_particles`: as dump --particles, every particle in `particles.list`.
nlohmann::ordered_json radioss_to_json(const RadiossReading& reading, const Model& model, const grammar::RawDeck& deck,
                                       bool list_particles = false);

}  // namespace sphdeck::model
