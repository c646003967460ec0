// A big LS-DYNA file read in chunks (grammar/line_chunks.hpp): the chunks' lines were found and sorted on
// all threads; here they are read in file order, the keyword, comment and PGP lines by the line grammar
// as the line-by-line reading reads them, each run of data lines inside an open block in one step.
#include "grammar/dyna/deck_reader.hpp"
#include "grammar/line_chunks.hpp"

namespace sphdeck::grammar::dyna {

bool DeckReader::read_chunked(const SourceText& text, std::size_t chunk_bytes) {
    const char* const end = text.data() + text.size();
    return read_in_chunks(
        text, LineSyntax::Dyna, chunk_bytes, deck_.lines, [&](const char* line) { grammar_line(line, end); },
        [&](const std::uint32_t* starts, std::size_t count) { data_lines(starts, count, end); });
}

// What on_data does to each line of the run: where it does more than add a card line to the open block
// (no block, after *END, inside *COMMENT or encrypted text), the grammar reads the lines one by one.
void DeckReader::data_lines(const std::uint32_t* starts, std::size_t count, const char* text_end) {
    OpenFile& f = current();
    if (!f.block || f.in_encrypted || f.ended || f.in_comment_block) {
        for (std::size_t i = 0; i < count; ++i) grammar_line(f.base + starts[i], text_end);
        return;
    }
    deck_.lines.push_back_lines(f.id, f.line + 1, starts, count);
    f.line += static_cast<std::uint32_t>(count);
    deck_.blocks[*f.block].line_count += static_cast<std::uint32_t>(count);
    deck_.stats.cards += count;
}

}  // namespace sphdeck::grammar::dyna
