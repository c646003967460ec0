#include "model/bulk_reuse.hpp"

#include <cstring>

#include "grammar/earlier_text.hpp"

namespace sphdeck::model {

DecodedBulkBlock decoded_bulk_block(const grammar::RawDeck& deck, const grammar::Block& block,
                                    const keywords::CardSpec& card, std::size_t first_slot) {
    DecodedBulkBlock out;
    out.keyword = block.keyword;
    out.card = &card;
    out.format = block.format;
    out.first_line = block.first_line;
    out.line_count = block.line_count;
    out.first_slot = first_slot;
    if (block.line_count == 0) return out;
    const grammar::CardLine& first = *deck.begin_lines(block);
    const grammar::CardLine& last = *(deck.end_lines(block) - 1);
    out.file = first.file;
    out.begin = first.offset;
    out.end = last.file == first.file ? last.offset + deck.length(last) : first.offset;  // one file: never else
    return out;
}

const DecodedBulkBlock* same_bulk_block(const BulkReuse& previous, const grammar::RawDeck& deck,
                                        const grammar::Block& block, const keywords::CardSpec& card) {
    if (block.line_count == 0) return nullptr;
    const DecodedBulkBlock now = decoded_bulk_block(deck, block, card, 0);
    // A block whose lines run into another file (never made by the reader) is not compared.
    if (now.end <= now.begin || (deck.end_lines(block) - 1)->file != now.file) return nullptr;
    const std::string_view text = deck.sources.file(now.file).text.view();
    for (const DecodedBulkBlock& before : previous.blocks) {
        if (before.card != &card || before.format != block.format || before.line_count != block.line_count ||
            before.end - before.begin != now.end - now.begin || before.keyword != block.keyword)
            continue;
        if (const grammar::SplicedLines* changed = previous.changed;
            changed && changed->file == before.file && changed->file == now.file) {
            // Bytes before the splice are the same, bytes after it moved with it.
            if (before.end <= changed->begin && now.begin == before.begin) return &before;
            if (before.begin >= changed->old_end && now.begin - changed->new_end == before.begin - changed->old_end &&
                now.begin >= changed->new_end)
                return &before;
            // Bytes the edit replaced lie in it: not the same (no compare of a 100 MB block to find it).
            if (before.begin < changed->old_end && changed->begin < before.end) continue;
        }
        const grammar::SourceFile& old_file = previous.deck.sources.file(before.file);
        const std::string_view old_text = old_file.text.view();
        if (before.end > old_text.size() || now.end > text.size()) continue;
        const std::string_view block_now = text.substr(now.begin, now.end - now.begin);
        const grammar::TextSince since = grammar::text_since(old_file.path, old_text, previous.documents);
        if (since.state == grammar::TextSince::Fate::Unknown) continue;
        if (since.earlier ? since.earlier->equals(before.begin, block_now)
                          : std::memcmp(old_text.data() + before.begin, block_now.data(), block_now.size()) == 0)
            return &before;
    }
    return nullptr;
}

}  // namespace sphdeck::model
