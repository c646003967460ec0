// The deck-driven runner (design.md, "Tests"): every deck under decks/tests/ and decks/demo/ states the
// diagnostics it expects with `$ expect: CODE[, CODE...]` on the comment line(s) right before
// the line that must trigger them; `$ expect-above: CODE` expects one on the line just above (a
// suppression comment); `$ expect-deck: CODE` expects one without a location. The
// set of (file, line, code) found must equal the set expected: an undeclared finding fails.
// Included files (*.inc, or anything under a folder named `include`) are not run on their own.
// Radioss decks (*.rad) may write the same lines with '#' instead of '$'; their engine decks
// (<run>_0001.rad) are checked with the starter deck <run>_0000.rad that reads them.
// A rule's decks (tests/rule_decks.hpp) also show their rule: a *fires* deck declares it, a *silent* one not.
// SPHDECK_DECKS picks the decks of one run: a rule code (ctest's rule-SPH030: SPHDECK_DECKS=SPH030), `none`
// (the decks named after no rule, with the unit tests in ctest), or, unset, every deck.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <tuple>

#include "engine/check.hpp"
#include "lint/registry.hpp"
#include "rule_decks.hpp"

namespace test_decks_cpp {  // each test file's names stay its own in a unity batch

namespace fs = std::filesystem;
using namespace sphdeck;

namespace {

using Expectation = std::tuple<std::string, std::uint32_t, std::string>;  // file, line, code

void add_codes(std::string_view list, const std::string& file, std::uint32_t line, std::multiset<Expectation>& out) {
    std::string code;
    for (char c : std::string(list) + ",") {
        if (c == ',' || c == ' ') {
            if (!code.empty()) out.insert({file, line, code});
            code.clear();
        } else if (c != '\r') {
            code += c;
        }
    }
}

// Reads the expectations of every file the deck opened.
std::multiset<Expectation> expectations(const grammar::SourceMap& sources) {
    std::multiset<Expectation> out;
    for (grammar::FileId f = 0; f < sources.size(); ++f) {
        const auto& file = sources.file(f);
        // Radioss decks (main file *.rad) also write `# expect: CODE`; '#' lines are comments there.
        const std::string& root = sources.file(sources.include_chain(f).front()).display_name;
        const bool radioss = root.size() > 4 && root.substr(root.size() - 4) == ".rad";
        std::vector<std::string> pending;  // copies: a '#' line is rewritten into a temporary
        std::string hash_comment;
        for (std::uint32_t n = 1, last = sources.line_count(f); n <= last; ++n) {
            std::string_view text = sources.line_text(f, n);
            if (radioss && text.rfind('#', 0) == 0 && text.rfind("#include", 0) != 0 && text.rfind("#enddata", 0) != 0)
                text = hash_comment = "$" + std::string(text.substr(1));
            static constexpr std::string_view expect = "$ expect:", expect_deck = "$ expect-deck:",
                                              expect_above = "$ expect-above:";
            if (text.rfind(expect_above, 0) == 0) {
                add_codes(text.substr(expect_above.size()), file.display_name, n - 1, out);  // e.g. on a comment
            } else if (text.rfind(expect, 0) == 0) {
                pending.emplace_back(text.substr(expect.size()));
            } else if (text.rfind(expect_deck, 0) == 0) {
                add_codes(text.substr(expect_deck.size()), "", 0, out);
            } else if (!text.empty() && text[0] == '$') {
                continue;  // other comments keep pending expectations for the next line
            } else {
                for (auto codes : pending) add_codes(codes, file.display_name, n, out);
                pending.clear();
            }
        }
    }
    return out;
}

std::multiset<Expectation> found(const engine::CheckResult& r) {
    std::multiset<Expectation> out;
    for (const auto& d : r.diagnostics) {
        if (d.span.valid())
            out.insert({r.deck.sources.file(d.span.file).display_name, d.span.line, d.code});
        else
            out.insert({"", 0, d.code});
    }
    return out;
}

std::string describe(const std::multiset<Expectation>& set) {
    std::string s;
    for (const auto& [file, line, code] : set) s += "  " + file + ":" + std::to_string(line) + " " + code + "\n";
    return s.empty() ? "  (none)\n" : s;
}

// The decks SPHDECK_DECKS asks for (every one when unset).
std::vector<fs::path> selected_decks() {
    const char* env = std::getenv("SPHDECK_DECKS");
    const std::string selection = env ? env : "";
    std::vector<fs::path> decks = test::all_test_decks();
    if (selection.empty()) return decks;
    std::erase_if(decks, [&](const fs::path& deck) {
        const std::string rule = test::rule_of_deck(deck);
        return selection == "none" ? !rule.empty() : rule != selection;
    });
    return decks;
}

}  // namespace

TEST_CASE("decks: every test deck produces exactly the diagnostics it declares") {
    const std::vector<fs::path> decks = selected_decks();
    const char* env = std::getenv("SPHDECK_DECKS");
    const std::string selection = env ? env : "";
    INFO("SPHDECK_DECKS=" << selection);
    CHECK(decks.size() >= (selection.empty() ? 10 : 1));
    for (const auto& deck : decks) {
        CAPTURE(deck.string());
        engine::CheckResult r = engine::check_file(deck.string());
        auto expected = expectations(r.deck.sources);
        auto actual = found(r);
        std::multiset<Expectation> missing, unexpected;
        std::set_difference(expected.begin(), expected.end(), actual.begin(), actual.end(),
                            std::inserter(missing, missing.end()));
        std::set_difference(actual.begin(), actual.end(), expected.begin(), expected.end(),
                            std::inserter(unexpected, unexpected.end()));
        INFO("expected but not found:\n" << describe(missing) << "found but not declared:\n" << describe(unexpected));
        CHECK((missing.empty() && unexpected.empty()));
        // A deck named after a rule shows that rule: reported (on the lines it declares) or not at all.
        const std::string rule = test::rule_of_deck(deck);
        if (rule.empty()) continue;
        CHECK_MESSAGE(lint::find_rule(rule) != nullptr, "no registry row for " << rule);
        const bool declares_rule =
            std::any_of(expected.begin(), expected.end(), [&](const Expectation& e) { return std::get<2>(e) == rule; });
        if (test::kind_of_deck(deck) == test::DeckKind::Fires)
            CHECK_MESSAGE(declares_rule, "a firing deck must report " << rule);
        if (test::kind_of_deck(deck) == test::DeckKind::Silent && !test::reports_its_rule_lower(deck))
            CHECK_MESSAGE(!declares_rule, "a silent deck must not report " << rule);
    }
}
}  // namespace test_decks_cpp
