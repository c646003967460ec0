#include "grammar/line_scan.hpp"

#include <bit>
#include <cstddef>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sphdeck::grammar {

ScannedLine scan_line(const RawDeck& deck, const CardLine& line) {
    const std::string_view file = deck.sources.file(line.file).text;
    const char* begin = file.data() + line.offset;
    const std::size_t rest = file.size() - line.offset;
    std::size_t length = rest, i = 0;
    unsigned found = 0;
    bool ended = false;
#if defined(__SSE2__)
    // Whole chunks only: never a byte past the file's text.
    const __m128i newline = _mm_set1_epi8('\n'), comma = _mm_set1_epi8(','), tab = _mm_set1_epi8('\t');
    for (; i + 16 <= rest && !ended; i += 16) {
        const __m128i chunk = _mm_loadu_si128(reinterpret_cast<const __m128i*>(begin + i));
        const auto ends = static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(chunk, newline)));
        auto marks = static_cast<unsigned>(
            _mm_movemask_epi8(_mm_or_si128(_mm_cmpeq_epi8(chunk, comma), _mm_cmpeq_epi8(chunk, tab))));
        if (ends != 0) {
            const auto at = static_cast<unsigned>(std::countr_zero(ends));
            marks &= (1u << at) - 1;  // only what lies before the line's end
            length = i + at;
            ended = true;
        }
        found |= marks;
    }
#endif
    for (; i < rest && !ended; ++i) {
        const char c = begin[i];
        if (c == '\n') {
            length = i;
            ended = true;
        } else {
            found |= static_cast<unsigned>(c == ',' || c == '\t');
        }
    }
    if (length > 0 && begin[length - 1] == '\r') --length;
    return {std::string_view(begin, length), found != 0};
}

}  // namespace sphdeck::grammar
