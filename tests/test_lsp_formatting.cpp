// textDocument/formatting and rangeFormatting (lsp/feature_formatting.cpp): the edits of `sphdeck format`
// as LSP TextEdits, for the whole file or the lines of a range; the capability announced.
#include <doctest/doctest.h>

#include <string>

#include "engine/check.hpp"
#include "lsp/features.hpp"

namespace test_lsp_formatting_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

const std::string kDeck =
    "*keyword\n"
    "*CONTROL_TERMINATION\n"
    "1.0\n"
    "*SECTION_SPH\n"
    "1         1.2\n"
    "*END\n";

lsp::CheckedDeck check(const std::string& text) {
    lsp::CheckedDeck deck;
    deck.main = "main.k";
    deck.result = engine::check_buffer(text, "main.k");
    return deck;
}

nlohmann::json ask(const lsp::CheckedDeck& deck, std::string_view method, nlohmann::json params) {
    auto answer = lsp::answer_feature(method, deck, 0, params);
    REQUIRE(answer.handled);
    return answer.result;
}

nlohmann::json range(std::uint32_t first, std::uint32_t last) {
    return {{"start", {{"line", first}, {"character", 0}}}, {"end", {{"line", last}, {"character", 3}}}};
}

}  // namespace

TEST_CASE("lsp formatting: the edits of sphdeck format, whole lines, for the file") {
    const auto deck = check(kDeck);
    const auto edits = ask(deck, "textDocument/formatting", {{"options", {{"tabSize", 4}, {"insertSpaces", true}}}});
    REQUIRE(edits.is_array());
    REQUIRE(edits.size() == 3);
    CHECK(edits[0]["newText"] == "*KEYWORD");
    CHECK(edits[0]["range"] ==
          nlohmann::json::parse(R"({"start":{"line":0,"character":0},"end":{"line":0,"character":8}})"));
    CHECK(edits[1]["newText"] == "       1.0");
    CHECK(edits[1]["range"]["start"]["line"] == 2);
    CHECK(edits[2]["newText"] == "         1       1.2");
    // A formatted deck: nothing to do.
    CHECK(ask(check("*KEYWORD\n*CONTROL_TERMINATION\n       1.0\n*END\n"), "textDocument/formatting", {}).empty());
}

TEST_CASE("lsp range formatting: only the lines of the range") {
    const auto deck = check(kDeck);
    auto edits = ask(deck, "textDocument/rangeFormatting", {{"range", range(1, 2)}});
    REQUIRE(edits.size() == 1);
    CHECK(edits[0]["range"]["start"]["line"] == 2);
    // A range ending at the start of a line does not take it.
    edits = ask(deck, "textDocument/rangeFormatting",
                {{"range", {{"start", {{"line", 3}, {"character", 0}}}, {"end", {{"line", 4}, {"character", 0}}}}}});
    CHECK(edits.empty());
    CHECK(ask(deck, "textDocument/rangeFormatting", {{"range", "x"}}).empty());
}

TEST_CASE("lsp formatting: capabilities announced") {
    const auto capabilities = lsp::feature_capabilities();
    CHECK(capabilities["documentFormattingProvider"] == true);
    CHECK(capabilities["documentRangeFormattingProvider"] == true);
}
}  // namespace test_lsp_formatting_cpp
