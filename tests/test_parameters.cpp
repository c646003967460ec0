// Format rules of the *PARAMETER family (lsdyna-format.md §14).
#include <doctest/doctest.h>

#include "grammar/dyna/reader.hpp"
#include "engine/check.hpp"
#include "test_support.hpp"

namespace test_parameters_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using grammar::dyna::read_buffer;
using test::count_code;

namespace {
const grammar::Parameter* param(const grammar::RawDeck& deck, std::string_view name) {
    return deck.parameters.find(name, 0, deck.parameters.epoch()).parameter;
}
}  // namespace

TEST_CASE("parameters: R, I and C types, glued or spaced names, 4 pairs per line") {
    auto deck = read_buffer(
        "*PARAMETER\n"
        "Rtend     1.0+3     I  n              12Cname     water     r    rho      1000.0\n",
        "d.k");
    CHECK(deck.diagnostics.empty());
    REQUIRE(param(deck, "tend"));
    REQUIRE(param(deck, "n"));
    REQUIRE(param(deck, "name"));
    REQUIRE(param(deck, "rho"));
    CHECK(param(deck, "tend")->number == 1000.0);
    CHECK(param(deck, "n")->type == grammar::ParameterType::Integer);
    CHECK(param(deck, "n")->number == 12);
    CHECK(param(deck, "name")->text == "water");
    CHECK(param(deck, "rho")->number == 1000.0);
}

TEST_CASE("parameters: free format pairs") {
    auto deck = read_buffer("*PARAMETER\nR dt,0.5,I k,3\n", "d.k");
    CHECK(deck.diagnostics.empty());
    CHECK(param(deck, "dt")->number == 0.5);
    CHECK(param(deck, "k")->number == 3);
}

TEST_CASE("parameters: &name and -&name substitute in fields, right-justified references too") {
    auto r = engine::check_buffer(
        "*PARAMETER\nR tend    2.5\n*CONTROL_TERMINATION\n     &tend\n*CONTROL_TIMESTEP\n         0    -&tend\n",
        "d.k");
    CHECK(count_code(r.diagnostics, "DK012") == 0);
    CHECK(count_code(r.diagnostics, "DK003") == 0);
}

TEST_CASE("parameters: undefined, used before definition, and wrong type") {
    auto r = engine::check_buffer(
        "*CONTROL_TERMINATION\n     &tend\n*PARAMETER\nR tend    2.5\nC word    abc       R x            1.5\n"
        "*CONTROL_TERMINATION\n     &word\n*CONTROL_SPH\n        &x\n",
        "d.k");
    CHECK(count_code(r.diagnostics, "DK012") == 1);  // used before its definition
    CHECK(count_code(r.diagnostics, "DK013") == 2);  // C in a real field, R in an integer field
    const auto* undefined = test::find_code(r.diagnostics, "DK012");
    REQUIRE(undefined);
    CHECK(undefined->span.line == 2);
    CHECK(undefined->span.column == 6);
}

TEST_CASE("parameters: *PARAMETER_EXPRESSION with references, functions and continuation") {
    auto deck = read_buffer(
        "*PARAMETER\nR h       2.0\n*PARAMETER_EXPRESSION\nR area    &h*h + max(1, 2)\n"
        "R long    sqrt(area)\n          + pi*0\nI count   7/2\nR bad     (1 +\nR zero    1/0\nR undef   &nope+1\n",
        "d.k");
    CHECK(param(deck, "area")->number == doctest::Approx(6.0));
    CHECK(param(deck, "long")->number == doctest::Approx(std::sqrt(6.0)));
    CHECK(param(deck, "count")->number == 3);  // integer expressions truncate like Fortran INT()
    CHECK(count_code(deck.diagnostics, "DK015") == 2);
    CHECK(count_code(deck.diagnostics, "DK012") == 1);
}

