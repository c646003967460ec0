// The fast number readers of the value grammar (grammar/value.cpp), inline so that the bulk card
// decoder (model/card_decoder_plain.cpp) calls them without a call per field. Each answers false
// for any text it does not convert exactly as std::from_chars would; the caller then takes the
// general path. tests/test_values.cpp checks them bit for bit against from_chars.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <string_view>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sphdeck::grammar {
namespace fast_number {

// The forms C and Fortran share ([-]digits[.digits][e[+-]digits], [-].digits...) are what
// std::from_chars accepts once a leading "inf"/"nan" is excluded, which the first-character
// test does. For them a successful whole-token from_chars is the same verdict as the grammar,
// at a third of the cost; every other text (Fortran forms, '+', garbage) goes to the grammar.
// tests/test_values.cpp checks the two paths agree.
inline bool starts_like_c_number(std::string_view t) {
    std::size_t i = t[0] == '-' ? 1 : 0;
    return i < t.size() && ((t[i] >= '0' && t[i] <= '9') || t[i] == '.');
}

// Exact powers of ten: every 10^k with k <= 22 is a double.
inline constexpr double exact_powers_of_ten[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                                 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The plain integers from_chars takes ("-"? 1-18 digits), converted without it: no overflow
// is possible at 18 digits, so the verdict and the value are from_chars' own. Anything else
// (19 digits and more) answers false and goes to from_chars.
inline bool short_integer(const char* p, const char* end, long long& out) {
    const bool negative = *p == '-';
    if (negative) ++p;
    const std::ptrdiff_t n = end - p;
    if (n < 1 || n > 18) return false;
    long long v = 0;
    for (; p < end; ++p) {
        if (!is_digit(*p)) return false;
        v = v * 10 + (*p - '0');
    }
    out = negative ? -v : v;
    return true;
}

// Eight ASCII digits at p (little-endian load): whether they all are digits, and their value.
// The classic SWAR steps: a digit is 0x30-0x39, so its high nibble is 3 and adding 6 keeps it 3.
inline bool eight_digits_word(std::uint64_t v, std::uint64_t& value) {
    if ((((v & 0xF0F0F0F0F0F0F0F0u) | (((v + 0x0606060606060606u) & 0xF0F0F0F0F0F0F0F0u) >> 4))) != 0x3333333333333333u)
        return false;
    v -= 0x3030303030303030u;
    v = v * 10 + (v >> 8);  // pairs of digits
    value = (((v & 0x000000FF000000FFu) * (100 + (1000000ull << 32))) +
             (((v >> 16) & 0x000000FF000000FFu) * (1 + (10000ull << 32)))) >>
            32;
    return true;
}
inline bool eight_digits(const char* p, std::uint64_t& value) {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    return eight_digits_word(v, value);
}

// Reads digits from p into m (at most 19 digits in all, so m cannot overflow); false past 19.
inline bool read_digits(const char*& p, const char* end, std::uint64_t& m, int& count) {
    std::uint64_t eight = 0;
    if constexpr (std::endian::native == std::endian::little)
        while (end - p >= 8 && count <= 11 && eight_digits(p, eight)) m = m * 100000000u + eight, p += 8, count += 8;
    for (; p < end && is_digit(*p); ++p) {
        if (++count > 19) return false;
        m = m * 10 + static_cast<std::uint64_t>(*p - '0');
    }
    return true;
}

// C's "%.8e" (d.dddddddde+dd, 14 characters after the sign): the coordinates and masses of the big
// decks. Read in one go into the same m and decimal exponent as read_digits and the exponent loop
// of short_real would give, so the same double follows.
[[gnu::always_inline]] inline bool e8_form(const char* p, const char* end, std::uint64_t& m, int& exponent) {
    if constexpr (std::endian::native != std::endian::little) return false;
    std::uint64_t eight = 0;
    if (end - p != 14 || !is_digit(p[0]) || p[1] != '.' || (p[10] != 'e' && p[10] != 'E') ||
        (p[11] != '+' && p[11] != '-') || !is_digit(p[12]) || !is_digit(p[13]) || !eight_digits(p + 2, eight))
        return false;
    m = static_cast<std::uint64_t>(p[0] - '0') * 100000000u + eight;
    const int e = (p[12] - '0') * 10 + (p[13] - '0');
    exponent = -8 + e * (1 - 2 * static_cast<int>(p[11] == '-'));
    return true;
}

// m * 10^exponent when both are exact doubles (Clinger), the sign applied; false otherwise.
inline bool scale_exact(std::uint64_t m, int exponent, bool negative, double& out) {
    if (m > (std::uint64_t{1} << 53)) return false;
    // The sign by its bit, not a branch: the signs of coordinates follow no pattern a predictor learns. It goes
    // on the power of ten, before the division (m / -p is -(m / p) exactly, 0 / -p is -0): the quotient is then
    // stored as it comes, where flipping its bit afterwards waited for the division.
    const std::uint64_t sign = static_cast<std::uint64_t>(negative) << 63;
    if (m == 0) {
        out = std::bit_cast<double>(sign);
        return true;
    }
    if (exponent < -22 || exponent > 22) return false;
    const double power = std::bit_cast<double>(
        std::bit_cast<std::uint64_t>(exact_powers_of_ten[exponent < 0 ? -exponent : exponent]) ^ sign);
    const double v = static_cast<double>(m);
    out = exponent < 0 ? v / power : v * power;
    return true;
}

// Clinger's fast path for the C form [-]digits[.digits][e|E[+-]digits]: when the digits make an
// integer m <= 2^53 and the decimal exponent e has |e| <= 22, m and 10^|e| are exact doubles and
// one IEEE multiplication or division rounds m * 10^e correctly, which is the value from_chars
// returns (it rounds correctly too). Any other text (more digits, larger exponents, Fortran forms)
// answers false and is left to from_chars. The big decks' "%16.8e" coordinates all take this path.
inline bool short_real(const char* p, const char* end, double& out) {
    const bool negative = *p == '-';
    if (negative) ++p;
    std::uint64_t m = 0;
    int exponent = 0;
    if (e8_form(p, end, m, exponent)) return scale_exact(m, exponent, negative, out);
    int count = 0;
    const char* start = p;
    if (!read_digits(p, end, m, count)) return false;
    if (p < end && *p == '.') {
        ++p;
        const int before = count;
        if (!read_digits(p, end, m, count)) return false;
        exponent = before - count;
    }
    if (count == 0 || (p - start) == 0) return false;
    if (p < end && (*p == 'e' || *p == 'E')) {
        ++p;
        bool minus = false;
        if (p < end && (*p == '+' || *p == '-')) minus = *p++ == '-';
        if (p == end) return false;
        int e = 0;
        for (; p < end && is_digit(*p); ++p) {
            e = e * 10 + (*p - '0');
            if (e > 400) return false;
        }
        exponent += minus ? -e : e;
    }
    if (p != end) return false;
    return scale_exact(m, exponent, negative, out);
}

// Whole fixed-width fields of the bulk lines, read from their columns without trimming them first
// (model/card_decoder_plain.cpp). Each takes only the one shape a preprocessor writes and answers
// Other for anything else, which the caller then trims and reads with short_integer / short_real:
// so each gives exactly what those give on the trimmed text, or nothing.
enum class FieldShape : std::uint8_t { Blank, Number, Other };

// An I8 field of 8 bytes at p: spaces, then "-"? and 1-8 digits up to the field's end (right-aligned).
// Number: `value` and `lead`, the spaces before the number; Blank: 8 spaces.
[[gnu::always_inline]] inline FieldShape integer8(const char* p, long long& value, std::uint32_t& lead) {
    if constexpr (std::endian::native != std::endian::little) return FieldShape::Other;
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    constexpr std::uint64_t low7 = 0x7F7F7F7F7F7F7F7Fu, high = 0x8080808080808080u;
    const std::uint64_t x = v ^ 0x2020202020202020u;                 // a space becomes 0
    const std::uint64_t spaces = ~(((x & low7) + low7) | x | low7);  // 0x80 in each byte that was a space
    if (spaces == high) return FieldShape::Blank;
    const auto first = static_cast<std::uint32_t>(std::countr_zero(~spaces & high)) / 8;  // the first non-space
    if ((spaces >> (8 * first)) != 0) return FieldShape::Other;  // a space after it: not right-aligned
    std::uint64_t before = first == 0 ? 0 : ~std::uint64_t{0} >> (64 - 8 * first);  // the bytes of the spaces
    const bool negative = ((v >> (8 * first)) & 0xFF) == '-';
    if (negative) {
        if (first == 7) return FieldShape::Other;  // "-" alone
        before |= std::uint64_t{0xFF} << (8 * first);
    }
    std::uint64_t digits = 0;
    if (!eight_digits_word((v & ~before) | (0x3030303030303030u & before), digits)) return FieldShape::Other;
    const auto n = static_cast<long long>(digits);
    value = negative ? -n : n;
    lead = first;
    return FieldShape::Number;
}

// An E16 field of 16 bytes at p holding C's "%16.8e" ("  d.dddddddde+dd", " -d.dddddddde-dd"): true with
// short_real's double of the trimmed text (and `lead`, 2 or 1) when the field is that and scales exactly.
// With SSE2 (every x86-64) the field's shape is tested in one pass of 16 lanes: the character tests of
// e8_form below, on all bytes at once.
[[gnu::always_inline]] inline bool e8_field16(const char* p, double& out, std::uint32_t& lead) {
#if defined(__SSE2__)
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    // Digits: bytes 2, 4-11, 14 and 15 (d.dddddddde+dd after the two leading bytes).
    const __m128i from_zero = _mm_sub_epi8(v, _mm_set1_epi8('0'));
    const __m128i is_digit = _mm_cmpeq_epi8(_mm_subs_epu8(from_zero, _mm_set1_epi8(9)), _mm_setzero_si128());
    // The other bytes, each one of two characters: ' ', ' ' or '-', '.', 'e' or 'E', '+' or '-'.
    const __m128i one = _mm_setr_epi8(' ', ' ', 0, '.', 0, 0, 0, 0, 0, 0, 0, 0, 'e', '+', 0, 0);
    const __m128i other = _mm_setr_epi8(' ', '-', 0, '.', 0, 0, 0, 0, 0, 0, 0, 0, 'E', '-', 0, 0);
    const __m128i is_mark = _mm_or_si128(_mm_cmpeq_epi8(v, one), _mm_cmpeq_epi8(v, other));
    constexpr int digits = 0xCFF4, marks = 0x300B;
    const int shape = (_mm_movemask_epi8(is_digit) & digits) | (_mm_movemask_epi8(is_mark) & marks);
    if (shape != (digits | marks)) return false;
    std::uint64_t eight = 0;
    std::uint64_t word;
    std::memcpy(&word, p + 4, 8);
    eight_digits_word(word, eight);  // digits, tested above
    const std::uint64_t m = static_cast<std::uint64_t>(p[2] - '0') * 100000000u + eight;
    const int e = (p[14] - '0') * 10 + (p[15] - '0');
    const int exponent = -8 + e * (1 - 2 * static_cast<int>(p[13] == '-'));
    const bool negative = p[1] == '-';
#else
    if (p[0] != ' ' || (p[1] != ' ' && p[1] != '-')) return false;
    const bool negative = p[1] == '-';
    std::uint64_t m = 0;
    int exponent = 0;
    if (!e8_form(p + 2, p + 16, m, exponent)) return false;
#endif
    if (!scale_exact(m, exponent, negative, out)) return false;
    lead = 2 - static_cast<std::uint32_t>(negative);
    return true;
}

}  // namespace fast_number

// The fast paths of classify_value alone, for bulk readers that fall back to the full decoder:
// `text` is already trimmed; true with the value when the text is a plain C integer ("-"? 1-18
// digits) or a real that converts exactly by the short path, false for anything else (which
// classify_value may still accept). The verdict and value are classify_value's own.
inline bool plain_integer(std::string_view text, long long& value) {
    return !text.empty() && fast_number::starts_like_c_number(text) &&
           fast_number::short_integer(text.data(), text.data() + text.size(), value);
}
inline bool plain_real(std::string_view text, double& value) {
    return !text.empty() && fast_number::starts_like_c_number(text) &&
           fast_number::short_real(text.data(), text.data() + text.size(), value);
}

}  // namespace sphdeck::grammar
