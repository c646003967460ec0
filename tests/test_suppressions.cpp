// Inline "$ sphdeck:" suppressions: next line, block, file, unused (DK026) and malformed (DK028).
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "engine/check.hpp"
#include "lint/suppressions.hpp"
#include "test_support.hpp"

namespace test_suppressions_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;
using test::find_code;

namespace {

// Two *CONTROL_TERMINATION blocks would add DK018; *DEFINE_CURVE takes any number of cards
// whose first field is real, so "abc" gives one DK003 per line.
std::vector<diag::Diagnostic> check(const std::string& text) {
    // The pipeline applies the deck's suppressions itself.
    return engine::check_buffer(text, "main.k").diagnostics;
}

std::vector<std::uint32_t> lines_of(const std::vector<diag::Diagnostic>& ds, const std::string& code) {
    std::vector<std::uint32_t> out;
    for (const auto& d : ds)
        if (d.code == code) out.push_back(d.span.line);
    return out;
}

const std::string kHead = "*KEYWORD\n*CONTROL_TERMINATION\n$#  endtim\n";

}  // namespace

TEST_CASE("suppress: the deck without directives reports DK003") {
    auto ds = check(kHead + "abc\n*END\n");
    CHECK(lines_of(ds, "DK003") == std::vector<std::uint32_t>{4});
}

TEST_CASE("suppress: disable before a data line silences that line only") {
    auto ds = check(
        "*KEYWORD\n*CONTROL_TERMINATION\n$ sphdeck: disable=DK003 -- known\nabc\n"
        "*CONTROL_TIMESTEP\nabc\n*END\n");
    CHECK(lines_of(ds, "DK003") == std::vector<std::uint32_t>{6});
    CHECK(count_code(ds, "DK026") == 0);
}

TEST_CASE("suppress: disable before a keyword line silences its whole block") {
    const std::string text =
        "*KEYWORD\n"
        "$ sphdeck: disable=bad-real,DK009 -- by name and code\n"
        "$ another comment in between\n"
        "*CONTROL_TERMINATION\n"  // line 4
        "abc\n"
        "$ a comment inside the block\n"
        "abc\n"  // line 7: DK009 too many cards
        "*CONTROL_TIMESTEP\n"
        "abc\n"  // line 9: not silenced
        "*END\n";
    auto ds = check(text);
    CHECK(lines_of(ds, "DK003") == std::vector<std::uint32_t>{9});
    CHECK(count_code(ds, "DK009") == 0);
    CHECK(count_code(ds, "DK026") == 0);
}

TEST_CASE("suppress: disable-next-line before a keyword line covers the keyword line only") {
    auto ds = check("*KEYWORD\n$ sphdeck: disable-next-line=DK003\n*CONTROL_TERMINATION\nabc\n*END\n");
    CHECK(lines_of(ds, "DK003") == std::vector<std::uint32_t>{4});
    const diag::Diagnostic* unused = find_code(ds, "DK026");
    REQUIRE(unused != nullptr);
    CHECK(unused->span.line == 2);
    CHECK(unused->severity == diag::Severity::Info);
}

TEST_CASE("suppress: disable-file silences the whole file, wherever it stands") {
    auto ds = check(kHead + "abc\n*CONTROL_TIMESTEP\nabc\n$ sphdeck: disable-file=DK003 -- legacy deck\n*END\n");
    CHECK(count_code(ds, "DK003") == 0);
    CHECK(count_code(ds, "DK026") == 0);
}

TEST_CASE("suppress: `all` silences every rule where it applies") {
    auto ds = check("*KEYWORD\n$ sphdeck: disable=all\n*CONTROL_TERMINATION\nabc\nabc\n*END\n");
    CHECK(count_code(ds, "DK003") == 0);
    CHECK(count_code(ds, "DK009") == 0);
}

TEST_CASE("suppress: an unused directive is reported at the code it names") {
    auto ds = check("*KEYWORD\n$ sphdeck: disable=DK003,DK002 -- one is stale\n*CONTROL_TERMINATION\nabc\n*END\n");
    CHECK(count_code(ds, "DK003") == 0);
    REQUIRE(count_code(ds, "DK026") == 1);
    const diag::Diagnostic* unused = find_code(ds, "DK026");
    CHECK(unused->span.line == 2);
    CHECK(unused->span.column == 26);  // "DK002"
    CHECK(unused->span.end_column == 31);
    CHECK(unused->message.find("DK002 (bad-integer)") != std::string::npos);

    // At the end of the file nothing follows: unused too.
    ds = check(kHead + "     0.002\n$ sphdeck: disable=DK003\n");
    CHECK(count_code(ds, "DK026") == 1);
    // disable-file=DK026 keeps a file's stale directives quiet.
    ds = check("$ sphdeck: disable-file=DK026\n" + kHead + "     0.002\n$ sphdeck: disable=DK003\n");
    CHECK(count_code(ds, "DK026") == 0);
}

