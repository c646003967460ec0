// edit/format_*: `sphdeck format`'s layout of a deck as text edits: numbers right-aligned in their own
// columns, text and doubtful lines kept, keyword case, `$#` headers, free lines, idempotence.
#include <doctest/doctest.h>

#include <string>

#include "text/apply_edits.hpp"
#include "edit/format_deck.hpp"
#include "edit/format_line.hpp"
#include "engine/check.hpp"

namespace test_format_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

std::string format_text(const std::string& text, edit::FormatOptions options = {},
                        edit::FormatResult* result = nullptr) {
    const engine::CheckResult r = engine::check_buffer(text, "main.k");
    edit::FormatResult formatted = edit::format_deck(r.deck, r.diagnostics, {0}, options);
    std::string out = text::apply_edits(text, formatted.edits).text;
    if (result) *result = std::move(formatted);
    return out;
}

std::size_t changes(const edit::FormatResult& r, edit::FormatChange kind) {
    return r.changes[static_cast<std::size_t>(kind)];
}

}  // namespace

TEST_CASE("format line: numbers right-aligned, blanks stay blank, text kept") {
    const std::vector<grammar::FixedField> slots{{0, 10}, {10, 10}, {20, 10}, {30, 10}};
    using K = edit::CellKind;
    const std::vector<K> kinds{K::Number, K::Number, K::Text, K::Number};
    std::string out;
    auto laid = edit::layout_fixed_line("1         2.5e-3    abc       7", slots, kinds, out);
    CHECK(laid.verdict == edit::LineVerdict::Changed);
    CHECK(out == "         1    2.5e-3abc                7");
    // Already canonical: the same.
    laid = edit::layout_fixed_line("         1    2.5e-3", slots, kinds, out);
    CHECK(laid.verdict == edit::LineVerdict::Same);
    // A value across a boundary, a blank inside a value, text past the fields, a tab: left as written.
    CHECK(edit::layout_fixed_line("      1.0002.0", slots, kinds, out).verdict == edit::LineVerdict::Doubt);
    CHECK(edit::layout_fixed_line("  1.0 2   ", slots, kinds, out).verdict == edit::LineVerdict::Doubt);
    CHECK(edit::layout_fixed_line(std::string(40, ' ') + "x", slots, kinds, out).verdict == edit::LineVerdict::Doubt);
    CHECK(edit::layout_fixed_line("\t1.0", slots, kinds, out).verdict == edit::LineVerdict::Doubt);
    // A value that fills its field may touch the one before (dense decks are written so).
    laid = edit::layout_fixed_line("1234567890123456789", slots, kinds, out);
    CHECK(laid.verdict == edit::LineVerdict::Doubt);  // the second is not full: one value cut in two?
    laid = edit::layout_fixed_line("12345678901234567890", slots, kinds, out);
    CHECK(laid.verdict == edit::LineVerdict::Same);
    laid = edit::layout_fixed_line("1.0       -1.2345e-5", slots, kinds, out);
    CHECK(laid.verdict == edit::LineVerdict::Changed);
    CHECK(out == "       1.0-1.2345e-5");
    // A parameter reference moves like a number and keeps its text.
    laid = edit::layout_fixed_line("&ro", slots, kinds, out);
    CHECK(out == "       &ro");
}

TEST_CASE("format line: the bulk lines' quick test agrees with the layout") {
    const std::vector<grammar::FixedField> slots{{0, 8}, {8, 16}, {24, 16}};
    using K = edit::CellKind;
    const std::vector<K> kinds{K::Number, K::Number, K::Number};
    std::string out;
    for (const std::string line :
         {"       1  1.00000000e-01 -2.00000000e+00", "       1  1.00000000e-01",
          "       1                  -2.00000000e+00", "1         1.00000000e-01", "       1  1.00000000e-01 ",
          "       1 1.0 2", "       1  1.00000000e-01 x", "       1-1.00000000e-01"}) {
        CAPTURE(line);
        const bool quick = edit::already_laid_out(line, slots, kinds);
        const auto laid = edit::layout_fixed_line(line, slots, kinds, out);
        if (quick) CHECK(laid.verdict == edit::LineVerdict::Same);
        if (laid.verdict == edit::LineVerdict::Changed) CHECK_FALSE(quick);
    }
    CHECK(edit::already_laid_out("       1  1.00000000e-01 -2.00000000e+00", slots, kinds));
    CHECK_FALSE(edit::already_laid_out("1         1.00000000e-01", slots, kinds));
}

TEST_CASE("format: a deck's cards in their columns, keyword names upper case, comments kept") {
    const std::string deck =
        "*keyword\n"
        "$ a comment   stays   as it is   \n"
        "*control_termination\n"
        "1.0\n"
        "*CONTROL_SPH\n"
        "$#    ncbs    boxid\n"
        "1         0                   \n"
        "\n"
        "*END\n";
    edit::FormatResult result;
    const std::string out = format_text(deck, {}, &result);
    CHECK(out ==
          "*KEYWORD\n"
          "$ a comment   stays   as it is   \n"
          "*CONTROL_TERMINATION\n"
          "       1.0\n"
          "*CONTROL_SPH\n"
          "$#    ncbs    boxid\n"
          "         1         0\n"
          "\n"
          "*END\n");
    CHECK(changes(result, edit::FormatChange::KeywordCase) == 2);
    CHECK(changes(result, edit::FormatChange::Realigned) == 2);
    CHECK(format_text(out) == out);  // idempotent
}

