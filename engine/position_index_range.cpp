// The decoded card lines of a range of lines of one file (engine/position_index.hpp), for the
// features that colour or annotate every value of a screenful (semantic tokens, inlay hints).
#include <algorithm>

#include "engine/position_index.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::engine {
namespace {

// A block this long is decoded line by line when only part of it is asked for.
constexpr std::uint32_t kWalkWholeBlockBelow = 512;

// The first card line of `block` at or after `line` (card lines are in line order).
grammar::CardLinePtr first_line_from(const grammar::RawDeck& deck, const grammar::Block& block, std::uint32_t line) {
    return std::lower_bound(deck.begin_lines(block), deck.end_lines(block), line,
                            [](const grammar::CardLine& l, std::uint32_t n) { return l.line < n; });
}

bool only_repeated_card(const grammar::Block& block) {
    const auto match = decodable_match(block);
    if (!match) return false;
    const auto cards = keywords::cards_for(*match);
    return cards.size() == 1 && cards[0]->repeat == keywords::CardRepeat::Repeated && !cards[0]->unknown_layout &&
           keywords::repeat_group_size(*match) == 0;
}

void visit_dyna(const grammar::RawDeck& deck, const grammar::Block& block, LineRange range,
                const DecodedLineVisitor& visit) {
    const bool partial = block.line_count >= kWalkWholeBlockBelow;
    if (partial && only_repeated_card(block)) {
        for (grammar::CardLinePtr l = first_line_from(deck, block, range.first);
             l != deck.end_lines(block) && l->line <= range.last; ++l)
            if (l->file != block.span.file)
                continue;
            else if (auto card = dyna_card_at(deck, block, l))
                visit({&block, l, &*card, nullptr});
        return;
    }
    walk_dyna_block(deck, block, [&](const DynaCard& card) {
        if (card.line->file != block.span.file) return true;
        if (card.line->line > range.last) return false;
        if (range.holds(card.line->line)) visit({&block, card.line, &card, nullptr});
        return true;
    });
}

void visit_radioss(const grammar::RawDeck& deck, const grammar::Block& block, LineRange range,
                   const DecodedLineVisitor& visit) {
    if (!radioss_keyword(block) || block.line_count == 0) return;
    const int version = model::radioss_version(deck);
    const grammar::CardLinePtr first = deck.begin_lines(block);
    if (range.holds(first->line))
        if (auto card = radioss_card_at(deck, block, first, version); card && card->title)
            visit({&block, first, nullptr, &*card});
    walk_radioss_block(deck, block, version, [&](grammar::CardLinePtr line, const RadiossCard& card) {
        if (line->file != block.span.file) return true;
        if (line->line > range.last) return false;
        if (range.holds(line->line)) visit({&block, line, nullptr, &card});
        return true;
    });
}

}  // namespace

bool is_bulk_block(const grammar::Block& block, bool radioss) {
    if (!radioss) return only_repeated_card(block);
    static constexpr std::string_view kBulk[] = {"/NODE",    "/SPHCEL", "/BRICK",  "/SHELL", "/SH3N",     "/TETRA4",
                                                 "/TETRA10", "/BEAM",   "/SPRING", "/TRUSS", "/INISPHCEL"};
    return std::any_of(std::begin(kBulk), std::end(kBulk), [&](std::string_view name) {
        return block.keyword.rfind(name, 0) == 0 &&
               (block.keyword.size() == name.size() || block.keyword[name.size()] == '/');
    });
}

std::vector<const grammar::Block*> blocks_in_range(const grammar::RawDeck& deck, grammar::FileId file,
                                                   LineRange range) {
    std::vector<const grammar::Block*> out;
    for (const grammar::Block& block : deck.blocks) {
        if (block.span.file != file || block.span.line > range.last) continue;
        if (block_last_line(deck, block) < range.first) continue;
        out.push_back(&block);
    }
    return out;
}

void visit_card_lines(const grammar::RawDeck& raw, bool radioss, grammar::FileId file, LineRange range,
                      const RangeWalkOptions& options, const DecodedLineVisitor& visit) {
    for (const grammar::Block* block : blocks_in_range(raw, file, range)) {
        if (options.max_block_lines != 0 && block->line_count > options.max_block_lines) continue;
        if (options.skip_bulk && is_bulk_block(*block, radioss)) continue;
        if (radioss)
            visit_radioss(raw, *block, range, visit);
        else
            visit_dyna(raw, *block, range, visit);
    }
}

}  // namespace sphdeck::engine
