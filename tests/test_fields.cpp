// Format rules for cutting a line into fields (lsdyna-format.md §3-§6).
#include <doctest/doctest.h>

#include "grammar/fields.hpp"
#include "grammar/value.hpp"

namespace test_fields_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck::grammar;

namespace {
const FixedField node_fields[] = {{0, 8}, {8, 16}, {24, 16}, {40, 16}, {56, 8}, {64, 8}};
CardLine line_of(std::string_view) { return CardLine{0, 7, 0}; }

std::vector<Field> cut(std::string_view text, std::span<const FixedField> standard, CardFormat format,
                       CutReport* report = nullptr) {
    std::vector<FixedField> positions;
    widen(standard, format, positions);
    std::vector<Field> out;
    CutReport r = cut_fields(text, line_of(text), positions, significant_width(positions, format), out);
    if (report) *report = r;
    return out;
}
}  // namespace

TEST_CASE("fields: glued fixed fields are cut by columns, never by blanks") {
    auto f = cut("     101-1.234567890e+01 2.000000000e+00 0.000000000e+00", node_fields, CardFormat::Standard);
    REQUIRE(f.size() == 6);
    CHECK(parse_integer(f[0].text).value == 101);
    CHECK(parse_real(f[1].text).value == doctest::Approx(-12.3456789));
    CHECK(parse_real(f[2].text).value == doctest::Approx(2.0));
    CHECK(f[1].span.column == 9);
    CHECK(f[1].span.end_column == 25);
    CHECK(f[1].span.line == 7);
}

TEST_CASE("fields: a material card whose density touches the modulus") {
    const FixedField tens[] = {{0, 10}, {10, 10}, {20, 10}, {30, 10}};
    auto f = cut("         1 1000.00002.2000e+09     0.499", tens, CardFormat::Standard);
    CHECK(parse_real(f[1].text).value == doctest::Approx(1000.0));
    CHECK(parse_real(f[2].text).value == doctest::Approx(2.2e9));
    CHECK(parse_real(f[3].text).value == doctest::Approx(0.499));
}

TEST_CASE("fields: short lines leave trailing fields blank") {
    auto f = cut("       1", node_fields, CardFormat::Standard);
    REQUIRE(f.size() == 6);
    CHECK(is_blank(f[3].text));
    CHECK(f[3].span.column == 41);
}

TEST_CASE("fields: free format is decided per line by a comma outside parentheses") {
    CHECK(is_free_format("101,-63.34,132.9,62.27"));
    CHECK_FALSE(is_free_format("     101     1.0"));
    CHECK_FALSE(is_free_format("min(a,b)"));
    CutReport r;
    auto f = cut("101,-63.34,132.9,62.27", node_fields, CardFormat::Standard, &r);
    CHECK(r.free_format);
    CHECK(parse_integer(f[0].text).value == 101);
    CHECK(parse_real(f[1].text).value == doctest::Approx(-63.34));
    CHECK(parse_real(f[3].text).value == doctest::Approx(62.27));
    CHECK(is_blank(f[4].text));  // missing trailing values take their defaults
    CHECK(f[1].span.column == 5);
}

TEST_CASE("fields: a free token longer than its fixed field is reported") {
    CutReport r;
    cut("123456789,1.0", node_fields, CardFormat::Standard, &r);
    REQUIRE(r.too_long.size() == 1);
    CHECK(r.too_long[0] == 0);
    cut("12345678,1.0", node_fields, CardFormat::Standard, &r);
    CHECK(r.too_long.empty());
}

TEST_CASE("fields: values beyond the fields in free format are counted") {
    CutReport r;
    cut("1,2,3,4,5,6,7,8", node_fields, CardFormat::Standard, &r);
    CHECK(r.extra_values == 2);
    CHECK(r.beyond.valid());
}

TEST_CASE("fields: text past column 80 is reported, blanks are not") {
    const FixedField eight[] = {{0, 10}, {10, 10}, {20, 10}, {30, 10}, {40, 10}, {50, 10}, {60, 10}, {70, 10}};
    CutReport r;
    std::string line(80, ' ');
    cut(line + "     ", eight, CardFormat::Standard, &r);
    CHECK_FALSE(r.beyond.valid());
    cut(line + "  junk", eight, CardFormat::Standard, &r);
    REQUIRE(r.beyond.valid());
    CHECK(r.beyond.column == 83);
    CHECK(r.beyond.end_column == 87);
}

TEST_CASE("fields: tabs in a fixed line are flagged") {
    CutReport r;
    cut("1\t2.0", node_fields, CardFormat::Standard, &r);
    CHECK(r.has_tab);
}

TEST_CASE("fields: I10 and long formats widen fields and shift offsets") {
    std::vector<FixedField> w;
    widen(node_fields, CardFormat::I10, w);  // I10,3E16,2I10
    CHECK(w[0].start == 0);
    CHECK(w[0].width == 10);
    CHECK(w[1].start == 10);
    CHECK(w[1].width == 16);
    CHECK(w[4].start == 58);
    CHECK(w[5].width == 10);
    widen(node_fields, CardFormat::Long, w);  // I20,3E20,2I20
    CHECK(w[1].start == 20);
    CHECK(w[3].start == 60);
    CHECK(w[5].start == 100);
    CHECK(w[5].width == 20);
    CHECK(significant_width(w, CardFormat::Long) == 160);
}

TEST_CASE("fields: gaps between fields widen like unused fields") {
    const FixedField gap[] = {{0, 10}, {30, 10}};
    std::vector<FixedField> w;
    widen(gap, CardFormat::Long, w);
    CHECK(w[1].start == 40);
}
}  // namespace test_fields_cpp