TEST_CASE("suppress: malformed directives are reported and silence nothing") {
    auto ds = check("*KEYWORD\n$ sphdeck: disabel=DK003\n*CONTROL_TERMINATION\nabc\n*END\n");
    CHECK(count_code(ds, "DK003") == 1);
    const diag::Diagnostic* bad = find_code(ds, "DK028");
    REQUIRE(bad != nullptr);
    CHECK(bad->severity == diag::Severity::Warning);
    CHECK(bad->message.find("'disabel'") != std::string::npos);
    CHECK(bad->span.line == 2);
    CHECK(bad->span.column == 12);

    ds = check("*KEYWORD\n$ sphdeck: disable DK003\n*END\n");
    CHECK(count_code(ds, "DK028") == 1);
    CHECK(find_code(ds, "DK028")->message.find("expected '='") != std::string::npos);

    // An unknown code is reported; the valid ones of the same directive still work.
    ds = check("*KEYWORD\n$ sphdeck: disable=SPH03O,DK003\n*CONTROL_TERMINATION\nabc\n*END\n");
    CHECK(count_code(ds, "DK003") == 0);
    REQUIRE(count_code(ds, "DK028") == 1);
    CHECK(find_code(ds, "DK028")->message.find("did you mean 'SPH030'") != std::string::npos);

    ds = check("*KEYWORD\n$ sphdeck: disable=DK003 DK002\n$ sphdeck: disable=,\n*END\n");
    CHECK(count_code(ds, "DK028") == 3);  // a missing comma; two empty codes
}

TEST_CASE("suppress: comments that are no directive are left alone") {
    for (const char* comment : {"$ sphdeck is great\n", "$# sphdeck: disable=DK003\n", "$ written by sphdeck\n",
                                "$sphdeckx: disable=DK003\n"}) {
        INFO(comment);
        auto ds = check("*KEYWORD\n*CONTROL_TERMINATION\n" + std::string(comment) + "abc\n*END\n");
        CHECK(count_code(ds, "DK003") == 1);
        CHECK(count_code(ds, "DK026") + count_code(ds, "DK028") == 0);
    }
    auto ds = check("*KEYWORD\n*CONTROL_TERMINATION\n$sphdeck:disable=DK003\r\nabc\r\n*END\n");  // compact, CRLF
    CHECK(count_code(ds, "DK003") == 0);
}

TEST_CASE("suppress: a directive applies to its own file, not to the files it includes") {
    test::TempDir dir;
    dir.write("part.k", "*CONTROL_TIMESTEP\nabc\n");
    const std::string main = dir.write("main.k",
                                       "*KEYWORD\n$ sphdeck: disable-file=DK003\n*CONTROL_TERMINATION\nabc\n"
                                       "*INCLUDE\npart.k\n*END\n");
    engine::CheckResult r = engine::check_file(main);
    REQUIRE(count_code(r.diagnostics, "DK003") == 1);
    CHECK(r.deck.sources.file(find_code(r.diagnostics, "DK003")->span.file).display_name.ends_with("part.k"));
}

TEST_CASE("suppress: parse_suppression reads scope, codes and their columns") {
    lint::Suppression s;
    std::vector<diag::Diagnostic> problems;
    REQUIRE(lint::parse_suppression("$ sphdeck: disable-file = sph032 , form-advice -- why", 0, 7, s, problems));
    CHECK(problems.empty());
    CHECK(s.scope == lint::Suppression::Scope::File);
    CHECK(s.line == 7);
    REQUIRE(s.items.size() == 2);
    CHECK(s.items[0].code == "SPH032");
    CHECK(s.items[0].column == 27);
    CHECK(s.items[0].end_column == 33);
    CHECK(s.items[1].code == "SPH034");
    CHECK_FALSE(lint::parse_suppression("$ sphdeck rocks", 0, 1, s, problems));
    CHECK_FALSE(lint::parse_suppression("* sphdeck: disable=DK003", 0, 1, s, problems));
}