TEST_CASE("parameters: *PARAMETER_DUPLICATION decides what a redefinition does") {
    const std::string defs = "*PARAMETER\nR a       1.0\n*PARAMETER\nR a       2.0\n";
    auto keep = read_buffer(defs, "d.k");  // DFLAG 1 by default: warn, keep the first
    CHECK(param(keep, "a")->number == 1.0);
    CHECK(count_code(keep.diagnostics, "DK014") == 1);
    CHECK(keep.diagnostics[0].severity == diag::Severity::Warning);

    auto replace = read_buffer("*PARAMETER_DUPLICATION\n         2\n" + defs, "d.k");
    CHECK(param(replace, "a")->number == 2.0);

    auto error = read_buffer("*PARAMETER_DUPLICATION\n         3\n" + defs, "d.k");
    REQUIRE(count_code(error.diagnostics, "DK014") == 1);
    CHECK(error.diagnostics[0].severity == diag::Severity::Error);

    auto silent = read_buffer("*PARAMETER_DUPLICATION\n         4\n" + defs, "d.k");
    CHECK(silent.diagnostics.empty());
    CHECK(param(silent, "a")->number == 2.0);

    auto ignore = read_buffer("*PARAMETER_DUPLICATION\n         5\n" + defs, "d.k");
    CHECK(ignore.diagnostics.empty());
    CHECK(param(ignore, "a")->number == 1.0);
}

TEST_CASE("parameters: definitions differing only by case are reported, references resolve silently") {
    auto deck = read_buffer("*PARAMETER_DUPLICATION\n         4\n*PARAMETER\nR Rho     1.0\nR rho     2.0\n", "d.k");
    CHECK(count_code(deck.diagnostics, "DK024") == 1);
    // LS-DYNA resolves references case-insensitively (issue 26, class H).
    auto r = engine::check_buffer("*PARAMETER\nR Tend    1.0\n*CONTROL_TERMINATION\n     &tend\n", "d.k");
    CHECK(count_code(r.diagnostics, "DK024") == 0);
    CHECK(count_code(r.diagnostics, "DK012") == 0);
}

TEST_CASE("parameters: *PARAMETER_LOCAL is seen by its file and its includes only") {
    test::TempDir dir;
    dir.write("child.k", "*CONTROL_TERMINATION\n     &loc\n");
    dir.write("local.k", "*PARAMETER_LOCAL\nR loc     1.0\n*INCLUDE\nchild.k\n");
    dir.write("global.k", "*PARAMETER\nR glob    1.0\n");
    auto main =
        dir.write("main.k",
                  "*INCLUDE\nlocal.k\nglobal.k\n*CONTROL_TIMESTEP\n     &glob\n*CONTROL_TERMINATION\n     &loc\n");
    auto r = engine::check_file(main);
    // The sibling's global parameter is visible; the local one is not, outside local.k's tree.
    REQUIRE(count_code(r.diagnostics, "DK012") == 1);
    const auto* d = test::find_code(r.diagnostics, "DK012");
    CHECK(r.deck.sources.file(d->span.file).display_name.find("main.k") != std::string::npos);
}

TEST_CASE("parameters: case-only matches inside *PARAMETER cards resolve, tabs there are reported") {
    auto deck =
        read_buffer("*PARAMETER\nR tend    0.002\nR t2      &TEND\n*PARAMETER_EXPRESSION\nR t3      &TEND*2.0\n",
                    "d.k");
    CHECK(count_code(deck.diagnostics, "DK024") == 0);
    CHECK(count_code(deck.diagnostics, "DK012") == 0);
    // A tab that moves the value into the next field when expanded to column 9 (issue 26, class J).
    auto tabs = read_buffer("*PARAMETER\nR tend\t        0.002\n", "d.k");
    CHECK(count_code(tabs.diagnostics, "DK016") == 1);
    CHECK(count_code(read_buffer("*PARAMETER\nR tend\t   0.002\n", "d.k").diagnostics, "DK016") == 0);
}
}  // namespace test_parameters_cpp
