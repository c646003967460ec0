#include "grammar/line_chunks.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string_view>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "text/source_map.hpp"
#include "text/text_window.hpp"

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

// The '\n's of [begin, end), found 64 bytes at a time from a bit mask: a line costs a few instructions
// rather than a memchr call (two million calls on the 1M-particle deck, a tenth of `format --check`).
// Queries go forward: next(from) with `from` after the last '\n' found.
class NewlineFinder {
public:
    NewlineFinder(const char* begin, const char* end) : end_(end), block_(begin) { load(); }

    // The first '\n' at or after `from`, or null.
    const char* next(const char* from) {
        if (from >= block_ + 64) block_ = from, load();
        mask_ &= ~std::uint64_t{0} << (from - block_);  // from - block_ < 64
        while (mask_ == 0) {
            block_ += 64;
            if (block_ >= end_) return nullptr;
            load();
        }
        return block_ + std::countr_zero(mask_);
    }

private:
    void load() {
        mask_ = 0;
        if (block_ >= end_) return;
        if (end_ - block_ >= 64) {
#if defined(__SSE2__)
            const __m128i newline = _mm_set1_epi8('\n');
            for (int k = 0; k < 4; ++k) {
                const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(block_ + 16 * k));
                mask_ |= std::uint64_t{static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, newline)))}
                         << (16 * k);
            }
            return;
#endif
        }
        const std::ptrdiff_t n = std::min<std::ptrdiff_t>(end_ - block_, 64);
        for (std::ptrdiff_t k = 0; k < n; ++k) mask_ |= std::uint64_t{block_[k] == '\n'} << k;
    }

    const char* end_;
    const char* block_;       // the 64 bytes the mask is of
    std::uint64_t mask_ = 0;  // their '\n's not yet passed
};

// A line of a chunk whose end the window did not reach is read again from its start; the window holds
// this many bytes past a chunk's end for the line that crosses it.
constexpr std::size_t line_slack = std::size_t{4} << 10;

// The lines of the text (of `size` bytes) from the line start `begin` on, up to the first line whose '\n' is
// at `end` or after it: the next line belongs to the next chunk. Read through `window` (each line whole in
// it, read again from its start when it is not). Returns where the next line starts.
template <typename GrammarLines>
std::size_t scan_chunk(text::TextWindow& window, std::size_t size, std::size_t begin, std::size_t end, LineChunk& out) {
    std::size_t at = begin;  // the first line not yet recorded
    std::size_t least = line_slack;
    while (at < size) {
        const std::string_view bytes = window.from(at, least, std::max(end, at) - at + line_slack);
        const bool to_end = window.at_end(bytes);
        const char* const base = bytes.data();
        const char* const bytes_end = base + bytes.size();
        const char* p = base;
        bool done = false;
        NewlineFinder newlines(base, bytes_end);
        while (p < bytes_end) {
            const char* const newline = newlines.next(p);
            if (!newline && !to_end) break;  // the line runs past the window
            const char* const line_end = newline ? newline : bytes_end;
            if (GrammarLines::match(p, line_end)) out.special.push_back(static_cast<std::uint32_t>(out.starts.size()));
            out.starts.push_back(static_cast<std::uint32_t>(at + static_cast<std::size_t>(p - base)));
            // While the line is in the cache: what the suppressions would search the whole text for afterwards.
            if ((*p == '$' || *p == '#') && !out.comment_holds_marker)
                out.comment_holds_marker =
                    std::string_view(p, static_cast<std::size_t>(line_end - p)).find(text::directive_marker) !=
                    std::string_view::npos;
            p = newline ? newline + 1 : bytes_end;
            if (newline && at + static_cast<std::size_t>(newline - base) >= end) {
                done = true;
                break;
            }
        }
        const std::size_t next = at + static_cast<std::size_t>(p - base);
        if (done || to_end) return next;
        least = next == at ? 2 * bytes.size() : line_slack;  // a line longer than the window: a wider one
        at = next;
    }
    return at;
}

// The start of the first line that begins in [from, to) (after a '\n' there), or nothing.
std::optional<std::size_t> first_line_start(text::TextWindow& window, std::size_t from, std::size_t to) {
    while (from < to) {
        const std::string_view bytes = window.from(from, std::min(to - from, line_slack), to - from);
        const std::size_t n = std::min(bytes.size(), to - from);
        if (n == 0) return std::nullopt;
        if (const void* newline = std::memchr(bytes.data(), '\n', n))
            return from + static_cast<std::size_t>(static_cast<const char*>(newline) - bytes.data()) + 1;
        from += n;
    }
    return std::nullopt;
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
    const std::size_t size = source.size();
    chunk_bytes = std::max<std::size_t>(chunk_bytes, 1);
    SplitLines split;
    if (first >= size) return split;
    // Chunk c holds the lines that follow a '\n' in bytes [c * chunk_bytes, (c + 1) * chunk_bytes) (chunk 0
    // the first line too). Each thread reads its chunks through a window of its own (the mapping's pages
    // are not touched: text/text_window.hpp), contiguous runs of chunks (a static schedule).
    const std::size_t count = (size + chunk_bytes - 1) / chunk_bytes;
    split.chunks.resize(count);
#pragma omp parallel if (count > 1)
    {
        text::TextWindow window(source);
#pragma omp for schedule(static)
        for (std::size_t c = 0; c < count; ++c) {
            const std::size_t from = std::max(first, c * chunk_bytes), to = std::min(size, (c + 1) * chunk_bytes);
            std::size_t begin = first;
            if (c > 0) {
                const std::optional<std::size_t> start = first_line_start(window, from, to);
                if (!start) continue;  // a line longer than the chunk runs through it: no line starts here
                begin = *start;
            }
            LineChunk& chunk = split.chunks[c];
            if (syntax == LineSyntax::Dyna)
                scan_chunk<DynaGrammarLines>(window, size, begin, to, chunk);
            else
                scan_chunk<RadiossGrammarLines>(window, size, begin, to, chunk);
        }
    }
    for (const LineChunk& chunk : split.chunks) {
        split.lines += chunk.starts.size();
        split.comment_holds_marker = split.comment_holds_marker || chunk.comment_holds_marker;
    }
    return split;
}

}  // namespace sphdeck::grammar
