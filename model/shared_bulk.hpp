// Decoded bulk blocks shared across the decks of one run (issue 40 item 4): 32 load cases that
// include one 100 MB mesh decode its *NODE and *ELEMENT_SPH blocks once. A block is shared only when
// it decoded cleanly (model/bulk_reuse.hpp: every line on the plain path, numbers in their columns,
// no `&` parameter, no finding, no NEND range): what it decodes to then depends on its bytes, its
// keyword, its card and its card format alone, so every deck that holds the same bytes under the same
// keyword, card and format gets the same nodes or particles, and no finding is lost. Safe to use from
// several threads at once (`check --jobs N`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"
#include "model/id_column.hpp"
#include "text/source_text.hpp"

namespace sphdeck::model {

struct Model;

// One cleanly decoded block: its key and its values, never changed once made.
struct SharedBulkBlock {
    std::string keyword;  // as Block::keyword ("*ELEMENT_SPH_VOLUME" reads volumes)
    const keywords::CardSpec* card = nullptr;
    grammar::CardFormat format = grammar::CardFormat::Standard;
    std::uint32_t line_count = 0;
    grammar::SourceText text;        // the file the block was read from: kept, so its bytes stay put
    std::size_t begin = 0, end = 0;  // the block's bytes in `text`
    bool particles = false;          // *ELEMENT_SPH (else *NODE)
    IdColumn ids;                    // node ids, or the particles' nodes
    std::vector<double> x, y, z;     // nodes only
    IdColumn part;                   // particles only
    std::vector<double> mass;        // particles only
    std::uint8_t volume = 0;         // particles only: *ELEMENT_SPH_VOLUME
    std::size_t bytes() const;       // what its columns hold
};

// The shared blocks a model's nodes and particles were taken from or kept as, in model order. When
// they hold every node and every particle (`covers`), two models with the same lists hold the same
// nodes and particles (their lines in the deck aside): what the geometry preview is keyed by.
struct BulkProvenance {
    std::vector<std::shared_ptr<const SharedBulkBlock>> nodes, particles;
    std::size_t node_count = 0, particle_count = 0;  // what they hold
    bool covers(const Model& model) const;
    void add(std::shared_ptr<const SharedBulkBlock> block);
};

class SharedBulkBlocks {
public:
    // `budget`: bytes of columns kept at most; the oldest blocks go first past it.
    explicit SharedBulkBlocks(std::size_t budget = std::size_t{2} << 30) : budget_(budget) {}

    // The shared block `block` of `deck` decodes to, read as `card`: same keyword, card, format,
    // line count and bytes. Null when none is kept.
    std::shared_ptr<const SharedBulkBlock> find(const grammar::RawDeck& deck, const grammar::Block& block,
                                                const keywords::CardSpec& card) const;

    // `block` of `deck` decoded cleanly into `model`'s nodes or particles from `first_slot` on, one a
    // line: kept for the next decks, unless the same block is kept already. Returns the kept block.
    std::shared_ptr<const SharedBulkBlock> offer(const grammar::RawDeck& deck, const grammar::Block& block,
                                                 const keywords::CardSpec& card, const Model& model,
                                                 std::size_t first_slot);

    struct Counters {
        std::size_t kept = 0, shared = 0;  // blocks decoded and kept, blocks given to another deck
    };
    Counters counters() const;

private:
    mutable std::mutex mutex_;
    std::list<std::shared_ptr<const SharedBulkBlock>> blocks_;  // oldest first
    std::size_t budget_ = 0, held_ = 0;
    mutable Counters counters_;
};

}  // namespace sphdeck::model
