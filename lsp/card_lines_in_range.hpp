// The decoded card lines of one file of a checked deck within a range of lines, for the features
// that colour or annotate every value of a screenful (semantic tokens, inlay hints). A big block
// of one repeated card (*NODE, *ELEMENT_SPH) is decoded only on the lines asked for, so a range
// costs what it shows, not what lies before it.
#pragma once

#include <cstdint>
#include <functional>

#include "grammar/raw_deck.hpp"
#include "lsp/checked_deck.hpp"
#include "engine/position_index.hpp"

namespace sphdeck::lsp {

struct LineRange {
    std::uint32_t first = 1;  // 1-based, inclusive
    std::uint32_t last = 0;   // 1-based, inclusive
    bool holds(std::uint32_t line) const { return line >= first && line <= last; }
};

// A bulk block: one repeated card line after another (nodes, particles, elements), where the
// values are many and alike. Judged from the schema (LS-DYNA) or the header (Radioss).
bool is_bulk_block(const grammar::Block& block, bool radioss);

// One card line as the decoders read it; exactly one of `dyna` and `radioss` is set.
struct DecodedLine {
    const grammar::Block* block = nullptr;
    const grammar::CardLine* line = nullptr;
    const engine::DynaCard* dyna = nullptr;
    const engine::RadiossCard* radioss = nullptr;  // with `title` set on a Radioss title line
};
using DecodedLineVisitor = std::function<void(const DecodedLine&)>;

struct RangeWalkOptions {
    // Blocks with more card lines than this are left out (0: none left out).
    std::uint32_t max_block_lines = 0;
    // Bulk blocks are left out.
    bool skip_bulk = false;
};

// Calls `visit` for every decoded card line of `file` in `range`, in line order within a block.
void visit_card_lines(const CheckedDeck& deck, grammar::FileId file, LineRange range, const RangeWalkOptions& options,
                      const DecodedLineVisitor& visit);

// The blocks of `file` that overlap `range` (keyword line to last card line).
std::vector<const grammar::Block*> blocks_in_range(const grammar::RawDeck& deck, grammar::FileId file, LineRange range);

}  // namespace sphdeck::lsp
