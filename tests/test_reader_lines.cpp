// Format rules for lines and keywords (lsdyna-format.md §1, §2, §8, §9, §11, §15).
#include <doctest/doctest.h>
#include <tao/pegtl/contrib/analyze.hpp>

#include "grammar/dyna/line_grammar.hpp"
#include "grammar/dyna/reader.hpp"
#include "test_support.hpp"

namespace test_reader_lines_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using grammar::dyna::read_buffer;
using test::count_code;

TEST_CASE("reader: the line grammar has no infinite loops") {
    CHECK(tao::pegtl::analyze<grammar::dyna::rules::file>(-1) == 0);
}

TEST_CASE("reader: comment, keyword and data lines") {
    auto deck =
        read_buffer("$ a comment\n*KEYWORD\n*NODE\n$# nid x\n       1     0.0\n       2     1.0\n*END\n", "d.k");
    REQUIRE(deck.blocks.size() == 3);
    CHECK(deck.blocks[0].keyword == "*KEYWORD");
    CHECK(deck.blocks[1].keyword == "*NODE");
    CHECK(deck.blocks[1].line_count == 2);  // comment lines between cards are not cards
    const auto& first = deck.lines[deck.blocks[1].first_line];
    CHECK(first.line == 5);
    CHECK(deck.text(first) == "       1     0.0");
    CHECK(deck.blocks[1].span.line == 3);
    CHECK(deck.blocks[1].span.column == 1);
    CHECK(deck.blocks[1].span.end_column == 6);
    CHECK(deck.stats.keywords == 3);
    CHECK(deck.stats.cards == 2);
}

TEST_CASE("reader: CRLF, a UTF-8 BOM and trailing blanks are accepted") {
    auto deck = read_buffer("\xEF\xBB\xBF*KEYWORD\r\n*NODE   \r\n       1     0.0   \r\n", "d.k");
    REQUIRE(deck.blocks.size() == 2);
    CHECK(deck.blocks[0].keyword == "*KEYWORD");
    CHECK(deck.blocks[1].keyword == "*NODE");
    CHECK(deck.text(deck.lines[0]) == "       1     0.0   ");
    CHECK(deck.diagnostics.empty());
}

TEST_CASE("reader: no final newline") {
    auto deck = read_buffer("*NODE\n       1", "d.k");
    REQUIRE(deck.lines.size() == 1);
    CHECK(deck.text(deck.lines[0]) == "       1");
}

TEST_CASE("reader: keyword text after the name is ignored, format suffixes are read glued or spaced") {
    auto deck = read_buffer("*ELEMENT_SOLID (ten nodes format)\n*NODE +\n*NODE%\n*SECTION_SEATBELT-\n*NODE\n", "d.k");
    REQUIRE(deck.blocks.size() == 5);
    CHECK(deck.blocks[0].keyword == "*ELEMENT_SOLID");
    CHECK(deck.blocks[0].arguments == "(ten nodes format)");
    CHECK(deck.blocks[1].format == grammar::CardFormat::Long);
    CHECK(deck.blocks[2].format == grammar::CardFormat::I10);
    CHECK(deck.blocks[3].keyword == "*SECTION_SEATBELT");
    CHECK(deck.blocks[3].suffix == '-');
    CHECK(deck.blocks[4].format == grammar::CardFormat::Standard);
}

TEST_CASE("reader: *KEYWORD long=y and i10=y set the file's format; memory arguments are kept") {
    auto deck = read_buffer("*KEYWORD 100m memory2=20m LONG=Y ncpu=4\n*NODE\n*NODE -\n", "d.k");
    CHECK(deck.keyword_arguments.present);
    CHECK(deck.keyword_arguments.memory == "100m");
    CHECK(deck.keyword_arguments.memory2 == "20m");
    CHECK(deck.keyword_arguments.ncpu == 4);
    CHECK(deck.blocks[1].format == grammar::CardFormat::Long);
    CHECK(deck.blocks[2].format == grammar::CardFormat::Standard);
    auto i10 = read_buffer("*KEYWORD i10=y\n*NODE\n", "d.k");
    CHECK(i10.blocks[1].format == grammar::CardFormat::I10);
    auto s = read_buffer("*keyword long=s\n*NODE\n", "d.k");
    CHECK(s.blocks[1].format == grammar::CardFormat::Standard);
}

TEST_CASE("reader: lower-case keywords and blanks before '*' are accepted and reported") {
    auto deck = read_buffer("*keyword\n  *NODE\n", "d.k");
    CHECK(deck.blocks[0].keyword == "*KEYWORD");
    CHECK(deck.blocks[1].keyword == "*NODE");
    CHECK(count_code(deck.diagnostics, "DK021") == 1);
    CHECK(count_code(deck.diagnostics, "DK020") == 1);
    CHECK(deck.blocks[1].span.column == 3);
}

TEST_CASE("reader: *COMMENT lines are not cards") {
    auto deck = read_buffer("*COMMENT anything\nfree text, 1, 2\n*NODE with more\n*NODE\n       1\n", "d.k");
    REQUIRE(deck.blocks.size() == 3);
    CHECK(deck.blocks[0].line_count == 0);
    CHECK(deck.blocks[1].keyword == "*NODE");
    CHECK(deck.blocks[2].line_count == 1);
}

