// engine/deck_diff and `sphdeck diff`: what the solver reads differently, formatting aside (issue 33
// item 4).
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "engine/deck_diff.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_deck_diff_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

const std::string kDamBreak = std::string(SPHDECK_SOURCE_DIR) + "/decks/demo/dam_break_2d.k";

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

engine::DeckDiff diff_texts(const std::string& before, const std::string& after) {
    return engine::diff_decks(engine::check_buffer(before, "before.k"), engine::check_buffer(after, "after.k"), 1e-12);
}

const engine::KeywordChange* find_change(const engine::DeckDiff& d, const std::string& name) {
    for (const auto& k : d.keywords)
        if (k.name == name) return &k;
    return nullptr;
}

}  // namespace

TEST_CASE("diff: a deck against itself and against a copy written in another layout") {
    const std::string deck = slurp(kDamBreak);
    CHECK(diff_texts(deck, deck).equal());
    // Values moved inside their fields, comments gone, a card in free format, the same values read.
    std::string other = replaced(deck, "       1.0         0       0.0       0.0   1.0e+08         0",
                                 "1.0       0         0.        0.0       100000000.0");
    other = replaced(other, "         1       1.2       0.2       2.0       0.0   1.0e+20       0.0",
                     "1,1.2,0.2,2.0,0.0,1e20,0");
    other = replaced(other, "$ Constant gravity: scale 1.0 from t = 0 to t = 100 s, well past ENDTIM.\n", "");
    const auto d = diff_texts(deck, other);
    CHECK(d.equal());
}

TEST_CASE("diff: two versions of a shipped deck differ by exactly the values changed") {
    const std::string deck = slurp(kDamBreak);
    std::string v2 = replaced(deck, "         1         0   1.0e+20         2       150        15",
                              "         1         0   1.0e+20         2       150        12");
    v2 = replaced(v2, "         1       1.2       0.2", "         1       1.3       0.2");
    v2 = replaced(v2, "       2          0.0225          0.0075",
                  "       2          0.0230          0.0075");  // node 2 moved
    v2 = replaced(v2, "*MAT_NULL", "*PART\nsecond column\n         2         1         1         1\n*MAT_NULL");
    const auto d = diff_texts(deck, v2);
    CHECK_FALSE(d.equal());
    const auto* sph = find_change(d, "*CONTROL_SPH");
    REQUIRE(sph);
    REQUIRE(sph->fields.size() == 1);
    CHECK(sph->fields[0].field == "card 1 FORM");
    CHECK(sph->fields[0].before == 15);
    CHECK(sph->fields[0].after == 12);
    CHECK(sph->fields[0].after_at.line == 14);
    const auto* section = find_change(d, "*SECTION_SPH");
    REQUIRE(section);
    CHECK(section->id == "SECID 1");
    REQUIRE(section->fields.size() == 1);
    CHECK(section->fields[0].field == "CSLH");
    std::size_t parts_added = 0;
    for (const auto& k : d.keywords) parts_added += k.kind == engine::KeywordChange::Kind::Added && k.id == "PID 2";
    CHECK(parts_added == 1);
    CHECK(d.keywords.size() == 3);
    CHECK(d.nodes.changed == 1);
    CHECK(d.nodes.changed_ids == std::vector<long long>{2});
    CHECK(d.nodes.largest_displacement == doctest::Approx(0.0005));
    CHECK(d.particles.equal());
}

TEST_CASE("diff: a parameter's new value is a difference where it is used; a tolerance absorbs round-off") {
    const std::string deck = "*KEYWORD\n*PARAMETER\nR tend     0.002\n*CONTROL_TERMINATION\n&tend\n*END\n";
    const auto d = diff_texts(deck, replaced(deck, "0.002", "0.003"));
    REQUIRE(d.keywords.size() == 1);  // the field that uses it (the reader consumes *PARAMETER)
    CHECK(find_change(d, "*CONTROL_TERMINATION") != nullptr);
    const auto close = engine::diff_decks(engine::check_buffer(deck, "a.k"),
                                          engine::check_buffer(replaced(deck, "0.002", "0.0020000001"), "b.k"), 1e-6);
    CHECK(close.equal());
}

TEST_CASE("diff: the command's exit codes and a value no layout decodes") {
    test::TempDir dir;
    const std::string deck = slurp(kDamBreak);
    dir.write("a.k", deck);
    dir.write("b.k", replaced(deck, "         1       1.2       0.2", "         1       1.3       0.2"));
    CHECK(test::run_sphdeck(dir, "diff a.k a.k").exit_code == 0);
    const test::Run changed = test::run_sphdeck(dir, "diff a.k b.k");
    CHECK(changed.exit_code == 1);
    CHECK(changed.out.find("CSLH: 1.2 -> 1.3  (a.k:25:18 -> b.k:25:18)") != std::string::npos);
    CHECK(test::run_sphdeck(dir, "diff a.k missing.k").exit_code == 2);
    // An OpenRadioss card past the first of a /MAT law whose CFG reads free lines (LAW30) is not decoded:
    // its text is compared, blanks aside.
    const std::string rad =
        "#RADIOSS STARTER\n/BEGIN\nrun\n      2026         0\n                  kg                  mm                  ms\n"
        "                  kg                  mm                  ms\n"
        "/MAT/LAW30/1\nmat\n               .0078                   0\n                  10                 100                   1\n/END\n";
    dir.write("r1_0000.rad", rad);
    dir.write("r2_0000.rad",
              replaced(rad, "                  10                 100", "                  11                 100"));
    const test::Run radioss = test::run_sphdeck(dir, "diff r1_0000.rad r2_0000.rad");
    CHECK(radioss.exit_code == 1);
    CHECK(radioss.out.find("not decoded: 10") != std::string::npos);
}

TEST_CASE("diff: a deck and the copy `sphdeck format` writes read the same; two versions differ") {
    test::TempDir dir;
    // Values written off the right edge of their fields (left-aligned, blanks around): format moves them.
    const std::string deck =
        "*KEYWORD\n*control_termination\n0.5       0         \n*SECTION_SPH\n1         1.2       "
        "0.2       2.0\n*END\n";
    dir.write("a.k", deck);
    dir.write("b.k", deck);
    CHECK(test::run_sphdeck(dir, "format b.k").exit_code == 0);
    CHECK(slurp((dir.path() / "b.k").string()) != deck);  // format did change the text
    const test::Run same = test::run_sphdeck(dir, "diff a.k b.k");
    CHECK_MESSAGE(same.exit_code == 0, same.out);
    CHECK(same.out.find("no difference in what the solver reads") != std::string::npos);
}
}  // namespace test_deck_diff_cpp
