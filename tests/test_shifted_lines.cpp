// The shifted-line and field-width diagnosis (grammar/shifted_line.hpp, DK029 and DK030): when it
// decides, and that its fix, applied, gives the line the author meant.
#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "grammar/shifted_line.hpp"
#include "test_support.hpp"

namespace test_shifted_lines_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;

namespace {

// Applies one fix's edits (whole lines or column ranges of one file) to `text`.
std::string apply(std::string text, const diag::Fix& fix) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    std::vector<diag::TextEdit> edits = fix.edits;
    std::sort(edits.begin(), edits.end(), [](const auto& a, const auto& b) {
        return a.span.line != b.span.line ? a.span.line > b.span.line : a.span.column > b.span.column;
    });
    for (const auto& e : edits) {
        std::string& l = lines.at(e.span.line - 1);
        l.replace(e.span.column - 1, e.span.end_column - e.span.column, e.replacement);
    }
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

const diag::Diagnostic* only(const engine::CheckResult& r, std::string_view code) {
    const diag::Diagnostic* found = nullptr;
    for (const auto& d : r.diagnostics)
        if (d.code == code) {
            if (found) return nullptr;
            found = &d;
        }
    return found;
}

keywords::CardSpec four_reals() {
    keywords::CardSpec card;
    for (int i = 0; i < 4; ++i)
        card.fields.push_back({.name = "F",
                               .column = static_cast<std::uint16_t>(1 + 10 * i),
                               .width = 10,
                               .type = keywords::FieldType::Real});
    return card;
}

const std::string control_sph = "         1         0   1.0e+20         3       150        15       0.0   1.0e+15";
const std::string deck_head =
    "*KEYWORD\n*CONTROL_SPH\n$#    ncbs     boxid        dt      idim    memory      form"
    "     start      maxv\n";

}  // namespace

TEST_CASE("shifted line: decided only on consistent evidence") {
    const auto card = four_reals();
    const auto slots = keywords::layout(card, grammar::CardFormat::Standard);
    const std::string aligned = "       1.0    2.0E-3       3.0  4.00E+10";
    for (int n : {1, 3, -2}) {
        INFO(n);
        const std::string moved = n > 0 ? std::string(static_cast<std::size_t>(n), ' ') + aligned : aligned.substr(2);
        auto shift = grammar::find_shift(moved, "", slots, card);
        if (n == -2) {
            CHECK_FALSE(shift);  // every value still whole in its field and no header: nothing to go on
            const std::string header = "$#      f1        f2        f3        f4";
            shift = grammar::find_shift(moved, header, slots, card);
            REQUIRE(shift);
            CHECK_FALSE(shift->changes_reading);  // a warning: only misaligned
            CHECK(shift->from_header);
        } else {
            REQUIRE(shift);
            CHECK(shift->changes_reading);
        }
        CHECK(shift->columns == n);
        CHECK(shift->realigned == aligned);
    }
    CHECK_FALSE(grammar::find_shift(aligned, "", slots, card));                   // nothing off
    CHECK_FALSE(grammar::find_shift("        1.0E-3", "", slots, card));          // one value: no consistent shift
    CHECK_FALSE(grammar::find_shift("        1.0E-3     2.0", "", slots, card));  // the values disagree: no one shift
    CHECK_FALSE(grammar::find_shift(" 1.0 2.0 3.0", "", slots, card));            // free-ish words, no field ends
    CHECK_FALSE(grammar::find_shift("        1.0,2.0", "", slots, card));         // free format
}

TEST_CASE("field widths: a line written in 8-column fields where 10 are read") {
    keywords::CardSpec card;
    for (int i = 0; i < 8; ++i)
        card.fields.push_back({.name = "D",
                               .column = static_cast<std::uint16_t>(1 + 10 * i),
                               .width = 10,
                               .type = keywords::FieldType::Integer});
    const std::string eight = "       1       0       1       1       1       0       0       0";
    auto written = grammar::find_written_widths(eight, card, grammar::CardFormat::Standard);
    REQUIRE(written);
    CHECK(written->described == "8-column fields");
    const auto read = keywords::layout(card, grammar::CardFormat::Standard);
    CHECK(grammar::rewrite_fields(eight, written->slots, read, card) ==
          "         1         0         1         1         1         0         0         0");
    CHECK_FALSE(grammar::find_written_widths("         1         0         1         1", card,
                                             grammar::CardFormat::Standard));  // read as written
}

