#include "edit/laid_out_test.hpp"

#include <algorithm>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sphdeck::edit {

LaidOutTest::LaidOutTest(std::span<const grammar::FixedField> slots, std::span<const CellKind> kinds)
    : slots_(slots), kinds_(kinds) {
    const std::size_t n = std::min(slots.size(), kinds.size());
    if (n == 0) return;
    for (std::size_t i = 0; i < n; ++i) last_ = std::max(last_, std::size_t{slots[i].start} + slots[i].width);
#if defined(__SSE2__)
    // The 16-byte steps below read mask_columns bytes at most: a laid-out line and its "\r\n" fit.
    masks_ = last_ + 2 <= mask_columns;
    std::size_t end = 0;
    for (std::size_t i = 0; i < n && masks_; ++i) {
        const std::size_t start = slots[i].start, width = slots[i].width;
        if (start < end) masks_ = false;  // fields out of order: not the layouts this is for
        end = start + width;
        if (width == 0 || (kinds[i] != CellKind::Number && kinds[i] != CellKind::Label)) continue;
        const Mask field = ((Mask{1} << end) - 1) & ~((Mask{1} << start) - 1);
        numbers_ |= field;
        ends_ |= Mask{1} << (end - 1);
        if (kinds[i] == CellKind::Label) labels_.push_back(field);
    }
#endif
}

std::optional<std::size_t> LaidOutTest::length(std::string_view rest) const {
    if (masks_ && rest.size() >= mask_columns) return by_masks(rest);
    if (last_ == 0) return std::nullopt;
    // Byte by byte (lines near their file's end, wide layouts): the line's end, as RawDeck::text finds it
    // ("\r\n", or the file's end), looked for no further than the last field's end and its "\r\n".
    const std::size_t bound = std::min(rest.size(), last_ + 2);
    const void* newline = std::memchr(rest.data(), '\n', bound);
    if (!newline && bound < rest.size()) return std::nullopt;  // longer than the fields
    std::size_t length = newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - rest.data()) : bound;
    if (length > 0 && rest[length - 1] == '\r') --length;
    const std::string_view text = rest.substr(0, length);
    if (text.find_first_of(",\t") != std::string_view::npos || !already_laid_out(text, slots_, kinds_))
        return std::nullopt;
    return length;
}

std::optional<std::size_t> LaidOutTest::by_masks(std::string_view rest) const {
#if defined(__SSE2__)
    // The line's blanks, commas and tabs, digits and signs as bit masks, 16 bytes at a time up to its '\n':
    // each step's 16 bits stored in its place, the masks read whole afterwards (a 128-bit shift a step cost
    // more than the tests).
    constexpr std::size_t steps = mask_columns / 16;
    std::uint16_t blank_bits[steps] = {}, mark_bits[steps] = {}, digit_bits[steps] = {}, sign_bits[steps] = {};
    std::size_t length = mask_columns;
    const __m128i blank = _mm_set1_epi8(' '), newline = _mm_set1_epi8('\n'), comma = _mm_set1_epi8(','),
                  tab = _mm_set1_epi8('\t'), below_0 = _mm_set1_epi8('0' - 1), above_9 = _mm_set1_epi8('9' + 1),
                  plus = _mm_set1_epi8('+'), minus = _mm_set1_epi8('-');
    const auto bits_of = [](__m128i lanes) { return static_cast<std::uint16_t>(_mm_movemask_epi8(lanes)); };
    for (std::size_t k = 0; k < steps; ++k) {
        const __m128i chunk = _mm_loadu_si128(reinterpret_cast<const __m128i*>(rest.data() + 16 * k));
        blank_bits[k] = bits_of(_mm_cmpeq_epi8(chunk, blank));
        mark_bits[k] = bits_of(_mm_or_si128(_mm_cmpeq_epi8(chunk, comma), _mm_cmpeq_epi8(chunk, tab)));
        if (!labels_.empty()) {  // bytes of 0x80 and above compare as negative: not digits
            digit_bits[k] = bits_of(_mm_and_si128(_mm_cmpgt_epi8(chunk, below_0), _mm_cmplt_epi8(chunk, above_9)));
            sign_bits[k] = bits_of(_mm_or_si128(_mm_cmpeq_epi8(chunk, plus), _mm_cmpeq_epi8(chunk, minus)));
        }
        const auto ends = static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(chunk, newline)));
        if (ends != 0) {
            length = 16 * k + static_cast<std::size_t>(__builtin_ctz(ends));
            break;
        }
    }
    if (length == mask_columns) return std::nullopt;  // longer than every field
    // Bit c of a mask: column c (the steps' bits in order, little-endian: x86-64 alone has SSE2 here).
    static_assert(sizeof(Mask) == sizeof blank_bits);
    Mask blanks, marks, digits, signs;
    std::memcpy(&blanks, blank_bits, sizeof blanks), std::memcpy(&marks, mark_bits, sizeof marks);
    std::memcpy(&digits, digit_bits, sizeof digits), std::memcpy(&signs, sign_bits, sizeof signs);
    if (length > 0 && rest[length - 1] == '\r') --length;
    if (length == 0 || length > last_ || rest[length - 1] == ' ') return std::nullopt;
    const Mask line = (Mask{1} << length) - 1;
    if ((marks & line) != 0) return std::nullopt;
    const Mask filled = ~blanks & line;
    // Text between the fields, past them, or in a text or unused field.
    if ((filled & ~numbers_) != 0) return std::nullopt;
    // Each value's last character (a filled column before a blank one, or before the line's end) must be its
    // field's last column: a value that ends early, is cut by the line's end or holds a blank fails here.
    if ((filled & ~(filled >> 1) & ~ends_) != 0) return std::nullopt;
    for (const Mask label : labels_) {  // an integer: digits, a sign first at most
        const Mask value = filled & label;
        const Mask not_digits = value & ~digits;
        if (not_digits == 0) continue;
        const Mask first = value & (~value + 1);
        if (not_digits != first || (first & signs) == 0 || value == first) return std::nullopt;
    }
    return length;
#else
    (void)rest;
    return std::nullopt;
#endif
}

}  // namespace sphdeck::edit
