// False alarms the corpus check (issue 13) found on published LS-DYNA decks, each pinned by the
// general mechanism that fixed it.
#include <doctest/doctest.h>

#include <string>

#include "engine/check.hpp"
#include "model/flood_guard.hpp"
#include "test_support.hpp"

namespace test_corpus_regressions_dyna_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;
using test::find_code;

namespace {

const std::string kFluid =
    "*KEYWORD\n*SECTION_SPH\n         1\n*MAT_NULL\n         1    1000.0\n*EOS_MURNAGHAN\n         1       7.0    1.0e+5"
    "       1.0\n*PART\nwater\n         1         1         1         1\n*NODE\n       1\n       2\n       3\n";

// n particles on nodes 1..n, 1 apart on the x axis, naming part i (pid_is_nid) or one of seven
// parts 1000-1006; MASS blank.
std::string particles(int n, bool pid_is_nid) {
    std::string s = "*KEYWORD\n*NODE\n";
    for (int i = 1; i <= n; ++i) {
        const std::string nid = std::to_string(i), x = std::to_string(i) + ".0";
        s += std::string(8 - nid.size(), ' ') + nid + std::string(16 - x.size(), ' ') + x + "\n";
    }
    s += "*ELEMENT_SPH\n";
    for (int i = 1; i <= n; ++i) {
        const std::string nid = std::to_string(i), pid = std::to_string(pid_is_nid ? i : 1000 + i % 7);
        s += std::string(8 - nid.size(), ' ') + nid + std::string(8 - pid.size(), ' ') + pid + "\n";
    }
    return s;
}

bool has_note(const diag::Diagnostic& d, const std::string& text) {
    for (const auto& n : d.notes)
        if (n.message.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("corpus: 0 entries padding a set list are empty slots, not undefined ids") {
    auto silent =
        engine::check_buffer(kFluid +
                                 "*SET_NODE_LIST\n         1\n         1         2         0         0\n"
                                 "*SET_PART_LIST\n         1\n         1         0         0         0\n"
                                 "*SET_NODE_LIST_GENERATE\n         2\n         1         3         0         0\n",
                             "d.k");
    CHECK(count_code(silent.diagnostics, "REF001") == 0);
    CHECK(count_code(silent.diagnostics, "REF002") == 0);
    REQUIRE(silent.model.node_sets.size() == 2);
    CHECK(silent.model.node_sets[0].members == std::vector<long long>{1, 2});
    CHECK(silent.model.node_sets[1].members == std::vector<long long>{1, 2, 3});
    auto fires =
        engine::check_buffer(kFluid + "*SET_NODE_LIST\n         1\n         1        99         0         0\n", "d.k");
    const diag::Diagnostic* d = find_code(fires.diagnostics, "REF001");
    REQUIRE(d);
    CHECK(d->message == "node set 1 names undefined node(s) 99");
}

TEST_CASE("corpus: MID 0 on a part of a thermal-only analysis is not a missing material") {
    const std::string part =
        "*SECTION_SPH\n         1\n*PART\nwafer\n         1         1         0         0         0"
        "         0         0         1\n*MAT_THERMAL_ISOTROPIC\n         1    2330.0\n     700.0     150.0\n";
    auto thermal = engine::check_buffer("*KEYWORD\n*CONTROL_SOLUTION\n         1\n" + part, "d.k");
    CHECK(count_code(thermal.diagnostics, "REF004") == 0);
    CHECK(thermal.model.controls.soln.value == 1);
    SUBCASE("structural or coupled: the part has no material, said without a 'material 0'") {
        for (std::string control : {"", "*CONTROL_SOLUTION\n         0\n", "*CONTROL_SOLUTION\n         2\n"}) {
            auto r = engine::check_buffer("*KEYWORD\n" + control + part, "d.k");
            const diag::Diagnostic* d = find_code(r.diagnostics, "REF004");
            REQUIRE(d);
            CHECK(d->message == "part 1 has no material (MID 0)");
        }
    }
    SUBCASE("thermal-only without a TMID: still no material at all") {
        auto r = engine::check_buffer(
            "*KEYWORD\n*CONTROL_SOLUTION\n         1\n*SECTION_SPH\n         1\n*PART\nwafer\n"
            "         1         1         0\n",
            "d.k");
        CHECK(count_code(r.diagnostics, "REF004") == 1);
    }
    SUBCASE("SECID 0 is a part without section") {
        auto r = engine::check_buffer("*KEYWORD\n*PART\nshell\n         1         0         0\n", "d.k");
        const diag::Diagnostic* d = find_code(r.diagnostics, "REF003");
        REQUIRE(d);
        CHECK(d->message == "part 1 has no section (SECID 0)");
    }
}

TEST_CASE("corpus: a mesh fragment whose particles each name their own part makes one REF002 and one SPH112") {
    auto r = engine::check_buffer(particles(3000, true), "d.k");
    CHECK(count_code(r.diagnostics, "REF002") == 1);
    CHECK(count_code(r.diagnostics, "SPH112") == 1);
    CHECK(r.diagnostics.size() < 10);
    const diag::Diagnostic* ref = find_code(r.diagnostics, "REF002");
    REQUIRE(ref);
    CHECK(ref->message ==
          "3000 particles name 3000 parts that are not defined: parts 1, 2, 3, 4, 5, ...; particles "
          "1, 2, 3, 4, 5, ...");
    CHECK(ref->span.line == 3004);
    CHECK(has_note(*ref, "particle 2 names part 2"));
    CHECK(has_note(*ref, "the part id equals the node id on every line: columns swapped?"));
    const diag::Diagnostic* mass = find_code(r.diagnostics, "SPH112");
    REQUIRE(mass);
    CHECK(mass->message.find("3000 particles of 3000 parts") != std::string::npos);
}

TEST_CASE("corpus: a few undefined parts keep one finding each; the hint needs its pattern") {
    auto r = engine::check_buffer(particles(70, false), "d.k");  // 70 particles over parts 1000-1006
    CHECK(count_code(r.diagnostics, "REF002") == 1);             // 7 parts > 5: merged
    auto few = engine::check_buffer(
        kFluid + "*ELEMENT_SPH\n       1    1001           0.001\n       2    1002           0.001\n", "d.k");
    CHECK(count_code(few.diagnostics, "REF002") == 2);
    for (const auto& d : few.diagnostics) CHECK_FALSE(has_note(d, "columns swapped"));
    auto no_parts = engine::check_buffer(particles(3, false), "d.k");
    const diag::Diagnostic* d = find_code(no_parts.diagnostics, "REF002");
    REQUIRE(d);
    CHECK(has_note(*d, "the deck defines no *PART"));
}

TEST_CASE("corpus: a missing include silences undefined and unused references, not duplicates") {
    test::TempDir dir;
    const std::string body = kFluid +
                             "*SET_NODE_LIST\n         1\n      1001\n*SECTION_SPH\n         7\n"
                             "*NODE\n       1\n";
    auto complete = engine::check_file(dir.write("complete.k", body));
    CHECK(count_code(complete.diagnostics, "REF001") == 1);
    CHECK(count_code(complete.diagnostics, "REF007") == 1);
    auto missing = engine::check_file(dir.write("missing.k", body + "*INCLUDE\nmesh.k\n"));
    CHECK(count_code(missing.diagnostics, "DK010") == 1);
    CHECK(count_code(missing.diagnostics, "REF001") == 0);
    CHECK(count_code(missing.diagnostics, "REF007") == 0);
    CHECK(count_code(missing.diagnostics, "REF006") == 1);  // node 1 twice: no include can undo that
}

TEST_CASE("corpus: QL 0.0 is the default's zero: no SPH012 away from FORM 12, no SPH013 with it") {
    auto deck = [](const std::string& form, const std::string& ql) {
        return "*KEYWORD\n*CONTROL_MPP_DECOMPOSITION_DISTRIBUTE_SPH_ELEMENTS\n*CONTROL_SPH\n         1         0   1.0e+20"
               "         3       150" +
               form +
               "\n         0         0         0         0         0         0         0       100\n         0"
               "         0" +
               ql + "\n";
    };
    auto zero = engine::check_buffer(deck("        15", "       0.0"), "d.k");
    CHECK(count_code(zero.diagnostics, "SPH012") == 0);
    CHECK(zero.model.controls.sph.ql.value == doctest::Approx(0.01));
    CHECK(count_code(engine::check_buffer(deck("        15", "      0.05"), "d.k").diagnostics, "SPH012") == 1);
    CHECK(count_code(engine::check_buffer(deck("        12", "       0.0"), "d.k").diagnostics, "SPH013") == 0);
    CHECK(count_code(engine::check_buffer(deck("        12", "       0.5"), "d.k").diagnostics, "SPH013") == 1);
}

TEST_CASE("corpus: blank lines past a keyword's last card are not DK009; a data line is") {
    auto blank = engine::check_buffer("*KEYWORD\n*CONTROL_TERMINATION\n     0.002\n\n   \n*END\n", "d.k");
    CHECK(count_code(blank.diagnostics, "DK009") == 0);
    auto data = engine::check_buffer("*KEYWORD\n*CONTROL_TERMINATION\n     0.002\n\n       1.0\n*END\n", "d.k");
    CHECK(count_code(data.diagnostics, "DK009") == 1);
}

TEST_CASE("corpus: a title longer than 80 columns is not DK006; a data card is") {
    const std::string long_title(95, 'T');
    auto title = engine::check_buffer("*KEYWORD\n*TITLE\n" + long_title + "\n*END\n", "d.k");
    CHECK(count_code(title.diagnostics, "DK006") == 0);
    auto card =
        engine::check_buffer("*KEYWORD\n*CONTROL_TERMINATION\n     0.002" + std::string(75, ' ') + "9\n*END\n", "d.k");
    CHECK(count_code(card.diagnostics, "DK006") == 1);
}

TEST_CASE("corpus: a mistake repeated on every line of a block is a finding per line (text folds them)") {
    std::string deck = "*KEYWORD\n*NODE\n";
    for (int i = 1; i <= 3000; ++i) deck += std::to_string(i) + "," + std::to_string(i) + ".0,0.0,0.0\n";
    deck += "*ELEMENT_SPH\n";
    for (int i = 1; i <= 3000; ++i) deck += std::to_string(i) + ",1,mass\n";
    auto r = engine::check_buffer(deck, "d.k");
    CHECK(count_code(r.diagnostics, "DK003") == 3000);  // every format carries them (issue 25 item 5)
    for (const auto& d : r.diagnostics) CHECK(d.message.find("(and ") == std::string::npos);
}

TEST_CASE("flood guard: past the safety bound per code and block, the rest are dropped and counted") {
    std::vector<diag::Diagnostic> out(1, {"DK001", diag::Severity::Info, "before", {}, {}});
    for (std::uint32_t line = 1; line <= 12; ++line)
        out.push_back({"DK003", diag::Severity::Error, "bad", {0, line, 1, 2}, {}});
    out.push_back({"DK002", diag::Severity::Error, "other", {0, 13, 1, 2}, {}});
    model::collapse_block_floods(out, 1, "*NODE", 4);
    REQUIRE(out.size() == 1 + 4 + 1);
    CHECK(out[0].message == "before");  // findings before `from` stay as they are
    CHECK(out[4].message ==
          "bad (and 8 more DK003 finding(s) on the lines of this *NODE block, dropped: at most 4 of one code per "
          "block are kept; lines 5, 6, 7, 8, 9, ...)");
    CHECK(out[5].code == "DK002");
}

TEST_CASE("flood guard: trimmed while a block is walked, and across threads' ranges, the same as at once") {
    auto findings = [](std::uint32_t first, std::uint32_t last) {
        std::vector<diag::Diagnostic> v;
        for (std::uint32_t line = first; line <= last; ++line)
            v.push_back({"DK003", diag::Severity::Error, "bad", {0, line, 1, 2}, {}});
        return v;
    };
    // Two "threads": lines 1-10 and 11-20, each trimmed as it goes, then merged in line order.
    std::vector<diag::Diagnostic> a, b;
    model::FloodBound bound_a(0, 4), bound_b(0, 4);
    for (auto& d : findings(1, 10)) a.push_back(d), bound_a.trim(a);
    for (auto& d : findings(11, 20)) b.push_back(d), bound_b.trim(b);
    CHECK(a.size() == 4);  // never more than the bound held at once
    CHECK(bound_a.dropped() == 6);
    std::vector<diag::Diagnostic> out = a;
    out.insert(out.end(), b.begin(), b.end());
    model::FloodBound block(0, 4);
    block.merge(bound_a);
    block.merge(bound_b);
    block.annotate(out, 0, "*NODE");
    REQUIRE(out.size() == 4);
    CHECK(block.dropped() == 16);
    CHECK(out[3].message ==
          "bad (and 16 more DK003 finding(s) on the lines of this *NODE block, dropped: at most 4 of one code per "
          "block are kept; lines 5, 6, 7, 8, 9, ...)");
}

TEST_CASE("corpus: a word too long for a number field is one finding (DK003), a number too long is DK005") {
    auto word = engine::check_buffer("*KEYWORD\n*CONTROL_TERMINATION\n0.002,0,0.0,<PAB_TTF-1.1>\n*END\n", "d.k");
    CHECK(count_code(word.diagnostics, "DK003") == 1);
    CHECK(count_code(word.diagnostics, "DK005") == 0);
    auto number = engine::check_buffer("*KEYWORD\n*CONTROL_TERMINATION\n0.00200000001,0\n*END\n", "d.k");
    CHECK(count_code(number.diagnostics, "DK005") == 1);
}

TEST_CASE("corpus: a number glued across a field boundary says so in a note on its DK003") {
    auto r = engine::check_buffer(
        "*KEYWORD\n*CONTROL_TERMINATION\n1.000000E-3\n*DEFINE_CURVE\n         1\n"
        "       9.99990000E+03     0.00000000E+00\n*END\n",
        "d.k");  // O1 in its field: no whole-line shift (that is DK029); ENDTIM
                 // from column 1, too long: not one value pushed across (DK029 too)
    REQUIRE(count_code(r.diagnostics, "DK003") == 2);
    std::vector<std::string> notes;
    for (const auto& d : r.diagnostics)
        if (d.code == "DK003") notes.push_back(d.notes.empty() ? "" : d.notes.front().message);
    CHECK(notes[0] == "'1.000000E-3' runs on past column 10, so the field holds only '1.000000E-'");
    CHECK(notes[1] ==
          "'9.99990000E+03' of the field before runs on into this one at column 21: the field before "
          "holds only '9.99990000E+0'");
    auto word = engine::check_buffer("*KEYWORD\n*CONTROL_TERMINATION\n     abcdefghij\n*END\n", "d.k");
    const diag::Diagnostic* d = find_code(word.diagnostics, "DK003");
    REQUIRE(d);
    CHECK(d->notes.empty());  // glued, but no number: nothing to explain
}
}  // namespace test_corpus_regressions_dyna_cpp
