// Format rules for single values (lsdyna-format.md §10, §14.2).
#include <doctest/doctest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <random>
#include <string>
#include <tao/pegtl/contrib/analyze.hpp>

#include "grammar/value.hpp"
#include "grammar/value_grammar.hpp"

namespace test_values_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck::grammar;

TEST_CASE("values: the value grammar has no infinite loops") {
    CHECK(tao::pegtl::analyze<value_rules::integer_field>(-1) == 0);
    CHECK(tao::pegtl::analyze<value_rules::real_field>(-1) == 0);
    CHECK(tao::pegtl::analyze<value_rules::parameter_field>(-1) == 0);
}

TEST_CASE("values: Fortran reals in every documented form") {
    struct Case {
        const char* text;
        double value;
    };
    const Case cases[] = {{"1.0", 1.0},
                          {"1.", 1.0},
                          {".5", 0.5},
                          {"+2.5", 2.5},
                          {"5", 5.0},
                          {"1e3", 1000.0},
                          {"1E+03", 1000.0},
                          {"1.0D3", 1000.0},
                          {"2.5d-4", 2.5e-4},
                          {"1.0+3", 1000.0},
                          {"3.5-10", 3.5e-10},
                          {"1+4", 1e4},
                          {"-7.66720-110", -7.6672e-110},
                          {"  1.0     ", 1.0},
                          {"-0.5", -0.5}};
    for (const Case& c : cases) {
        CAPTURE(c.text);
        RealValue v = parse_real(c.text);
        REQUIRE(v.status == NumberStatus::Ok);
        CHECK(v.value == doctest::Approx(c.value).epsilon(1e-12));
    }
}

TEST_CASE("values: text that is not a real") {
    for (const char* text : {"abc", "1.0.0", "1e", "e3", "--1", "1,0", "1 2", "0x10", "1.0e+", "\x01"}) {
        CAPTURE(text);
        CHECK(parse_real(text).status == NumberStatus::Invalid);
    }
    CHECK(parse_real("").status == NumberStatus::Blank);
    CHECK(parse_real("      ").status == NumberStatus::Blank);
    CHECK(parse_real("1e999").status == NumberStatus::Overflow);
}

TEST_CASE("values: integers, and reals in integer fields") {
    CHECK(parse_integer("   42").value == 42);
    CHECK(parse_integer("-7").value == -7);
    CHECK(parse_integer("+7").value == 7);
    IntegerValue as_real = parse_integer("1.0");
    CHECK(as_real.status == NumberStatus::Ok);
    CHECK(as_real.written_as_real);
    CHECK(as_real.value == 1);
    CHECK(parse_integer("1e3").value == 1000);
    CHECK(parse_integer("1.5").status == NumberStatus::NotIntegral);
    CHECK(parse_integer("12a").status == NumberStatus::Invalid);
    CHECK(parse_integer("99999999999999999999").status == NumberStatus::Overflow);
}

TEST_CASE("values: parameter references") {
    ValueToken t = classify_value("     &tend");
    CHECK(t.shape == ValueShape::Parameter);
    CHECK(t.name == "tend");
    CHECK_FALSE(t.negated);
    ValueToken n = classify_value("-&Rho");
    CHECK(n.shape == ValueShape::Parameter);
    CHECK(n.negated);
    CHECK(n.name == "Rho");
    CHECK(parse_real("&x").status == NumberStatus::Parameter);
    CHECK(classify_value("& x").shape == ValueShape::Other);
}

TEST_CASE("values: the from_chars fast path agrees with the grammar") {
    // Every text is classified twice: as an integer field (fast path for integers) and as a
    // real field (fast path for reals); both must give the grammar's verdict and value.
    const char* texts[] = {"1",     "-1",     "+1",    "1.",     ".5",   "-.5",     "1e3",
                           "1E+03", "1.0D3",  "1.0+3", "inf",    "-inf", "nan",     "1e",
                           "-",     ".",      "-.",    "1.5e",   "0x10", "1..2",    "00012",
                           "-0",    "1e-400", "12a",   "9e9999", "-e5",  "1.0e+00", "-1.234567890e+01"};
    for (const char* text : texts) {
        CAPTURE(text);
        ValueToken as_int = classify_value(text, ValueShape::Integer);
        ValueToken as_real = classify_value(text, ValueShape::Real);
        bool grammar_number = as_int.shape == ValueShape::Integer || as_int.shape == ValueShape::Real;
        CHECK(grammar_number == (as_real.shape == ValueShape::Integer || as_real.shape == ValueShape::Real));
        if (!grammar_number) continue;
        RealValue a = to_real(as_int), b = to_real(as_real);
        CHECK(a.status == b.status);
        if (a.status == NumberStatus::Ok) CHECK(a.value == b.value);
    }
    CHECK(classify_value("inf", ValueShape::Real).shape == ValueShape::Other);
    CHECK(classify_value("-nan", ValueShape::Real).shape == ValueShape::Other);
}

TEST_CASE("values: the short-real path gives from_chars' double, bit for bit") {
    // Reals of at most 17 digits and a decimal exponent within 22 are converted without
    // from_chars (Clinger's fast path): the result must be the correctly rounded double that
    // from_chars gives, for the "%16.8e" coordinates of big decks and every other C form.
    std::mt19937_64 rng(7);
    const char* formats[] = {"%.8e", "%.3e", "%.16e", "%.6f", "%.1f", "%.12g", "%.17g", "%.0f", "%.2E"};
    auto same = [](const std::string& text) {
        double expected = 0.0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), expected);
        const ValueToken token = classify_value(text, ValueShape::Real);
        CAPTURE(text);
        REQUIRE(ec == std::errc());
        REQUIRE(end == text.data() + text.size());
        REQUIRE(token.shape == ValueShape::Real);
        const RealValue got = to_real(token);
        CHECK(got.status == NumberStatus::Ok);
        CHECK(std::memcmp(&got.value, &expected, sizeof expected) == 0);
    };
    for (int i = 0; i < 200000; ++i) {
        const double magnitude =
            std::ldexp(static_cast<double>(rng() >> 11) / 9007199254740992.0, static_cast<int>(rng() % 120) - 60);
        const double value = (rng() & 1) ? -magnitude : magnitude;
        char text[64];
        std::snprintf(text, sizeof text, formats[i % std::size(formats)], value);
        same(text);
    }
    for (const char* text : {"0", "-0", "0.0", "-0.0", "1.", "-.5", "000123.4500", "1e22", "1e-22", "9007199254740993",
                             "9007199254740992e-22", "123456789012345678", "4.9e-324", "1.7976931348623157e308",
                             "0.000000000000000000000001", "1.00000000e-06", "-2.29938015e-02", "1E+0", "2e-0",
                             // the one-go "%.8e" reader: its exponent limits, -0, upper case
                             "9.99999999e+99", "1.00000000e-99", "-0.00000000e+00", "1.23456789E-05", "1.23456789e+30",
                             "1.23456789e-14", "1.23456789e-15"})
        same(text);
}
}  // namespace test_values_cpp
