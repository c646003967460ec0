// The engine's position index (engine/position_index.hpp): the card and field at a line and column
// of LS-DYNA lines in fixed, long, I10 and free format, of a line the last check did not read as a
// card, of Radioss lines, and the decoded card lines of a range (a big bulk block decoded only there).
#include <doctest/doctest.h>

#include <algorithm>
#include <fmt/format.h>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "engine/position_index.hpp"
#include "lsp_radioss_deck.hpp"

namespace test_position_index_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

engine::CheckResult check_dyna(const std::string& text) { return engine::check_buffer(text, "main.k"); }

// The 1-based line of the first line holding `needle`.
std::uint32_t line_with(std::string_view text, std::string_view needle) {
    const auto at = text.find(needle);
    REQUIRE(at != std::string_view::npos);
    return static_cast<std::uint32_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) +
           1;
}

// The card at a line of file 0, whose block must exist.
std::optional<engine::CardAt> card_on(const engine::CheckResult& deck, std::uint32_t line, bool radioss = false) {
    const grammar::Block* block = engine::block_at(deck.deck, 0, line);
    REQUIRE(block != nullptr);
    return engine::card_at(deck.deck, *block, line, radioss);
}

std::string field_name(const engine::CardAt& at, std::size_t index) {
    return std::string(at.dyna_card->fields.at(index).name);
}

}  // namespace

TEST_CASE("position index: the fields of a fixed-format *NODE line, blanks and columns included") {
    const std::string text = "*KEYWORD\n*NODE\n       7             1.5             2.5             3.5\n*END\n";
    const auto deck = check_dyna(text);
    const auto at = card_on(deck, 3);
    REQUIRE(at);
    REQUIRE(at->dyna);
    CHECK(at->line != nullptr);
    CHECK(at->dyna_card == at->dyna->card);
    CHECK(field_name(*at, *at->field_under(1)) == "NID");  // the blank part of a right-aligned value
    CHECK(field_name(*at, *at->field_under(8)) == "NID");
    CHECK(field_name(*at, *at->field_under(9)) == "X");
    CHECK(field_name(*at, *at->field_under(45)) == "Z");
    const auto x = engine::dyna_field_columns(*at->dyna_card, grammar::CardFormat::Standard, 1);
    REQUIRE(x);
    CHECK(x->first == 9);
    CHECK(x->end == 25);
    CHECK(at->dyna->values[0].number == 7.0);
    // Not the keyword line, nor a line before the block.
    CHECK_FALSE(engine::card_at(deck.deck, *engine::block_at(deck.deck, 0, 2), 2, false));
}

TEST_CASE("position index: I10 and long format widen the fields") {
    SUBCASE("I10 (*NODE %): NID in columns 1-10, X in 11-26") {
        const std::string text = "*KEYWORD\n*NODE %\n        12             1.5             2.5             3.5\n";
        const auto deck = check_dyna(text);
        const auto at = card_on(deck, 3);
        REQUIRE(at);
        REQUIRE(at->dyna);
        CHECK(field_name(*at, *at->field_under(10)) == "NID");
        CHECK(field_name(*at, *at->field_under(11)) == "X");
        const auto x = engine::dyna_field_columns(*at->dyna_card, grammar::CardFormat::I10, 1);
        REQUIRE(x);
        CHECK(x->first == 11);
        CHECK(x->end == 27);
        CHECK(at->dyna->values[0].number == 12.0);
    }
    SUBCASE("long (*NODE +): 20 columns a field") {
        const std::string text = fmt::format("*KEYWORD\n*NODE +\n{:>20}{:>20}{:>20}{:>20}\n", 5, "1.5", "2.5", "3.5");
        const auto deck = check_dyna(text);
        const auto at = card_on(deck, 3);
        REQUIRE(at);
        REQUIRE(at->dyna);
        CHECK(field_name(*at, *at->field_under(20)) == "NID");
        CHECK(field_name(*at, *at->field_under(21)) == "X");
        CHECK(field_name(*at, *at->field_under(61)) == "Z");
        const auto z = engine::dyna_field_columns(*at->dyna_card, grammar::CardFormat::Long, 3);
        REQUIRE(z);
        CHECK(z->first == 61);
        CHECK(z->end == 81);
        CHECK(at->dyna->values[3].number == 3.5);
    }
}

TEST_CASE("position index: a free-format line answers between its commas") {
    const std::string text = "*KEYWORD\n*NODE\n3,1.5,2.5,3.5\n";
    const auto deck = check_dyna(text);
    const auto at = card_on(deck, 3);
    REQUIRE(at);
    REQUIRE(at->dyna);
    CHECK(field_name(*at, *at->field_under(1)) == "NID");
    CHECK(field_name(*at, *at->field_under(4)) == "X");  // on "1.5"
    CHECK(field_name(*at, *at->field_under(8)) == "Y");  // on "2.5"
    CHECK(*at->typed_slot(11) == 3);                     // after the third comma
    // Columns are no answer for a free-format line's default.
    CHECK_FALSE(engine::blank_field_start(*at->dyna, grammar::CardFormat::Standard, at->text, 4));
}

