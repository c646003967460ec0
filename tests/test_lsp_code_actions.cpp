// The editor's code actions built from the findings' fixes (issue 27 item 4): the same diag::Fix data
// `check --fix` applies, no action offered twice, and the file's safe fixes in one source.fixAll action.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "lsp/diagnostics.hpp"
#include "lsp/features.hpp"

namespace test_lsp_code_actions_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

lsp::CheckedDeck check(const std::string& text) {
    lsp::CheckedDeck deck;
    deck.main = "main.k";
    deck.result = engine::check_buffer(text, "main.k", {}, grammar::DeckFormat::LsDyna);
    return deck;
}

std::vector<nlohmann::json> published(const lsp::CheckedDeck& deck) {
    std::vector<nlohmann::json> out;
    for (const auto& d : deck.result.diagnostics)
        out.push_back({{"range", lsp::range_json(deck.result.deck.sources, d.span)},
                       {"code", d.code},
                       {"source", "sphdeck"},
                       {"message", d.message}});
    return out;
}

nlohmann::json actions(const lsp::CheckedDeck& deck, nlohmann::json diagnostics, nlohmann::json only = nullptr) {
    nlohmann::json context = {{"diagnostics", std::move(diagnostics)}};
    if (!only.is_null()) context["only"] = std::move(only);
    auto answer = lsp::answer_feature("textDocument/codeAction", deck, 0,
                                      {{"textDocument", {{"uri", "file:///tmp/main.k"}}}, {"context", context}});
    REQUIRE(answer.handled);
    return answer.result;
}

std::vector<std::string> titles(const nlohmann::json& list) {
    std::vector<std::string> out;
    for (const auto& a : list) out.push_back(a["title"].get<std::string>());
    return out;
}

// "1.0e-3" across DTMIN and ENDENG: two DK003 on one line, both carrying the same realigned line.
const std::string kDeck = "*KEYWORD\n*CONTROL_TERMINATION\n     0.002       100     1.0e-3  0.5\n*END\n";

}  // namespace

TEST_CASE("lsp code actions: findings sharing a fix and a card get each action once") {
    const auto deck = check(kDeck);
    const auto diagnostics = published(deck);
    REQUIRE(diagnostics.size() == 2);
    // Each finding listed twice too, as a client may send overlapping ranges.
    const nlohmann::json all = {diagnostics[0], diagnostics[1], diagnostics[0]};
    const auto list = actions(deck, all);
    CHECK(titles(list) == std::vector<std::string>{"Move the values of the line into their fields",
                                                   "Suppress DK003 for this card", "Suppress DK003 in this file"});
    CHECK(list[0]["isPreferred"] == true);
    CHECK(list[0]["diagnostics"].size() == 2);  // the action mends both findings
    const auto& edit = list[0]["edit"]["changes"]["file:///tmp/main.k"][0];
    CHECK(edit["newText"] == "     0.002       100    1.0e-3   0.5");
    CHECK(edit["range"]["start"]["line"] == 2);
}

TEST_CASE("lsp code actions: the fix is the finding's diag::Fix, the one check --fix applies") {
    const auto deck = check(kDeck);
    const diag::Fix& fix = deck.result.diagnostics[0].fixes.at(0);
    // json::array, not braces: `{j}` of one json is a copy of j under clang and an array of one under gcc.
    const auto list = actions(deck, nlohmann::json::array({published(deck)[0]}));
    REQUIRE(!list.empty());
    CHECK(list[0]["title"] == "Move the values of the line into their fields");
    CHECK(fix.description == "move the values of the line into their fields");
    CHECK(list[0]["edit"]["changes"]["file:///tmp/main.k"][0]["newText"] == fix.edits[0].replacement);
}

TEST_CASE("lsp code actions: source.fixAll applies every safe fix of the file, only when asked") {
    const std::string text = "*KEYWORD\n*control_termination\n     0.002       100     1.0e-3  0.5\n  *END\n";
    const auto deck = check(text);
    auto list = actions(deck, nlohmann::json::array(), {"source.fixAll"});
    REQUIRE(list.size() == 1);
    CHECK(list[0]["kind"] == "source.fixAll.sphdeck");
    CHECK(list[0]["title"] == "Apply the safe fixes of sphdeck (4)");  // DK021, two DK003, DK020
    CHECK(list[0]["edit"]["changes"]["file:///tmp/main.k"].size() == 3);
    // Not among the quick fixes of a plain request.
    list = actions(deck, nlohmann::json::array());
    CHECK(list.empty());
}
}  // namespace test_lsp_code_actions_cpp
