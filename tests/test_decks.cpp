// The deck-driven runner (design.md, "Tests"): every deck under decks/tests/ and decks/demo/ states the
// diagnostics it expects with `$ expect: CODE[, CODE...]` on the comment line(s) right before
// the line that must trigger them; `$ expect-above: CODE` expects one on the line just above (a
// suppression comment); `$ expect-deck: CODE` expects one without a location. The
// set of (file, line, code) found must equal the set expected: an undeclared finding fails.
// Included files (*.inc, or anything under a folder named `include`) are not run on their own.
// Radioss decks (*.rad) may write the same lines with '#' instead of '$'; their engine decks
// (<run>_0001.rad) are checked with the starter deck <run>_0000.rad that reads them.
#include <doctest/doctest.h>

#include <filesystem>
#include <set>
#include <tuple>

#include "grammar/radioss/reader.hpp"
#include "engine/check.hpp"

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
    // Radioss engine decks (<run>_0001.rad) are read with their starter deck.
    const bool engine = grammar::radioss::is_engine_file_name(p.filename().string());
    if (p.extension() != ".k" && (p.extension() != ".rad" || engine)) return false;
    for (const auto& part : p) if (part == "include") return false;
    return true;
}

}  // namespace

TEST_CASE("decks: every test deck produces exactly the diagnostics it declares") {
    // decks/demo too: the demo's mistakes deck declares what `make demo` shows, the dam break none.
    std::vector<fs::path> decks;
    for (const char* folder : {"tests", "demo"}) {
        fs::path root = fs::path(SPHDECK_SOURCE_DIR) / "decks" / folder;
        REQUIRE(fs::is_directory(root));
        for (const auto& e : fs::recursive_directory_iterator(root))
            if (e.is_regular_file() && is_main_deck(e.path())) decks.push_back(e.path());
    }
    std::sort(decks.begin(), decks.end());
    CHECK(decks.size() >= 10);
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
    }
}