namespace {

// A Radioss starter deck: lines 1-5 are the header, /BEGIN and /NODE; `body` starts on line 6.
// "abc" in a coordinate gives one DK003 per line.
std::vector<diag::Diagnostic> check_radioss(const std::string& body) {
    return engine::check_buffer("#RADIOSS STARTER\n/BEGIN\nrun\n      2026\n/NODE\n" + body + "/END\n", "main_0000.rad",
                                {}, grammar::DeckFormat::Radioss)
        .diagnostics;
}

const std::string kBadNode1 = "         1                 abc                 0.0                 0.0\n";
const std::string kBadNode2 = "         2                 abc                 0.0                 0.0\n";

}  // namespace

TEST_CASE("suppress: Radioss decks take the directives after '#'") {
    // Without a directive both lines are reported.
    CHECK(lines_of(check_radioss(kBadNode1 + kBadNode2), "DK003") == std::vector<std::uint32_t>{6, 7});

    // Before a data line: that line only.
    auto ds = check_radioss("# sphdeck: disable=DK003 -- known\n" + kBadNode1 + kBadNode2);
    CHECK(lines_of(ds, "DK003") == std::vector<std::uint32_t>{8});
    CHECK(count_code(ds, "DK026") == 0);

    // disable-next-line, compact spelling.
    ds = check_radioss("#sphdeck:disable-next-line=bad-real\n" + kBadNode1 + kBadNode2);
    CHECK(lines_of(ds, "DK003") == std::vector<std::uint32_t>{8});

    // disable-file, wherever it stands; '$' works in Radioss decks as well.
    ds = check_radioss(kBadNode1 + kBadNode2 + "# sphdeck: disable-file=DK003 -- legacy mesh\n");
    CHECK(count_code(ds, "DK003") == 0);
    ds = check_radioss(kBadNode1 + "$ sphdeck: disable-next-line=DK003\n" + kBadNode2);
    CHECK(lines_of(ds, "DK003") == std::vector<std::uint32_t>{6});
}

TEST_CASE("suppress: in a Radioss deck a directive before a '/' header covers its block") {
    const std::string text =
        "#RADIOSS STARTER\n/BEGIN\nrun\n      2026\n"
        "# sphdeck: disable=DK003\n"
        "/NODE\n" +  // line 6
        kBadNode1 +  // line 7: silenced
        "# a comment inside the block\n" +
        kBadNode2 +                                                                 // line 9: silenced
        "/NODE\n" +                                                                 // line 10: a new block
        "         3                 abc                 0.0                 0.0\n"  // line 11
        "/END\n";
    auto ds = engine::check_buffer(text, "main_0000.rad", {}, grammar::DeckFormat::Radioss).diagnostics;
    CHECK(lines_of(ds, "DK003") == std::vector<std::uint32_t>{11});
    CHECK(count_code(ds, "DK026") == 0);

    // Unused and malformed '#' directives are reported like '$' ones.
    ds = check_radioss("# sphdeck: disable=DK002\n" + kBadNode1 + "# sphdeck: disabel=DK003\n");
    REQUIRE(count_code(ds, "DK026") == 1);
    CHECK(find_code(ds, "DK026")->span.line == 6);
    CHECK(find_code(ds, "DK026")->span.column == 20);
    REQUIRE(count_code(ds, "DK028") == 1);
    CHECK(find_code(ds, "DK028")->span.line == 8);
}

TEST_CASE("suppress: '#include' and '#enddata' are no comments, and '#' is no comment in LS-DYNA decks") {
    // A directive before #include covers the #include line, not the line after it.
    test::TempDir dir;
    dir.write("empty.inc", "");
    const std::string main = dir.write("main_0000.rad",
                                       "#RADIOSS STARTER\n/BEGIN\nrun\n      2026\n/NODE\n"
                                       "# sphdeck: disable=DK003\n#include empty.inc\n" +
                                           kBadNode1 + "/END\n");
    auto r = engine::check_file(main);
    CHECK(lines_of(r.diagnostics, "DK003") == std::vector<std::uint32_t>{8});
    CHECK(count_code(r.diagnostics, "DK026") == 1);

    // In an LS-DYNA deck the '#' line is a card like any other: no directive, nothing silenced.
    auto ds = check("*KEYWORD\n*CONTROL_TERMINATION\nabc\n# sphdeck: disable-file=DK003\n*END\n");
    const auto dk003 = lines_of(ds, "DK003");
    CHECK(std::find(dk003.begin(), dk003.end(), 3u) != dk003.end());
    CHECK(count_code(ds, "DK026") + count_code(ds, "DK028") == 0);

    lint::Suppression s;
    std::vector<diag::Diagnostic> problems;
    CHECK(lint::parse_suppression("# sphdeck: disable=DK003", 0, 1, s, problems));
    CHECK(s.items.size() == 1);
}
}  // namespace test_suppressions_cpp