TEST_CASE("format: a line with a finding of the deck syntax, or in doubt, is left as written") {
    const std::string deck =
        "*KEYWORD\n"
        "*CONTROL_TERMINATION\n"
        "   1.0E-32.0\n"  // DK003: a value across the field boundary
        "*END\n";
    edit::FormatResult result;
    CHECK(format_text(deck, {}, &result) == deck);
    CHECK(result.kept == 1);
    REQUIRE(result.kept_lines.size() == 1);
    CHECK(result.kept_lines[0].line == 3);
}

TEST_CASE("format: free lines stay free unless --to fixed; long and I10 widths as the block reads them") {
    const std::string deck =
        "*KEYWORD\n"
        "*CONTROL_TERMINATION\n"
        "1.0,,2\n"
        "*CONTROL_TERMINATION+\n"
        "1.0\n"
        "*END\n";
    std::string out = format_text(deck);
    CHECK(out ==
          "*KEYWORD\n"
          "*CONTROL_TERMINATION\n"
          "1.0,,2\n"
          "*CONTROL_TERMINATION+\n"
          "                 1.0\n"
          "*END\n");
    edit::FormatOptions to_fixed;
    to_fixed.to_fixed = true;
    out = format_text(deck, to_fixed);
    CHECK(out.find("\n       1.0                   2\n") != std::string::npos);
}

TEST_CASE("format --headers: one `$#` line above each card, rewritten in place when there is one") {
    const std::string deck =
        "*KEYWORD\n"
        "*CONTROL_TERMINATION\n"
        "$# old header\n"
        "1.0\n"
        "*SECTION_SPH\n"
        "         1       1.2\n"
        "*END\n";
    edit::FormatOptions headers;
    headers.headers = true;
    const std::string out = format_text(deck, headers);
    CHECK(out.find("$#  endtim    endcyc     dtmin    endeng    endmas     nosol\n       1.0\n") != std::string::npos);
    CHECK(out.find("$# old header") == std::string::npos);
    CHECK(out.find("*SECTION_SPH\n$#   secid") != std::string::npos);
    CHECK(format_text(out, headers) == out);  // idempotent with headers too
}

TEST_CASE("format: CRLF line ends, titles and *INCLUDE names kept") {
    const std::string deck =
        "*KEYWORD\r\n"
        "*TITLE\r\n"
        "  my   title   \r\n"
        "*CONTROL_TERMINATION\r\n"
        "1.0\r\n"
        "*END\r\n";
    const std::string out = format_text(deck);
    CHECK(out == "*KEYWORD\r\n*TITLE\r\n  my   title   \r\n*CONTROL_TERMINATION\r\n       1.0\r\n*END\r\n");
}

TEST_CASE("format: OpenRadioss cards in the starter's cells, headers, titles and comments kept") {
    const std::string deck =
        "#RADIOSS STARTER\n"
        "/BEGIN\n"
        "run\n"
        "      2026         0\n"
        "                  kg                  mm                  ms\n"
        "                  kg                  mm                  ms\n"
        "/NODE\n"
        "#  node_ID                  Xc\n"
        "1         0.5                 1.0       \n"
        "         2                 0.5                 1.0\n"
        "/END\n";
    const engine::CheckResult r = engine::check_buffer(deck, "run_0000.rad", {}, grammar::DeckFormat::Radioss);
    const edit::FormatResult formatted = edit::format_deck(r.deck, r.diagnostics, {0}, {});
    const std::string out = text::apply_edits(deck, formatted.edits).text;
    CHECK(out.find("#  node_ID                  Xc\n         1                 0.5                 1.0\n         2") !=
          std::string::npos);
    CHECK(out.substr(0, 60) == deck.substr(0, 60));  // /BEGIN's cards: text cells and the version as written
    const engine::CheckResult again = engine::check_buffer(out, "run_0000.rad", {}, grammar::DeckFormat::Radioss);
    CHECK(edit::format_deck(again.deck, again.diagnostics, {0}, {}).edits.empty());
}

TEST_CASE("format: *ELEMENT_SPH NEND ends in column 40, where every reader takes it (DK023)") {
    const std::string deck =
        "*KEYWORD\n"
        "*ELEMENT_SPH\n"
        "101     1       2.7e-06         102\n"
        "     103       1         2.7e-06       110\n"  // columns 41-42 (DK023): as written
        "*END\n";
    edit::FormatResult result;
    const std::string out = format_text(deck, {}, &result);
    CHECK(out.find("\n     101       1         2.7e-06     102\n") != std::string::npos);
    CHECK(out.find("\n     103       1         2.7e-06       110\n") != std::string::npos);
    CHECK(result.kept == 1);
}
}  // namespace test_format_cpp
