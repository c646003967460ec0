#include "grammar/line_chunks.hpp"

#include <atomic>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "text/source_map.hpp"

namespace sphdeck::grammar {
namespace {

// Whether the LS-DYNA line grammar (grammar/dyna/line_grammar.hpp) may read the line at `p` as anything
// but a data line: a comment ('$'), a keyword ('*' after blanks) or a PGP marker ("-----BEGIN PGP",
// "-----END PGP"). `end`: the chunk's end (the line ends at a '\n' before it, or at it).
struct DynaGrammarLines {
    static bool match(const char* p, const char* end) {
        if (*p == '$') return true;
        if (*p == '-') return end - p >= 5 && std::memcmp(p, "-----", 5) == 0;
        while (p < end && (*p == ' ' || *p == '\t')) ++p;
        return p < end && *p == '*';
    }
};

// The same for OpenRadioss (grammar/radioss/line_grammar.hpp): '#' or '$' in column 1 (comments,
// #include, #enddata), a '/' after blanks (a header, or data the grammar decides on).
struct RadiossGrammarLines {
    static bool match(const char* p, const char* end) {
        if (*p == '#' || *p == '$') return true;
        while (p < end && (*p == ' ' || *p == '\t')) ++p;
        return p < end && *p == '/';
    }
};

// The lines of `text` (of `size` bytes) from the line start `begin` on, up to the first line whose '\n'
// is at `end` or after it: the next line belongs to the next chunk. Returns where the next line starts.
template <typename GrammarLines>
std::size_t scan_chunk(const char* text, std::size_t size, std::size_t begin, std::size_t end, LineChunk& out) {
    const char* const text_end = text + size;
    const char* p = text + begin;
    while (p < text_end) {
        if (GrammarLines::match(p, text_end)) out.special.push_back(static_cast<std::uint32_t>(out.starts.size()));
        out.starts.push_back(static_cast<std::uint32_t>(p - text));
        const char* newline = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(text_end - p)));
        // While the line is in the cache: what the suppressions would search the whole text for afterwards.
        if ((*p == '$' || *p == '#') && !out.comment_holds_marker)
            out.comment_holds_marker = std::string_view(p, static_cast<std::size_t>((newline ? newline : text_end) - p))
                                           .find(text::directive_marker) != std::string_view::npos;
        p = newline ? newline + 1 : text_end;
        if (newline && newline >= text + end) break;
    }
    return static_cast<std::size_t>(p - text);
}

std::atomic<std::size_t>& chosen_chunk_bytes() {
    static std::atomic<std::size_t> bytes = [] {
        const char* value = std::getenv("SPHDECK_READER_CHUNK_BYTES");
        std::size_t n = 0;
        if (value) std::from_chars(value, value + std::strlen(value), n);
        return n;
    }();
    return bytes;
}

}  // namespace

void set_line_chunk_bytes(std::size_t bytes) { chosen_chunk_bytes().store(bytes); }

std::size_t line_chunk_bytes(std::size_t bytes) {
    const std::size_t chosen = chosen_chunk_bytes().load();
    if (chosen == read_line_by_line || bytes > 0xFFFFFFFFu) return 0;  // card lines keep 32-bit offsets
    if (chosen > 0) return chosen;
    return bytes >= chunked_reading_min_bytes ? default_line_chunk_bytes : 0;
}

SplitLines split_lines(const SourceText& source, std::size_t first, LineSyntax syntax, std::size_t chunk_bytes) {
    const std::string_view text = source.view();
    const std::size_t size = text.size();
    chunk_bytes = std::max<std::size_t>(chunk_bytes, 1);
    SplitLines split;
    if (first >= size) return split;
    // Chunk c holds the lines that follow a '\n' in bytes [c * chunk_bytes, (c + 1) * chunk_bytes) (chunk 0
    // the first line too). Each thread reads its chunks in order from their first byte on, never a byte
    // before: a page fault maps a whole folio of the page cache around the byte read, and one behind a
    // chunk's start would stay mapped after its own chunk had gone back. Contiguous runs of chunks per
    // thread (a static schedule) for the same reason.
    const std::size_t count = (size + chunk_bytes - 1) / chunk_bytes;
    split.chunks.resize(count);
#pragma omp parallel for schedule(static) if (count > 1)
    for (std::size_t c = 0; c < count; ++c) {
        const std::size_t from = std::max(first, c * chunk_bytes), to = std::min(size, (c + 1) * chunk_bytes);
        std::size_t begin = first;
        if (c > 0) {
            const void* newline = from < to ? std::memchr(text.data() + from, '\n', to - from) : nullptr;
            if (!newline) continue;  // a line longer than the chunk runs through it: no line starts here
            begin = static_cast<std::size_t>(static_cast<const char*>(newline) - text.data()) + 1;
        }
        LineChunk& chunk = split.chunks[c];
        const std::size_t scanned = syntax == LineSyntax::Dyna
                                        ? scan_chunk<DynaGrammarLines>(text.data(), size, begin, to, chunk)
                                        : scan_chunk<RadiossGrammarLines>(text.data(), size, begin, to, chunk);
        source.release(from, scanned);  // a mapped file's pages: read again, line by line, when decoded
    }
    source.release(0, size);  // the folios the threads' edges mapped
    for (const LineChunk& chunk : split.chunks) {
        split.lines += chunk.starts.size();
        split.comment_holds_marker = split.comment_holds_marker || chunk.comment_holds_marker;
    }
    return split;
}

}  // namespace sphdeck::grammar
