// Converting a deck's number (a double) to an integer type without undefined behaviour.
// A static_cast of a double that is NaN, infinite or outside the target's range is undefined
// (C++ [conv.fpint]); deck text such as 1e20 in an integer field reaches such casts, so every one
// goes through these (issue 32: a fuzzed 1e+20 in CardDecoder::check_range).
#pragma once

#include <limits>
#include <optional>
#include <type_traits>

namespace sphdeck::grammar {

// Whether `number` truncates to a value of integer type T: finite and within [min, max].
template <typename T>
constexpr bool fits_integer(double number) {
    static_assert(std::is_integral_v<T>);
    // max + 1 is a power of two, exact as a double, where max itself may round up (2^63 - 1).
    constexpr double upper = 2.0 * static_cast<double>(std::numeric_limits<T>::max() / 2 + 1);
    constexpr double lower = static_cast<double>(std::numeric_limits<T>::min());
    // Truncation toward zero: anything above lower - 1 truncates to at least min. NaN fails both tests.
    return number > lower - 1.0 && number < upper;
}

// The number truncated to T when it fits, nothing otherwise.
template <typename T>
constexpr std::optional<T> checked_integer(double number) {
    if (!fits_integer<T>(number)) return std::nullopt;
    return static_cast<T>(number);
}

// The number truncated to T, clamped to T's range; NaN gives `if_nan`. For counts and sizes where the
// caller bounds the result further anyway (a grid dimension, a step count).
template <typename T>
constexpr T saturating_integer(double number, T if_nan = T{0}) {
    if (number != number) return if_nan;
    if (number <= static_cast<double>(std::numeric_limits<T>::min())) return std::numeric_limits<T>::min();
    if (!fits_integer<T>(number)) return std::numeric_limits<T>::max();
    return static_cast<T>(number);
}

}  // namespace sphdeck::grammar
