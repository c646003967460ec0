// Mistakes reported at their cause (issue 38): a stray *END or /END (DK017), a *PART heading left out
// (DK032), a keyword line that lost its '*' (DK033), a card of one-digit values one column right (DK029):
// each on the line a person edited, the symptoms elsewhere folded into its notes, its fix mending the deck.
#include <doctest/doctest.h>

#include <string>

#include "text/apply_edits.hpp"
#include "engine/check.hpp"
#include "test_support.hpp"

namespace test_mistakes_at_cause_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;
using test::find_code;

namespace {

const std::string head =
    "*KEYWORD\n*CONTROL_TERMINATION\n       1.0\n*CONTROL_SPH\n"
    "         1         0   1.0e+20         3       150        15       0.0   1.0e+15\n"
    "*SECTION_SPH\n         1       1.2       0.2       2.0       0.0   1.0e+20       0.0\n";  // lines 1-7
const std::string part = "*PART\nwater\n         1         1         1         1\n";
const std::string rest =
    "*MAT_NULL\n         1    1000.0\n*EOS_MURNAGHAN\n         1       7.0  340000.0       1.0\n"
    "*NODE\n       1             0.0             0.0             0.0\n"
    "       2             0.1             0.0             0.0\n"
    "*ELEMENT_SPH\n       1       1             1.0\n       2       1             1.0\n*END\n";

std::size_t errors_and_warnings(const engine::CheckResult& r) {
    std::size_t n = 0;
    for (const auto& d : r.diagnostics) n += d.severity != diag::Severity::Info;
    return n;
}

// The deck with the first fix of the finding applied.
std::string mended(const std::string& deck, const diag::Diagnostic& d) {
    REQUIRE(!d.fixes.empty());
    return text::apply_edits(deck, d.fixes.front().edits).text;
}

}  // namespace

TEST_CASE("DK017: keyword blocks after *END are a warning at *END, naming them; the symptoms are its notes") {
    const std::string deck = head + "*END\n" + part + rest;
    auto r = engine::check_buffer(deck, "d.k");
    const diag::Diagnostic* d = find_code(r.diagnostics, "DK017");
    REQUIRE(d);
    CHECK(d->span.line == 8);
    CHECK(d->severity == diag::Severity::Warning);
    CHECK(d->message.find("5 keyword blocks") != std::string::npos);
    CHECK(d->message.find("*PART, *MAT_NULL, *EOS_MURNAGHAN, *NODE, ...") != std::string::npos);
    CHECK(count_code(r.diagnostics, "REF007") == 0);  // "section 1 is not used": a note of the cause
    CHECK(errors_and_warnings(r) == 1);
    auto fixed = engine::check_buffer(mended(deck, *d), "d.k");
    CHECK(errors_and_warnings(fixed) == 0);
    CHECK(fixed.model.particles.size() == 2);
}

TEST_CASE("DK017: text, comments and an *INCLUDE after *END stay information on the first line") {
    auto text = engine::check_buffer(head + part + rest + "run notes\n*INCLUDE\nmore.k\n", "d.k");
    const diag::Diagnostic* d = find_code(text.diagnostics, "DK017");
    REQUIRE(d);
    CHECK(d->severity == diag::Severity::Info);
    CHECK(d->span.line == 22);
    CHECK(d->fixes.empty());
}

TEST_CASE("DK017: /END before /PART in a starter deck; HyperMesh metadata after /END is information") {
    const std::string begin =
        "#RADIOSS STARTER\n/BEGIN\nrun\n      2026\n                  kg                  mm                  ms\n"
        "                  kg                  mm                  ms\n";
    const std::string blocks =
        "/PART/2\nwater\n         2         3         0\n/MAT/LAW6/3\nwater\n              1.0E-6\n"
        "                 0.0                 0.0\n";
    const auto radioss = grammar::DeckFormat::Radioss;
    auto stray = engine::check_buffer(begin + "/END\n" + blocks + "/END\n", "run_0000.rad", {}, radioss);
    const diag::Diagnostic* d = find_code(stray.diagnostics, "DK017");
    REQUIRE(d);
    CHECK(d->severity == diag::Severity::Warning);
    CHECK(d->span.line == 7);
    CHECK(d->message.find("2 keyword blocks") != std::string::npos);
    CHECK(d->message.find("/PART, /MAT/LAW6") != std::string::npos);
    auto metadata = engine::check_buffer(begin + blocks + "/END\n/DUMMY_START/1\nH3\n/ASSEMBLY/1\nx\n/POSITION/1\n",
                                         "run_0000.rad", {}, radioss);
    const diag::Diagnostic* info = find_code(metadata.diagnostics, "DK017");
    REQUIRE(info);
    CHECK(info->severity == diag::Severity::Info);
}