TEST_CASE("DK029: the fix moves the values back and the line reads the values meant") {
    for (const std::string& moved : {" " + control_sph, "   " + control_sph}) {
        const std::string text = deck_head + moved + "\n*END\n";
        auto r = engine::check_buffer(text, "d.k");
        const diag::Diagnostic* d = only(r, "DK029");
        REQUIRE(d);
        CHECK(d->severity == diag::Severity::Error);
        CHECK(d->span.line == 4);
        CHECK(count_code(r.diagnostics, "DK003") == 0);  // folded: notes of the DK029
        CHECK(count_code(r.diagnostics, "SPH070") == 0);
        REQUIRE(d->fixes.size() == 1);
        CHECK(d->fixes[0].safe);
        const std::string fixed = apply(text, d->fixes[0]);
        CHECK(fixed == deck_head + control_sph + "\n*END\n");
        auto again = engine::check_buffer(fixed, "d.k");
        CHECK(count_code(again.diagnostics, "DK029") == 0);
        CHECK(diag::count(again.diagnostics).errors == 0);
    }
}

TEST_CASE("DK029: no shift that moves a real into an integer field; the value misread is reported where it is") {
    // ENDTIM 1.0 where it belongs and 0.5 in the integer ENDCYC: moved 3 columns right, both values would be
    // whole and left-aligned in fields, but ENDTIM would be emptied and ENDCYC read 1.0 (DK004).
    const std::string text = "*KEYWORD\n*CONTROL_TERMINATION\n       1.0       0.5\n*END\n";
    auto r = engine::check_buffer(text, "d.k");
    CHECK(count_code(r.diagnostics, "DK029") == 0);
    CHECK(count_code(r.diagnostics, "DK002") == 1);  // '0.5' in ENDCYC is not an integer, at its own columns
    for (const auto& d : r.diagnostics)
        CHECK(std::none_of(d.fixes.begin(), d.fixes.end(), [](const diag::Fix& f) { return f.safe; }));
    // The same shift with integers in the integer fields is still found.
    keywords::CardSpec card = four_reals();
    card.fields[1].type = keywords::FieldType::Integer;
    const auto slots = keywords::layout(card, grammar::CardFormat::Standard);
    CHECK_FALSE(grammar::find_shift("       1.0       0.5", "", slots, card));
    auto shift = grammar::find_shift("        2.5         3       7.0", "", slots, card);
    REQUIRE(shift);
    CHECK(shift->columns == 1);
    CHECK(shift->realigned == "       2.5         3       7.0");
}

TEST_CASE("DK030: one finding for the block, its fix rewrites every line in the widths read") {
    const std::string nodes =
        "*KEYWORD\n*NODE\n       1             0.0             0.0             0.0\n"
        "       2             1.0             0.0             0.0\n";
    const std::string text = nodes +
                             "*BOUNDARY_SPC_NODE\n"
                             "       1       0       1       1       1       0       0       0\n"
                             "       2       0       1       0       1       0       0       0\n*END\n";
    auto r = engine::check_buffer(text, "d.k");
    const diag::Diagnostic* d = only(r, "DK030");
    REQUIRE(d);
    CHECK(d->span.line == 6);
    CHECK(count_code(r.diagnostics, "DK003") == 0);
    REQUIRE(d->fixes.size() == 1);
    const std::string fixed = apply(text, d->fixes[0]);
    CHECK(fixed == nodes +
                       "*BOUNDARY_SPC_NODE\n"
                       "         1         0         1         1         1         0         0         0\n"
                       "         2         0         1         0         1         0         0         0\n*END\n");
    CHECK(engine::check_buffer(fixed, "d.k").diagnostics.empty());
}

