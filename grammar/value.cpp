#include "grammar/value.hpp"

#include <bit>
#include <charconv>
#include <cstring>
#include <cmath>

#include "grammar/value_fast.hpp"
#include "grammar/value_grammar.hpp"

namespace sphdeck::grammar {
namespace {

namespace pegtl = tao::pegtl;
using namespace fast_number;  // short_integer, short_real, starts_like_c_number

template <typename Rule>
bool matches_rule(std::string_view text) {
    pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf, const char*> in(text.data(),
                                                                                         text.data() + text.size(),
                                                                                         "field");
    return pegtl::parse<Rule>(in);
}

bool is_value_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view trim_token(std::string_view s, std::size_t& offset) {
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
    while (b < e && is_value_blank(s[b])) ++b;
    while (e > b && is_value_blank(s[e - 1])) --e;
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

ValueToken classify_value(std::string_view field, ValueShape expected) {
    ValueToken token;
    token.text = trim_token(field, token.offset);
    if (token.text.empty()) return token;
    if (fast_classify(token, expected)) return token;
    if (expected == ValueShape::Real && matches_rule<value_rules::real_field>(token.text)) {
        token.shape = ValueShape::Real;  // "5" in a real field is 5.0: no need to tell it from an integer
    } else if (matches_rule<value_rules::integer_field>(token.text)) {
        token.shape = ValueShape::Integer;
    } else if (matches_rule<value_rules::real_field>(token.text)) {
        token.shape = ValueShape::Real;
    } else if (matches_rule<value_rules::parameter_field>(token.text)) {
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
        result.status =
            (ec == std::errc() && end == digits.data() + digits.size()) ? NumberStatus::Ok : NumberStatus::Invalid;
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
