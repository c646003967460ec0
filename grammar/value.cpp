#include "grammar/value.hpp"

#include <bit>
#include <charconv>
#include <cstring>
#include <cmath>

#include "grammar/value_grammar.hpp"

namespace sphdeck::grammar {
namespace {

namespace pegtl = tao::pegtl;

template <typename Rule>
bool matches(std::string_view text) {
    pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf, const char*> in(
        text.data(), text.data() + text.size(), "field");
    return pegtl::parse<Rule>(in);
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view trim(std::string_view s, std::size_t& offset) {
    std::size_t b = 0, e = s.size();
    // Leading spaces eight at a time: right-aligned fixed fields ("       1") are mostly blanks.
    if constexpr (std::endian::native == std::endian::little) {
        while (e - b >= 8) {
            std::uint64_t v;
            std::memcpy(&v, s.data() + b, 8);
            v ^= 0x2020202020202020u;  // spaces become zero bytes
            if (v != 0) {
                b += static_cast<std::size_t>(std::countr_zero(v)) / 8;
                break;
            }
            b += 8;
        }
    }
    while (b < e && is_blank(s[b])) ++b;
    while (e > b && is_blank(s[e - 1])) --e;
    offset = b;
    return s.substr(b, e - b);
}

// Rewrites a Fortran real that matched value_rules::real into what from_chars reads:
// no leading '+', 'd'/'D' as 'e', and an 'e' before a bare signed exponent.
bool normalise_real(std::string_view text, char* out, std::size_t capacity, std::size_t& length) {
    std::size_t n = 0;
    auto put = [&](char c) {
        if (n >= capacity) return false;
        out[n++] = c;
        return true;
    };
    std::size_t i = 0;
    if (i < text.size() && text[i] == '+') ++i;
    bool seen_mantissa_digit = false;
    for (; i < text.size(); ++i) {
        char c = text[i];
        if (c == 'd' || c == 'D' || c == 'e' || c == 'E') {
            c = 'e';
        } else if ((c == '+' || c == '-') && seen_mantissa_digit && out[n - 1] != 'e') {
            if (!put('e')) return false;  // bare exponent: 1.0+3
        }
        if (c >= '0' && c <= '9') seen_mantissa_digit = true;
        if (c == '+' && n > 0 && out[n - 1] == 'e') continue;  // "e+3" -> "e3"
        if (!put(c)) return false;
    }
    length = n;
    return true;
}

// The forms C and Fortran share ([-]digits[.digits][e[+-]digits], [-].digits...) are what
// std::from_chars accepts once a leading "inf"/"nan" is excluded, which the first-character
// test does. For them a successful whole-token from_chars is the same verdict as the grammar,
// at a third of the cost; every other text (Fortran forms, '+', garbage) goes to the grammar.
// tests/test_values.cpp checks the two paths agree.
bool starts_like_c_number(std::string_view t) {
    std::size_t i = t[0] == '-' ? 1 : 0;
    return i < t.size() && ((t[i] >= '0' && t[i] <= '9') || t[i] == '.');
}

// Exact powers of ten: every 10^k with k <= 22 is a double.
constexpr double exact_powers_of_ten[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                          1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The plain integers from_chars takes ("-"? 1-18 digits), converted without it: no overflow
// is possible at 18 digits, so the verdict and the value are from_chars' own. Anything else
// (19 digits and more) answers false and goes to from_chars.
bool short_integer(const char* p, const char* end, long long& out) {
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
bool eight_digits(const char* p, std::uint64_t& value) {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    if ((((v & 0xF0F0F0F0F0F0F0F0u) | (((v + 0x0606060606060606u) & 0xF0F0F0F0F0F0F0F0u) >> 4))) !=
        0x3333333333333333u)
        return false;
    v -= 0x3030303030303030u;
    v = v * 10 + (v >> 8);  // pairs of digits
    value = (((v & 0x000000FF000000FFu) * (100 + (1000000ull << 32))) +
             (((v >> 16) & 0x000000FF000000FFu) * (1 + (10000ull << 32)))) >> 32;
    return true;
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
inline bool e8_form(const char* p, const char* end, std::uint64_t& m, int& exponent) {
    if constexpr (std::endian::native != std::endian::little) return false;
    std::uint64_t eight = 0;
    if (end - p != 14 || !is_digit(p[0]) || p[1] != '.' || (p[10] != 'e' && p[10] != 'E') ||
        (p[11] != '+' && p[11] != '-') || !is_digit(p[12]) || !is_digit(p[13]) || !eight_digits(p + 2, eight))
        return false;
    m = static_cast<std::uint64_t>(p[0] - '0') * 100000000u + eight;
    const int e = (p[12] - '0') * 10 + (p[13] - '0');
    exponent = -8 + (p[11] == '-' ? -e : e);
    return true;
}

// m * 10^exponent when both are exact doubles (Clinger), the sign applied; false otherwise.
inline bool scale_exact(std::uint64_t m, int exponent, bool negative, double& out) {
    if (m > (std::uint64_t{1} << 53)) return false;
    double v = static_cast<double>(m);
    if (m != 0) {
        if (exponent < -22 || exponent > 22) return false;
        v = exponent < 0 ? v / exact_powers_of_ten[-exponent] : v * exact_powers_of_ten[exponent];
    }
    out = negative ? -v : v;
    return true;
}

// Clinger's fast path for the C form [-]digits[.digits][e|E[+-]digits]: when the digits make an
// integer m <= 2^53 and the decimal exponent e has |e| <= 22, m and 10^|e| are exact doubles and
// one IEEE multiplication or division rounds m * 10^e correctly, which is the value from_chars
// returns (it rounds correctly too). Any other text (more digits, larger exponents, Fortran forms)
// answers false and is left to from_chars. The big decks' "%16.8e" coordinates all take this path.
bool short_real(const char* p, const char* end, double& out) {
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

bool fast_classify(ValueToken& token, ValueShape expected) {
    if (!starts_like_c_number(token.text)) return false;
    const char* begin = token.text.data();
    const char* end = begin + token.text.size();
    if (expected == ValueShape::Integer && short_integer(begin, end, token.integer)) {
        token.shape = ValueShape::Integer;
        token.real = static_cast<double>(token.integer);
        token.converted = true;
        return true;
    }
    if (expected != ValueShape::Integer && short_real(begin, end, token.real)) {
        token.shape = ValueShape::Real;
        token.converted = true;
        return true;
    }
    if (expected == ValueShape::Integer) {
        auto [stop, error] = std::from_chars(begin, end, token.integer);
        if (error == std::errc() && stop == end) {
            token.shape = ValueShape::Integer;
            token.real = static_cast<double>(token.integer);
            token.converted = true;
            return true;
        }
        return false;
    }
    auto [stop, error] = std::from_chars(begin, end, token.real);
    if (error == std::errc() && stop == end) {
        token.shape = ValueShape::Real;
        token.converted = true;
        return true;
    }
    return false;
}

}  // namespace

bool plain_integer(std::string_view text, long long& value) {
    return !text.empty() && starts_like_c_number(text) && short_integer(text.data(), text.data() + text.size(), value);
}

bool plain_real(std::string_view text, double& value) {
    return !text.empty() && starts_like_c_number(text) && short_real(text.data(), text.data() + text.size(), value);
}

ValueToken classify_value(std::string_view field, ValueShape expected) {
    ValueToken token;
    token.text = trim(field, token.offset);
    if (token.text.empty()) return token;
    if (fast_classify(token, expected)) return token;
    if (expected == ValueShape::Real && matches<value_rules::real_field>(token.text)) {
        token.shape = ValueShape::Real;  // "5" in a real field is 5.0: no need to tell it from an integer
    } else if (matches<value_rules::integer_field>(token.text)) {
        token.shape = ValueShape::Integer;
    } else if (matches<value_rules::real_field>(token.text)) {
        token.shape = ValueShape::Real;
    } else if (matches<value_rules::parameter_field>(token.text)) {
        token.shape = ValueShape::Parameter;
        token.negated = token.text.front() == '-';
        token.name = token.text.substr(token.negated ? 2 : 1);
    } else {
        token.shape = ValueShape::Other;
    }
    return token;
}

RealValue to_real(const ValueToken& token) {
    switch (token.shape) {
        case ValueShape::Blank: return {NumberStatus::Blank, 0.0};
        case ValueShape::Parameter: return {NumberStatus::Parameter, 0.0};
        case ValueShape::Other: return {NumberStatus::Invalid, 0.0};
        case ValueShape::Integer:
        case ValueShape::Real: break;
    }
    if (token.converted) return {NumberStatus::Ok, token.real};
    // Most reals are already in C form ("1.0e+00", "-2.5"): convert in place when from_chars
    // takes the whole token, and rewrite only the Fortran forms (1.0D3, 1.0+3, +2.5).
    double direct = 0.0;
    auto [stop, error] = std::from_chars(token.text.data(), token.text.data() + token.text.size(), direct);
    if (error == std::errc() && stop == token.text.data() + token.text.size()) return {NumberStatus::Ok, direct};
    if (error == std::errc::result_out_of_range) return {NumberStatus::Overflow, 0.0};
    char buffer[80];
    std::size_t length = 0;
    if (!normalise_real(token.text, buffer, sizeof buffer, length)) return {NumberStatus::Invalid, 0.0};
    double value = 0.0;
    auto [end, ec] = std::from_chars(buffer, buffer + length, value);
    if (ec == std::errc::result_out_of_range) return {NumberStatus::Overflow, 0.0};
    if (ec != std::errc() || end != buffer + length) return {NumberStatus::Invalid, 0.0};
    return {NumberStatus::Ok, value};
}

IntegerValue to_integer(const ValueToken& token) {
    IntegerValue result;
    if (token.converted && token.shape == ValueShape::Integer) return {NumberStatus::Ok, token.integer, false};
    if (token.shape == ValueShape::Integer) {
        std::string_view digits = token.text;
        if (digits.front() == '+') digits.remove_prefix(1);
        auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), result.value);
        if (ec == std::errc::result_out_of_range) return {NumberStatus::Overflow, 0, false};
        result.status = (ec == std::errc() && end == digits.data() + digits.size()) ? NumberStatus::Ok
                                                                                    : NumberStatus::Invalid;
        return result;
    }
    if (token.shape == ValueShape::Real) {
        RealValue real = to_real(token);
        if (real.status != NumberStatus::Ok) return {real.status, 0, false};
        if (std::fabs(real.value) >= 9.2e18) return {NumberStatus::Overflow, 0, true};
        if (real.value != std::trunc(real.value)) return {NumberStatus::NotIntegral, 0, true};
        return {NumberStatus::Ok, static_cast<long long>(real.value), true};
    }
    if (token.shape == ValueShape::Parameter) return {NumberStatus::Parameter, 0, false};
    if (token.shape == ValueShape::Blank) return {NumberStatus::Blank, 0, false};
    return {NumberStatus::Invalid, 0, false};
}

}  // namespace sphdeck::grammar