TEST_CASE("OpenRadioss: a /PROP line one column right is one DK029; its fix gives the deck as written before") {
    std::ifstream in(std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/rad/DK029_prop_fires.rad");
    REQUIRE(in);
    std::stringstream whole;
    whole << in.rdbuf();
    const std::string text = whole.str();
    auto r = engine::check_buffer(text, "prop_0000.rad", {}, grammar::DeckFormat::Radioss);
    const diag::Diagnostic* d = only(r, "DK029");
    REQUIRE(d);
    CHECK(count_code(r.diagnostics, "RAD025") == 0);  // notes of the DK029
    REQUIRE(d->fixes.size() == 1);
    const std::string fixed = apply(text, d->fixes[0]);
    CHECK(fixed.find("\n              8.0E-6                 2.0                 1.0") != std::string::npos);
    auto again = engine::check_buffer(fixed, "prop_0000.rad", {}, grammar::DeckFormat::Radioss);
    CHECK(diag::count(again.diagnostics).errors == 0);
    CHECK(count_code(again.diagnostics, "DK029") == 0);
}

TEST_CASE("OpenRadioss: a value across a cell boundary says what the starter keeps and where the rest goes") {
    std::ifstream in(std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/rad/RAD030_fires.rad");
    REQUIRE(in);
    std::stringstream whole;
    whole << in.rdbuf();
    auto r = engine::check_buffer(whole.str(), "straddle_0000.rad", {}, grammar::DeckFormat::Radioss);
    REQUIRE(count_code(r.diagnostics, "RAD030") == 2);  // h on /PROP/SPH, a dof flag on /BCS
    const diag::Diagnostic* d = nullptr;
    for (const auto& f : r.diagnostics)
        if (f.code == "RAD030" && f.message.find("cell h ") != std::string::npos) d = &f;
    REQUIRE(d);
    CHECK(d->message ==
          "'2.4' straddles the end of cell h (columns 11-30): the starter reads h as '2.' and '4' is "
          "read as the start of Xi_Stab (columns 31-50)");
    CHECK(count_code(r.diagnostics, "RAD025") == 0);
    REQUIRE(d->notes.size() == 1);
    CHECK(d->notes[0].message.ends_with("[RAD025]"));
}

TEST_CASE("OpenRadioss: a one-column flag run into the wider cell after it is RAD030; flags side by side are not") {
    const std::string head =
        "#RADIOSS STARTER\n/BEGIN\nflags\n      2026\n"
        "                  kg                  mm                  ms\n"
        "                  kg                  mm                  ms\n/BCS/4\nfixed\n";
    const std::string tail =
        "/GRNOD/NODE/2\nnodes\n         1\n/NODE\n         1                 0.0"
        "                 0.0                 0.0\n/END\n";
    auto moved = engine::check_buffer(head + "   001 1 10        0         2\n" + tail, "bcs_0000.rad", {},
                                      grammar::DeckFormat::Radioss);
    const diag::Diagnostic* d = only(moved, "RAD030");
    REQUIRE(d);
    CHECK(d->message.starts_with("'10' straddles the end of cell dof6 (columns 10-10)"));
    auto written = engine::check_buffer(head + "   001 110         0         2\n" + tail, "bcs_0000.rad", {},
                                        grammar::DeckFormat::Radioss);
    CHECK(count_code(written.diagnostics, "RAD030") == 0);
}

TEST_CASE("DK029 warning: a shift that changes no value read folds none of the line's findings") {
    const std::string text =
        deck_head + "       1         0   1.0e+20         5       150        15       0.0   1.0e+15\n*END\n";
    auto r = engine::check_buffer(text, "d.k");
    const diag::Diagnostic* d = only(r, "DK029");
    REQUIRE(d);
    CHECK(d->severity == diag::Severity::Warning);
    CHECK(count_code(r.diagnostics, "DK007") == 1);  // IDIM 5: its own error, not the shift's
}
}  // namespace test_shifted_lines_cpp
