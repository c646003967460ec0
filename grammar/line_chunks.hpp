// The parallel half of the line readers (issue 40): a big file's text is cut at line boundaries into
// chunks, and on all threads each chunk's lines are found and sorted into plain data lines and lines the
// reader's grammar must read (keywords, headers, comments, PGP markers...). The reader then walks the
// chunks in file order on one thread: it hands the grammar's lines to its line grammar one by one, as the
// line-by-line reading does, and takes each run of plain data lines in one step. A line counts as plain
// data only where the grammar could match nothing but a data line; any doubt sends it to the grammar, so
// the blocks, spans and findings are those of the line-by-line reading, on any chunk size and thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "text/source_text.hpp"

namespace sphdeck::grammar {

// Which line grammar decides what a plain data line is.
enum class LineSyntax : std::uint8_t { Dyna, Radioss };

struct LineChunk {
    std::vector<std::uint32_t> starts;   // byte offset in the file of each line that begins in the chunk
    std::vector<std::uint32_t> special;  // indexes into `starts` of the lines for the grammar, ascending
    bool comment_holds_marker = false;   // a line starting with '$' or '#' holds text::directive_marker
};

struct SplitLines {
    std::vector<LineChunk> chunks;      // in file order
    std::size_t lines = 0;              // physical lines of the file
    bool comment_holds_marker = false;  // in any chunk (text::SourceFile::comment_holds_marker)
};

// Files at least this long are read in chunks; shorter ones line by line (threads would cost more).
inline constexpr std::size_t chunked_reading_min_bytes = std::size_t{4} << 20;
inline constexpr std::size_t default_line_chunk_bytes = std::size_t{2} << 20;
// set_line_chunk_bytes(read_line_by_line): every file line by line (the reference of the tests).
inline constexpr std::size_t read_line_by_line = ~std::size_t{0};

// The chunk size the readers use from now on, in this process: 0 chooses by the file's size (the default),
// read_line_by_line never cuts, N cuts every file every N bytes (tests cut small decks anywhere). The
// environment variable SPHDECK_READER_CHUNK_BYTES=N sets N at start (tests/reader/identical_outputs.py).
void set_line_chunk_bytes(std::size_t bytes);

// The chunk size to read a file of `bytes` with, or 0 to read it line by line.
std::size_t line_chunk_bytes(std::size_t bytes);

// Finds and sorts the lines of `text` from byte `first` (after a byte order mark) in chunks of about
// `chunk_bytes` on the OpenMP threads; a mapped text's pages go back behind each chunk. The text must be
// shorter than 4 GiB (card lines keep 32-bit offsets).
SplitLines split_lines(const SourceText& text, std::size_t first, LineSyntax syntax, std::size_t chunk_bytes);

// Walks one chunk's lines in order: `grammar_line(offset)` for each line the grammar reads, and
// `data_lines(starts, count)` for each run of plain data lines between them.
template <typename GrammarLine, typename DataLines>
void walk_chunk(const LineChunk& chunk, GrammarLine&& grammar_line, DataLines&& data_lines) {
    std::size_t at = 0;
    for (const std::uint32_t special : chunk.special) {
        if (special > at) data_lines(chunk.starts.data() + at, special - at);
        grammar_line(chunk.starts[special]);
        at = special + 1;
    }
    if (chunk.starts.size() > at) data_lines(chunk.starts.data() + at, chunk.starts.size() - at);
}

// A reader's whole chunked reading of `text` (both formats' DeckReader::read_chunked): the lines found
// and sorted on all threads, then walked in file order, `grammar_line(line)` with a pointer to each line
// for the grammar, `data_lines(starts, count)` for each run of data lines; `card_lines` (the deck's card
// lines) gets room for all of the file's lines first. Returns whether a line that starts with '$' or '#'
// holds text::directive_marker (the line after a byte order mark counts, which the suppressions do not read as
// a comment: the answer may say yes for nothing, never no for a directive).
template <typename CardLines, typename GrammarLine, typename DataLines>
bool read_in_chunks(const SourceText& text, LineSyntax syntax, std::size_t chunk_bytes, CardLines& card_lines,
                    GrammarLine&& grammar_line, DataLines&& data_lines) {
    const std::size_t first = text.view().starts_with("\xEF\xBB\xBF") ? 3 : 0;  // the grammars' byte_order_mark
    SplitLines split = split_lines(text, first, syntax, chunk_bytes);
    if (card_lines.capacity() < card_lines.size() + split.lines) card_lines.reserve(card_lines.size() + split.lines);
    for (LineChunk& chunk : split.chunks) {
        walk_chunk(
            chunk, [&](std::uint32_t at) { grammar_line(text.data() + at); }, data_lines);
        chunk = {};  // its offsets are the deck's card lines now
    }
    return split.comment_holds_marker;
}

}  // namespace sphdeck::grammar
