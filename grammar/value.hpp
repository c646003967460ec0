// Field values: integers, Fortran reals and parameter references (lsdyna-format.md §10, §14.2).
// One small PEGTL grammar decides what a field holds; std::from_chars converts after it matched.
#pragma once

#include <cstdint>
#include <string_view>

namespace sphdeck::grammar {

// What the text of one field holds, blanks around it ignored.
enum class ValueShape : std::uint8_t {
    Blank,
    Integer,    // [+-]digits
    Real,       // Fortran real: 1.0  1.  .5  1e3  1.0D3  1.0+3  3.5-10
    Parameter,  // &name or -&name
    Other,      // anything else (text, garbage)
};

struct ValueToken {
    ValueShape shape = ValueShape::Blank;
    std::string_view text;   // trimmed
    std::size_t offset = 0;  // of `text` within the field
    bool negated = false;    // -&name
    std::string_view name;   // parameter name for Parameter
    // Set when classification already converted the number (the fast path), so the
    // conversion is not done twice.
    bool converted = false;
    double real = 0.0;
    long long integer = 0;
};

// `expected` (Integer or Real) is tried first: the common case then costs one match.
ValueToken classify_value(std::string_view field, ValueShape expected = ValueShape::Integer);

enum class NumberStatus : std::uint8_t { Ok, Blank, Invalid, Parameter, NotIntegral, Overflow };

struct RealValue {
    NumberStatus status = NumberStatus::Blank;
    double value = 0.0;
};

struct IntegerValue {
    NumberStatus status = NumberStatus::Blank;
    long long value = 0;
    bool written_as_real = false;  // "1.0" or "1e3" in an integer field (DK004)
};

// Converts an already classified token. Parameter tokens come back with status Parameter.
RealValue to_real(const ValueToken& token);
IntegerValue to_integer(const ValueToken& token);

// plain_integer and plain_real, the fast paths of classify_value alone: grammar/value_fast.hpp.

inline RealValue parse_real(std::string_view field) { return to_real(classify_value(field)); }
inline IntegerValue parse_integer(std::string_view field) { return to_integer(classify_value(field)); }

}  // namespace sphdeck::grammar
