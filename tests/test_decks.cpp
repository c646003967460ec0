// The deck-driven runner (design.md, "Tests"): every deck under decks/tests/ states the
// diagnostics it expects with `$ expect: CODE[, CODE...]` on the comment line(s) right before
// the line that must trigger them; `$ expect-deck: CODE` expects one without a location. The
// set of (file, line, code) found must equal the set expected: an undeclared finding fails.
// Included files (*.inc, or anything under a folder named `include`) are not run on their own.
#include <doctest/doctest.h>

#include <filesystem>
#include <set>
#include <tuple>

#include "lint/pipeline.hpp"

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
        std::vector<std::string_view> pending;
        for (std::uint32_t n = 1, last = sources.line_count(f); n <= last; ++n) {
            std::string_view text = sources.line_text(f, n);
            static constexpr std::string_view expect = "$ expect:", expect_deck = "$ expect-deck:";
            if (text.rfind(expect, 0) == 0) {
                pending.push_back(text.substr(expect.size()));
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

std::multiset<Expectation> found(const lint::CheckResult& r) {
    std::multiset<Expectation> out;
    for (const auto& d : r.diagnostics) {
        if (d.span.valid()) out.insert({r.deck.sources.file(d.span.file).display_name, d.span.line, d.code});
        else out.insert({"", 0, d.code});
    }
    return out;
}

std::string describe(const std::multiset<Expectation>& set) {
    std::string s;
    for (const auto& [file, line, code] : set) s += "  " + file + ":" + std::to_string(line) + " " + code + "\n";
    return s.empty() ? "  (none)\n" : s;
}

bool is_main_deck(const fs::path& p) {
    if (p.extension() != ".k") return false;
    for (const auto& part : p) if (part == "include") return false;
    return true;
}

}  // namespace

TEST_CASE("decks: every test deck produces exactly the diagnostics it declares") {
    fs::path root = fs::path(SPHDECK_SOURCE_DIR) / "decks" / "tests";
    REQUIRE(fs::is_directory(root));
    std::vector<fs::path> decks;
    for (const auto& e : fs::recursive_directory_iterator(root))
        if (e.is_regular_file() && is_main_deck(e.path())) decks.push_back(e.path());
    std::sort(decks.begin(), decks.end());
    CHECK(decks.size() >= 10);
    for (const auto& deck : decks) {
        CAPTURE(deck.string());
        lint::CheckResult r = lint::check_file(deck.string());
        auto expected = expectations(r.deck.sources);
        auto actual = found(r);
        std::multiset<Expectation> missing, unexpected;
        std::set_difference(expected.begin(), expected.end(), actual.begin(), actual.end(),
                            std::inserter(missing, missing.end()));
        std::set_difference(actual.begin(), actual.end(), expected.begin(), expected.end(),
                            std::inserter(unexpected, unexpected.end()));
        INFO("expected but not found:\n" << describe(missing) << "found but not declared:\n" << describe(unexpected));
        CHECK((missing.empty() && unexpected.empty()));
    }
}
