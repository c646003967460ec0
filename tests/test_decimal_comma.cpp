// The decimal comma finder shared by both decoders (model/decimal_comma.hpp, DK031): which lines it takes for
// fixed-format lines with a comma typed for a point, and which free-format lines it leaves alone.
#include <doctest/doctest.h>

#include <vector>

#include "engine/check.hpp"
#include "model/decimal_comma.hpp"
#include "test_support.hpp"

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

namespace test_decimal_comma_cpp {

// One cause, one finding: the free-format reading's consequences on the line are the comma's notes.
TEST_CASE("decimal comma: what the free-format reading does to the line's other values is one finding") {
    const auto r = engine::check_buffer("*KEYWORD\n*CONTROL_TIMESTEP\n     0,002       0.9\n*END\n", "d.k");
    CHECK(test::count_code(r.diagnostics, "DK003") == 0);
    REQUIRE(test::count_code(r.diagnostics, "DK031") == 1);
    const diag::Diagnostic* d = test::find_code(r.diagnostics, "DK031");
    CHECK(d->severity == diag::Severity::Error);  // TSSFAC '002       0.9' is no number: the solver stops
    REQUIRE(d->notes.size() == 1);
    CHECK(d->notes[0].message.find("(DK003)") != std::string::npos);
    CHECK(d->notes[0].span.column == 8);
    // Nothing else on the line: a warning, as before.
    const auto alone = engine::check_buffer("*KEYWORD\n*CONTROL_TERMINATION\n     0,002\n*END\n", "d.k");
    REQUIRE(test::count_code(alone.diagnostics, "DK031") == 1);
    CHECK(test::find_code(alone.diagnostics, "DK031")->severity == diag::Severity::Warning);
    CHECK(test::find_code(alone.diagnostics, "DK031")->notes.empty());
    // OpenRadioss: RHO_0 read from the rest of the line.
    const auto rad = engine::check_buffer(
        "#RADIOSS STARTER\n/BEGIN\nrun\n      2026\n/MAT/LAW6/3\nwater\n              1,0E-6                 0.0\n"
        "                 0.0                 0.0\n/END\n",
        "d_0000.rad", {}, grammar::DeckFormat::Radioss);
    CHECK(test::count_code(rad.diagnostics, "DK003") == 0);
    REQUIRE(test::count_code(rad.diagnostics, "DK031") == 1);
    CHECK(test::find_code(rad.diagnostics, "DK031")->severity == diag::Severity::Error);
}

}  // namespace test_decimal_comma_cpp
