// The editor's re-check (issue 45): a *NODE or *ELEMENT_SPH block of millions of lines that an edit
// left alone is not decoded again. A check notes the bulk blocks it decoded cleanly (every line on the
// plain path: numbers in their columns, no parameter, no finding, no NEND range), and the next check
// copies such a block's nodes or particles from the last model when its text is the same, byte for
// byte. What a clean block decodes to depends on its bytes, its card and its format alone.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "grammar/deck_splice.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

struct Model;

// One bulk block a check decoded cleanly.
struct DecodedBulkBlock {
    std::string keyword;                       // as Block::keyword ("*ELEMENT_SPH_VOLUME" reads volumes)
    const keywords::CardSpec* card = nullptr;  // every line is this card
    grammar::CardFormat format = grammar::CardFormat::Standard;
    grammar::FileId file = 0;
    std::size_t begin = 0, end = 0;  // its lines in the file's text: the first's start to the last's end
    std::uint32_t first_line = 0;    // its first line in RawDeck::lines
    std::uint32_t line_count = 0;
    std::size_t first_slot = 0;  // its nodes or particles in the model, one a line
};

// The columns a re-check moved out of the last model (BulkReuse::take_from): empty there now.
struct BulkTaken {
    bool nodes = false, particles = false;           // Model::nodes, Model::particles
    std::size_t node_count = 0, particle_count = 0;  // their sizes when taken
    bool any() const { return nodes || particles; }
};

// The last check: its deck and model (alive during the re-check) and the blocks it decoded cleanly.
// `changed`: where this deck's reading was spliced into that deck's (null when read in full): blocks
// outside it are known the same without comparing their bytes.
struct BulkReuse {
    const grammar::RawDeck& deck;
    const Model& model;
    const std::vector<DecodedBulkBlock>& blocks;
    const grammar::SplicedLines* changed = nullptr;
    // When set (`model` itself, which its owner is about to drop): a block that is the whole of its
    // column there is moved instead of copied (no 45 MB copy of a 1M-particle deck's columns an edit),
    // and `taken` says which columns went; the rest is copied as before.
    Model* take_from = nullptr;
    BulkTaken* taken = nullptr;
    // The texts held in memory the re-check reads (an editor's buffers, null: none): a buffer the last
    // check read may have been patched in place since; its old bytes are then read as it tells
    // (grammar/earlier_text.hpp).
    const grammar::FileOverlay* documents = nullptr;
};

// The block of `previous` that `block` of `deck` may be copied from: same keyword, card, format and
// line count, the same bytes. Null when none is.
const DecodedBulkBlock* same_bulk_block(const BulkReuse& previous, const grammar::RawDeck& deck,
                                        const grammar::Block& block, const keywords::CardSpec& card);

// `block` of `deck` as a DecodedBulkBlock whose nodes or particles start at `first_slot`.
DecodedBulkBlock decoded_bulk_block(const grammar::RawDeck& deck, const grammar::Block& block,
                                    const keywords::CardSpec& card, std::size_t first_slot);

}  // namespace sphdeck::model
