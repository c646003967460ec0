// From keyword records (and, for keywords without a schema, the raw blocks) to the typed
// parts of the Model: controls, sections, parts, materials, EOS, boxes, planes, sets.
#pragma once

#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"
#include "model/model.hpp"

namespace sphdeck::model {

void extract_typed(const grammar::RawDeck& deck, Model& model, std::vector<diag::Diagnostic>& out);

}  // namespace sphdeck::model