TEST_CASE("DK033: a keyword line without its '*' is the cause; DK009 and the lost part are its notes") {
    const std::string deck = head + "PART\nwater\n         1         1         1         1\n" + rest;
    auto r = engine::check_buffer(deck, "d.k");
    const diag::Diagnostic* d = find_code(r.diagnostics, "DK033");
    REQUIRE(d);
    CHECK(d->span.line == 8);
    CHECK(d->message.find("did you mean *PART?") != std::string::npos);
    CHECK(d->severity == diag::Severity::Error);  // the particles' part is not defined: an error folded in
    CHECK(count_code(r.diagnostics, "DK009") == 0);
    CHECK(count_code(r.diagnostics, "REF002") == 0);
    CHECK(errors_and_warnings(r) == 1);
    CHECK_FALSE(d->fixes.front().safe);
    auto fixed = engine::check_buffer(mended(deck, *d), "d.k");
    CHECK(errors_and_warnings(fixed) == 0);
}

TEST_CASE("DK033: a part heading that is a plain keyword name is a heading") {
    auto r = engine::check_buffer(head + "*PART\nNODE\n         1         1         1         1\n" + rest, "d.k");
    CHECK(count_code(r.diagnostics, "DK033") == 0);
    CHECK(errors_and_warnings(r) == 0);
}

TEST_CASE("DK032: a *PART whose heading reads as card 2 is missing its heading; the fix inserts one") {
    const std::string deck = head + "*PART\n         1         1         1         1\n" + rest;
    auto r = engine::check_buffer(deck, "d.k");
    const diag::Diagnostic* d = find_code(r.diagnostics, "DK032");
    REQUIRE(d);
    CHECK(d->span.line == 9);
    CHECK(d->severity == diag::Severity::Error);
    CHECK(count_code(r.diagnostics, "DK008") == 0);  // "missing its Card 2": a note
    CHECK(count_code(r.diagnostics, "REF002") == 0);
    CHECK(errors_and_warnings(r) == 1);
    auto fixed = engine::check_buffer(mended(deck, *d), "d.k");
    CHECK(errors_and_warnings(fixed) == 0);
    CHECK(count_code(engine::check_buffer(head + "*PART\n         1         2\n         1         1         1\n" + rest,
                                          "d.k")
                         .diagnostics,
                     "DK032") == 0);  // a heading of numbers, with its card 2 below
}

TEST_CASE("DK029: one-digit values one column right, refused as written, moved back by a safe fix") {
    std::string deck = head + part + rest;
    const std::size_t at = deck.find("         1       1.2");
    deck.replace(at, deck.find('\n', at) - at, "          1         0");
    auto r = engine::check_buffer(deck, "d.k");
    const diag::Diagnostic* d = find_code(r.diagnostics, "DK029");
    REQUIRE(d);
    CHECK(d->span.line == 7);
    REQUIRE(!d->fixes.empty());
    CHECK(d->fixes.front().safe);
    CHECK(count_code(r.diagnostics, "DK008") == 0);
    CHECK(count_code(r.diagnostics, "REF003") == 0);  // part 1's section: folded by the mended re-check
    auto fixed = engine::check_buffer(mended(deck, *d), "d.k");
    CHECK(errors_and_warnings(fixed) == 0);
}
}  // namespace test_mistakes_at_cause_cpp
