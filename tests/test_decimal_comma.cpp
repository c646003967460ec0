// The decimal comma finder shared by both decoders (model/decimal_comma.hpp, DK031): which lines it takes for
// fixed-format lines with a comma typed for a point, and which free-format lines it leaves alone.
#include <doctest/doctest.h>

#include <vector>

#include "model/decimal_comma.hpp"

namespace test_decimal_comma_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {
const std::vector<grammar::FixedField> ten_wide = {{0, 10}, {10, 10}, {20, 10}};
const std::vector<grammar::FixedField> twenty_wide = {{0, 20}, {20, 20}, {40, 20}};
}  // namespace

TEST_CASE("decimal comma: a padded line, as before") {
    const auto c = model::find_decimal_comma("     0,002", ten_wide);
    REQUIRE(c);
    CHECK(c->begin == 5);
    CHECK(c->end == 10);
    CHECK(c->meant == "0.002");
    CHECK(model::find_decimal_comma("     0,002"));  // without the layout too
}

TEST_CASE("decimal comma: a value right-aligned in its field, without two blanks before the line") {
    // One blank: ` 0.6000000` typed with a comma in columns 1-10.
    auto c = model::find_decimal_comma(" 0,6000000", ten_wide);
    REQUIRE(c);
    CHECK(c->meant == "0.6000000");
    CHECK(c->begin == 1);
    // A 20-wide cell filled to its end (an OpenRadioss real), then blanks and another value.
    c = model::find_decimal_comma("1,00000000000000E-03                   0", twenty_wide);
    REQUIRE(c);
    CHECK(c->meant == "1.00000000000000E-03");
    // In a later field.
    c = model::find_decimal_comma("       1.0 0,6000000", ten_wide);
    REQUIRE(c);
    CHECK(c->begin == 11);
    // Without the layout it is not known to be fixed format.
    CHECK_FALSE(model::find_decimal_comma(" 0,6000000"));
}

TEST_CASE("decimal comma: free-format lines are left alone") {
    CHECK_FALSE(model::find_decimal_comma("0.002,1000", ten_wide));    // would read 0.002.1000: two points
    CHECK_FALSE(model::find_decimal_comma("1000000,25,3", ten_wide));  // the word ends at a comma
    CHECK_FALSE(model::find_decimal_comma("1,2,3", ten_wide));         // ends at no field's end
    CHECK_FALSE(model::find_decimal_comma("0.5, 1.0", ten_wide));      // a blank beside the comma
    CHECK_FALSE(model::find_decimal_comma(" 0.6,1000", ten_wide));     // ends at column 9
    CHECK_FALSE(model::find_decimal_comma("123456.0,2.0", ten_wide));  // spans the fields' boundary
    CHECK_FALSE(model::find_decimal_comma("no comma at all", ten_wide));
}

}  // namespace test_decimal_comma_cpp