TEST_CASE("position index: a blank field's default, where it is read and what the solver takes") {
    const std::string text = "*KEYWORD\n*SECTION_SPH\n         3                 0.2       2.0\n*END\n";
    const auto deck = check_dyna(text);
    const auto at = card_on(deck, 3);
    REQUIRE(at);
    REQUIRE(at->dyna);
    const auto cslh = at->field_under(15);  // inside the blank CSLH slot
    REQUIRE(cslh);
    CHECK(field_name(*at, *cslh) == "CSLH");
    const model::FieldValue& v = at->dyna->values[*cslh];
    CHECK_FALSE(v.explicit_value);
    CHECK(engine::effective_value(v) == "1.2 (default: left blank)");
    CHECK(*engine::blank_field_start(*at->dyna, grammar::CardFormat::Standard, at->text, *cslh) == 11);
    CHECK(engine::effective_value(at->dyna->values[2]) == "0.2");  // HMIN as written
    // A field past the line's end reads no default in the line.
    CHECK_FALSE(engine::blank_field_start(*at->dyna, grammar::CardFormat::Standard, at->text, 6));
    // The cursor: right after "0.2" or "3" it types that value's field; on a blank, the field under it.
    CHECK(field_name(*at, *at->field_at_cursor(31)) == "HMIN");
    CHECK(field_name(*at, *at->field_at_cursor(11)) == "SECID");
    CHECK(field_name(*at, *at->field_at_cursor(13)) == "CSLH");
}

TEST_CASE("position index: a line the last check did not read as a card takes the next card's layout") {
    // A comment line after the PART's heading: the card it would be read as is the PID card.
    const std::string text = "*KEYWORD\n*PART\nwater\n$ typed here\n         1         3\n*END\n";
    const auto deck = check_dyna(text);
    const auto at = card_on(deck, 4);
    REQUIRE(at);
    CHECK(at->line == nullptr);
    CHECK_FALSE(at->dyna);
    REQUIRE(at->dyna_card != nullptr);
    CHECK(at->dyna_card->fields.at(0).name == "PID");
    CHECK_FALSE(at->field_under(5));                         // nothing decoded there
    CHECK(field_name(*at, *at->typed_slot(12)) == "SECID");  // the slot of columns 11-20
    CHECK(field_name(*at, *at->field_at_cursor(12)) == "SECID");
    // The decoded PID card right after it.
    const auto pid = card_on(deck, 5);
    REQUIRE(pid);
    REQUIRE(pid->dyna);
    CHECK(field_name(*pid, *pid->field_under(15)) == "SECID");
}

TEST_CASE("position index: Radioss lines, title and cells") {
    const std::string text(test::lsp_radioss_deck);
    const auto deck = engine::check_buffer(text, "model_0000.rad", {}, grammar::DeckFormat::Radioss);
    REQUIRE(deck.model.radioss);
    const std::uint32_t title = line_with(text, "water particles");
    const auto at_title = card_on(deck, title, true);
    REQUIRE(at_title);
    REQUIRE(at_title->radioss);
    CHECK(at_title->radioss->title);
    const std::uint32_t prop = line_with(text, "              8.0E-6");
    const auto at = card_on(deck, prop, true);
    REQUIRE(at);
    REQUIRE(at->radioss);
    REQUIRE(at->radioss->card != nullptr);
    const auto mp = at->field_under(3);
    REQUIRE(mp);
    CHECK(at->radioss->values[*mp].spec->name == "mp");
    const auto qa = at->field_under(25);
    REQUIRE(qa);
    CHECK(at->radioss->values[*qa].spec->name == "qa");
    const auto cells = engine::radioss_field_columns(*at->radioss, at->text, *qa);
    REQUIRE(cells);
    CHECK(cells->first == 21);
    CHECK(cells->end == 41);
    const std::uint32_t part = line_with(text, "         2         3         0");
    const auto ids = card_on(deck, part, true);
    REQUIRE(ids);
    CHECK(ids->radioss->values[*ids->field_under(15)].spec->name == "mat_ID");
}

TEST_CASE("position index: the card lines of a range in a big *NODE block, decoded only there") {
    std::string text = "*KEYWORD\n*SECTION_SPH\n         1\n*NODE\n";
    for (int n = 1; n <= 800; ++n) text += fmt::format("{:>8}{:>16}{:>16}{:>16}\n", n, n * 0.5, 0.0, 0.0);
    text += "*END\n";
    const auto deck = check_dyna(text);
    const std::uint32_t first_node = 5;  // node 1
    std::vector<double> nids;
    engine::visit_card_lines(deck.deck, false, 0, {first_node + 400, first_node + 402}, {},
                             [&](const engine::DecodedLine& line) {
                                 REQUIRE(line.dyna);
                                 CHECK(line.line->line >= first_node + 400);
                                 nids.push_back(line.dyna->values[0].number);
                             });
    CHECK(nids == std::vector<double>{401, 402, 403});
    // A range over the section and the keyword of the nodes: the section's card, no node line.
    nids.clear();
    engine::visit_card_lines(deck.deck, false, 0, {1, 4}, {}, [&](const engine::DecodedLine& line) {
        nids.push_back(line.dyna->values[0].number);
        CHECK(line.dyna->card->fields[0].name == "SECID");
    });
    CHECK(nids == std::vector<double>{1});
    // Bulk blocks left out on request (inlay hints' default), and blocks over a size.
    const grammar::Block& nodes = *engine::block_at(deck.deck, 0, first_node);
    CHECK(engine::is_bulk_block(nodes, false));
    CHECK_FALSE(engine::is_bulk_block(*engine::block_at(deck.deck, 0, 3), false));
    int visited = 0;
    engine::visit_card_lines(deck.deck, false, 0, {first_node, first_node + 5}, {0, true},
                             [&](const engine::DecodedLine&) { ++visited; });
    engine::visit_card_lines(deck.deck, false, 0, {first_node, first_node + 5}, {100, false},
                             [&](const engine::DecodedLine&) { ++visited; });
    CHECK(visited == 0);
    CHECK(engine::blocks_in_range(deck.deck, 0, {3, 5}).size() == 2);
}
}  // namespace test_position_index_cpp
