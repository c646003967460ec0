// A big OpenRadioss file read in chunks (grammar/line_chunks.hpp): the chunks' lines were found and sorted
// on all threads; here they are read in file order, the header, comment and #include lines by the line
// grammar as the line-by-line reading reads them, each run of data lines inside an open block in one step.
#include "grammar/line_chunks.hpp"
#include "grammar/radioss/deck_reader.hpp"

namespace sphdeck::grammar::radioss {

bool DeckReader::read_chunked(const SourceText& text, std::size_t chunk_bytes) {
    const char* const end = text.data() + text.size();
    return read_in_chunks(
        text, LineSyntax::Radioss, chunk_bytes, deck_.lines, [&](const char* line) { grammar_line(line, end); },
        [&](const std::uint32_t* starts, std::size_t count) { data_lines(starts, count, end); });
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
    deck_.lines.push_back_lines(f.id, f.line + 1, starts, count);
    f.line += static_cast<std::uint32_t>(count);
    deck_.blocks[*block_].line_count += static_cast<std::uint32_t>(count);
    deck_.stats.cards += count;
}

}  // namespace sphdeck::grammar::radioss
