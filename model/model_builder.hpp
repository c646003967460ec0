// Builds the Model while the syntax pass decodes the cards (one decode per line), then turns
// the keyword records into the typed parts of the model.
#pragma once

#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"
#include "model/deck_check.hpp"
#include "model/model.hpp"

namespace sphdeck::model {

class ModelBuilder {
public:
    explicit ModelBuilder(const grammar::RawDeck& deck);

    // The CardVisitor of check_deck.
    void on_card(const grammar::Block& block, const keywords::KeywordMatch& match, const keywords::CardSpec& card,
                 const grammar::CardLine& line, const std::vector<FieldValue>& values);

    // Typed extraction; reports model-level findings (IDIM without a value) into `out`.
    Model finish(std::vector<diag::Diagnostic>& out);

private:
    void add_node(const std::vector<FieldValue>& values);
    void add_particles(const grammar::Block& block, const std::vector<FieldValue>& values,
                       const grammar::CardLine& line);

    const grammar::RawDeck& deck_;
    Model model_;
    const grammar::Block* current_block_ = nullptr;
};

// Reads the whole deck into a Model in one pass: decode + build. Diagnostics go to `out`.
Model build_model(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, DeckSummary* summary = nullptr);

}  // namespace sphdeck::model