TEST_CASE("reader: *END stops the file; later content is reported once") {
    auto deck = read_buffer("*NODE\n       1\n*END\n$ fine\n\n*NODE\n       2\n", "d.k");
    CHECK(deck.blocks.size() == 2);
    CHECK(deck.lines.size() == 1);
    REQUIRE(count_code(deck.diagnostics, "DK017") == 1);
    CHECK(deck.diagnostics[0].span.line == 3);  // a keyword block dropped: a warning at *END
    CHECK(deck.diagnostics[0].severity == diag::Severity::Warning);
    auto text = read_buffer("*NODE\n       1\n*END\n$ fine\n\nnotes\n", "d.k");
    REQUIRE(count_code(text.diagnostics, "DK017") == 1);
    CHECK(text.diagnostics[0].span.line == 6);  // text only: information at its first line
    CHECK(text.diagnostics[0].severity == diag::Severity::Info);
}

TEST_CASE("reader: encrypted blocks are skipped with a note") {
    auto deck =
        read_buffer("*NODE\n-----BEGIN PGP MESSAGE-----\n*NOT_A_KEYWORD\nxyz\n-----END PGP MESSAGE-----\n       1\n",
                    "d.k");
    CHECK(deck.blocks.size() == 1);
    CHECK(deck.lines.size() == 1);
    CHECK(deck.lines[0].line == 6);
    CHECK(count_code(deck.diagnostics, "DK022") == 1);
}

TEST_CASE("reader: data before any keyword is reported once") {
    auto deck = read_buffer("junk\nmore junk\n*KEYWORD\n", "d.k");
    CHECK(count_code(deck.diagnostics, "DK027") == 1);
}

TEST_CASE("reader: blank lines inside a keyword are cards") {
    auto deck = read_buffer("*CONTROL_SPH\n\n\n", "d.k");
    CHECK(deck.blocks[0].line_count == 2);
}

TEST_CASE("reader: bad input never crashes") {
    SUBCASE("empty") {
        auto deck = read_buffer("", "d.k");
        CHECK(deck.blocks.empty());
    }
    SUBCASE("binary garbage and NUL bytes") {
        std::string junk;
        for (int i = 0; i < 100000; ++i) junk.push_back(static_cast<char>((i * 7919) % 256));
        junk += std::string("\0\0*NODE\n\0\0\0\n", 12);
        auto deck = read_buffer(junk, "d.k");
        CHECK(deck.stats.bytes == junk.size());
    }
    SUBCASE("a 100 MB line") {
        std::string text = "*NODE\n" + std::string(100u << 20, '1') + "\n*END\n";
        auto deck = read_buffer(std::move(text), "d.k");
        REQUIRE(deck.lines.size() == 1);
        CHECK(deck.length(deck.lines[0]) == (100u << 20));
    }
    SUBCASE("only newlines and carriage returns") {
        auto deck = read_buffer(std::string(1000, '\n') + std::string(1000, '\r'), "d.k");
        CHECK(deck.blocks.empty());
    }
}

TEST_CASE("reader: an indented '*' line inside *COMMENT or an expression continuation is data") {
    auto comment = read_buffer("*COMMENT\nLoad cases:\n  * bird 1.8 kg\n*NODE\n", "d.k");
    REQUIRE(comment.blocks.size() == 2);
    CHECK(count_code(comment.diagnostics, "DK020") == 0);
    auto expression = read_buffer("*PARAMETER_EXPRESSION\nR h0      8.0\n          **(1.0/3.0)\n", "d.k");
    REQUIRE(expression.blocks.size() == 1);
    const auto* h0 = expression.parameters.find("h0", 0, expression.parameters.epoch()).parameter;
    REQUIRE(h0);
    CHECK(h0->number == doctest::Approx(2.0));
    auto bare = read_buffer("*\n", "d.k");
    CHECK(count_code(bare.diagnostics, "DK001") == 1);
}

TEST_CASE("reader: '-' and '/' between letters or digits belong to the keyword name") {
    auto deck = read_buffer(
        "*CONSTRAINED_TIE-BREAK\n*MAT_SAMP-1 +\n*MAT_SIMPLIFIED_RUBBER/FOAM\n"
        "*ALE_MULTI-MATERIAL_GROUP-\n*NODE-\n*NODE -\n*PART-  hint\n*DEFINE_CURVE/\n",
        "d.k");
    REQUIRE(deck.blocks.size() == 8);
    CHECK(deck.blocks[0].keyword == "*CONSTRAINED_TIE-BREAK");
    CHECK(deck.blocks[0].suffix == 0);
    CHECK(deck.blocks[1].keyword == "*MAT_SAMP-1");
    CHECK(deck.blocks[1].format == grammar::CardFormat::Long);
    CHECK(deck.blocks[2].keyword == "*MAT_SIMPLIFIED_RUBBER/FOAM");
    CHECK(deck.blocks[3].keyword == "*ALE_MULTI-MATERIAL_GROUP");  // a final '-' is still the suffix
    CHECK(deck.blocks[3].suffix == '-');
    for (std::size_t i : {4, 5, 6}) {
        CHECK(deck.blocks[i].keyword.find('-') == std::string::npos);
        CHECK(deck.blocks[i].suffix == '-');
    }
    CHECK(deck.blocks[6].arguments == "hint");
    CHECK(deck.blocks[7].keyword == "*DEFINE_CURVE");  // a '/' not followed by a name character ends it
    CHECK(deck.blocks[7].arguments == "/");
}
}  // namespace test_reader_lines_cpp
