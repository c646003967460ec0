// A big OpenRadioss file read in chunks (grammar/line_chunks.hpp): the chunks' lines were found and sorted
// on all threads; here they are read in file order, the header, comment and #include lines by the line
// grammar as the line-by-line reading reads them, each run of data lines inside an open block in one step.
#include "grammar/line_chunks.hpp"
#include "grammar/radioss/deck_reader.hpp"

namespace sphdeck::grammar::radioss {

void DeckReader::read_chunked(const SourceText& text, std::size_t chunk_bytes) {
    const char* const base = text.data();
    const char* const end = base + text.size();
    const std::size_t first = text.view().starts_with("\xEF\xBB\xBF") ? 3 : 0;  // the grammar's byte_order_mark
    SplitLines split = split_lines(text, first, LineSyntax::Radioss, chunk_bytes);
    if (deck_.lines.capacity() < deck_.lines.size() + split.lines)
        deck_.lines.reserve(deck_.lines.size() + split.lines);
    for (LineChunk& chunk : split.chunks) {
        walk_chunk(
            chunk, [&](std::uint32_t at) { grammar_line(base + at, end); },
            [&](const std::uint32_t* starts, std::size_t count) { data_lines(starts, count, end); });
        chunk = {};  // its offsets are the deck's card lines now
    }
}

// What on_data and on_empty do to each line of the run: where they do more than add a card line to the
// open block (no block, after /END or #enddata, an include's preamble), the grammar reads the lines one
// by one.
void DeckReader::data_lines(const std::uint32_t* starts, std::size_t count, const char* text_end) {
    OpenFile& f = current();
    if (!block_ || ended_ || f.done || in_preamble()) {
        for (std::size_t i = 0; i < count; ++i) grammar_line(f.base + starts[i], text_end);
        return;
    }
    for (std::size_t i = 0; i < count; ++i) deck_.lines.push_back(CardLine{f.id, ++f.line, starts[i]});
    deck_.blocks[*block_].line_count += static_cast<std::uint32_t>(count);
    deck_.stats.cards += count;
}

}  // namespace sphdeck::grammar::radioss
