// grammar/number_cast.hpp: which doubles convert to an integer type without undefined behaviour
// (issue 32), exactly at the edges of each type's range.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "grammar/number_cast.hpp"

namespace test_number_cast_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck::grammar;

TEST_CASE("number cast: a double fits an integer type when it truncates into the type's range") {
    CHECK(fits_integer<long long>(0.0));
    CHECK(fits_integer<long long>(-9.2e18));
    CHECK(fits_integer<long long>(9.2e18));
    CHECK_FALSE(fits_integer<long long>(9223372036854775808.0));  // 2^63: one past the largest
    CHECK_FALSE(fits_integer<long long>(1e20));
    CHECK_FALSE(fits_integer<long long>(-1e20));
    CHECK_FALSE(fits_integer<long long>(INFINITY));
    CHECK_FALSE(fits_integer<long long>(-INFINITY));
    CHECK_FALSE(fits_integer<long long>(NAN));
    // int: the edges are exact doubles, and truncation toward zero takes fractions inside.
    CHECK(fits_integer<int>(2147483647.0));
    CHECK(fits_integer<int>(2147483647.9));
    CHECK_FALSE(fits_integer<int>(2147483648.0));
    CHECK(fits_integer<int>(-2147483648.9));
    CHECK_FALSE(fits_integer<int>(-2147483649.0));
    // unsigned: anything above -1 truncates to 0 or more.
    CHECK(fits_integer<std::size_t>(-0.5));
    CHECK_FALSE(fits_integer<std::size_t>(-1.0));
    CHECK_FALSE(fits_integer<std::uint32_t>(4294967296.0));
}

TEST_CASE("number cast: checked_integer and saturating_integer") {
    CHECK(checked_integer<long long>(42.9) == 42);
    CHECK(checked_integer<long long>(-42.9) == -42);
    CHECK_FALSE(checked_integer<long long>(1e20).has_value());
    CHECK_FALSE(checked_integer<int>(NAN).has_value());
    CHECK(saturating_integer<long long>(1e20) == std::numeric_limits<long long>::max());
    CHECK(saturating_integer<long long>(-1e20) == std::numeric_limits<long long>::min());
    CHECK(saturating_integer<long long>(-INFINITY) == std::numeric_limits<long long>::min());
    CHECK(saturating_integer<long long>(NAN, -1) == -1);
    CHECK(saturating_integer<std::size_t>(-5.0) == 0);
    CHECK(saturating_integer<int>(7.5) == 7);
}
}  // namespace test_number_cast_cpp
