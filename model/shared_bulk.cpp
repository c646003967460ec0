#include "model/shared_bulk.hpp"

#include <cstring>
#include <optional>

#include "model/model.hpp"

namespace sphdeck::model {
namespace {
// Where a block's bytes lie: one file, the first line's start to the last line's end.
struct BlockBytes {
    const grammar::SourceText* text = nullptr;
    std::size_t begin = 0, end = 0;
};

std::optional<BlockBytes> bytes_of(const grammar::RawDeck& deck, const grammar::Block& block) {
    if (block.line_count == 0) return std::nullopt;
    const grammar::CardLine& first = *deck.begin_lines(block);
    const grammar::CardLine& last = *(deck.end_lines(block) - 1);
    if (first.file != last.file) return std::nullopt;  // never made by the reader: not shared
    const grammar::SourceText& text = deck.sources.file(first.file).text;
    const std::size_t end = last.offset + deck.length(last);
    if (end <= first.offset || end > text.size()) return std::nullopt;
    return BlockBytes{&text, first.offset, end};
}

bool same_key(const SharedBulkBlock& kept, const grammar::Block& block, const keywords::CardSpec& card,
              const BlockBytes& bytes) {
    return kept.card == &card && kept.format == block.format && kept.line_count == block.line_count &&
           kept.end - kept.begin == bytes.end - bytes.begin && kept.keyword == block.keyword;
}

// The same bytes: the same place in the same text (a mapping or a shared buffer the kept block holds
// alive, so no other text can stand at that address), else compared.
bool same_bytes(const SharedBulkBlock& kept, const BlockBytes& bytes) {
    const char* here = bytes.text->data() + bytes.begin;
    const char* there = kept.text.data() + kept.begin;
    return here == there || std::memcmp(here, there, bytes.end - bytes.begin) == 0;
}
}  // namespace

std::size_t SharedBulkBlock::bytes() const {
    return ids.bytes() + (x.size() + y.size() + z.size() + mass.size()) * sizeof(double) + part.bytes();
}

bool BulkProvenance::covers(const Model& model) const {
    return node_count == model.nodes.id.size() && particle_count == model.particles.size() && particle_count > 0;
}

void BulkProvenance::add(std::shared_ptr<const SharedBulkBlock> block) {
    if (!block) return;
    (block->particles ? particle_count : node_count) += block->ids.size();
    (block->particles ? particles : nodes).push_back(std::move(block));
}

std::shared_ptr<const SharedBulkBlock> SharedBulkBlocks::find(const grammar::RawDeck& deck, const grammar::Block& block,
                                                              const keywords::CardSpec& card) const {
    const std::optional<BlockBytes> bytes = bytes_of(deck, block);
    if (!bytes) return nullptr;
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& kept : blocks_)
        if (same_key(*kept, block, card, *bytes) && same_bytes(*kept, *bytes)) {
            ++counters_.shared;
            return kept;
        }
    return nullptr;
}

std::shared_ptr<const SharedBulkBlock> SharedBulkBlocks::offer(const grammar::RawDeck& deck,
                                                               const grammar::Block& block,
                                                               const keywords::CardSpec& card, const Model& model,
                                                               std::size_t first_slot) {
    const std::optional<BlockBytes> bytes = bytes_of(deck, block);
    if (!bytes) return nullptr;
    if (auto kept = find(deck, block, card)) return kept;  // another deck (--jobs) kept it meanwhile
    auto made = std::make_shared<SharedBulkBlock>();
    made->keyword = block.keyword;
    made->card = &card;
    made->format = block.format;
    made->line_count = block.line_count;
    made->particles = block.keyword.rfind("*ELEMENT_SPH", 0) == 0;
    const auto from = static_cast<std::ptrdiff_t>(first_slot);
    const auto to = from + static_cast<std::ptrdiff_t>(block.line_count);
    if (made->particles) {
        const Particles& p = model.particles;
        if (static_cast<std::size_t>(to) > p.size()) return nullptr;
        made->ids.append(p.node, first_slot, block.line_count);
        made->part.append(p.part, first_slot, block.line_count);
        made->mass.assign(p.mass.begin() + from, p.mass.begin() + to);
        made->volume = block.keyword.find("_VOLUME") != std::string::npos;
    } else {
        const Nodes& n = model.nodes;
        if (static_cast<std::size_t>(to) > n.id.size()) return nullptr;
        made->ids.append(n.id, first_slot, block.line_count);
        made->x.assign(n.x.begin() + from, n.x.begin() + to);
        made->y.assign(n.y.begin() + from, n.y.begin() + to);
        made->z.assign(n.z.begin() + from, n.z.begin() + to);
    }
    // A mapped or shared text is kept by reference; an owned one (a file under 1 MiB, a buffer) by a
    // copy of the block's bytes alone.
    if (bytes->text->mapped()) {
        made->text = *bytes->text;
        made->begin = bytes->begin, made->end = bytes->end;
    } else {
        made->text = grammar::SourceText(std::string(bytes->text->substr(bytes->begin, bytes->end - bytes->begin)));
        made->begin = 0, made->end = bytes->end - bytes->begin;
    }
    const std::size_t size = made->bytes();
    if (size > budget_) return nullptr;
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& kept : blocks_)  // kept by another deck (--jobs) while this one copied its columns
        if (same_key(*kept, block, card, *bytes) && same_bytes(*kept, *bytes)) return kept;
    while (held_ + size > budget_ && !blocks_.empty()) {
        held_ -= blocks_.front()->bytes();
        blocks_.pop_front();
    }
    blocks_.push_back(made);
    held_ += size;
    ++counters_.kept;
    return made;
}

SharedBulkBlocks::Counters SharedBulkBlocks::counters() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return counters_;
}

}  // namespace sphdeck::model
