// `sphdeck check --fix`, `--unsafe-fixes`, `--diff` (issue 27 item 1): which fixes a round takes
// (edit/fix_choice.*), the rounds on a deck and its includes (edit/fix_session.*), the command line, and
// that the registry says which rules fix (lint::Fixable) as the deck tests' findings show.
#include <doctest/doctest.h>

#include <filesystem>
#include <map>
#include <set>

#include "edit/fix_session.hpp"
#include "grammar/radioss/reader.hpp"
#include "grammar/tab_expansion.hpp"
#include "text/apply_edits.hpp"
#include "lint/registry.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_fix_cpp {  // each test file's names stay its own in a unity batch

namespace fs = std::filesystem;
using namespace sphdeck;

namespace {

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

diag::Diagnostic finding(grammar::FileId file, std::uint32_t line, std::uint32_t column, std::uint32_t end,
                         std::string replacement, bool safe = true) {
    diag::Diagnostic d{"DK029", diag::Severity::Error, "m", grammar::Span{file, line, column, end}, {}};
    d.fixes.push_back({"fix", safe, {{grammar::Span{file, line, column, end}, std::move(replacement)}}});
    return d;
}

grammar::SourceMap two_instances_of_one_file() {
    grammar::SourceMap sources;
    for (int i = 0; i < 2; ++i) {
        grammar::SourceFile f;
        f.path = "/decks/common.inc";
        f.text = std::string("line one\nline two\n");
        sources.add(std::move(f));
    }
    return sources;
}

// A shifted *CONTROL_TERMINATION line (DK029, safe fix), a keyword in lower case (DK021, safe), and a
// misspelt keyword (DK001, unsafe).
constexpr const char* mistaken_deck =
    "*KEYWORD\r\n"
    "*control_termination\r\n"
    "$#  endtim    endcyc     dtmin    endeng    endmas     nosol\r\n"
    "       1.0E-3         0       0.0\r\n"
    "*CONTROL_TIMESTPE\r\n"
    "       0.0       0.9\r\n"
    "*END\r\n";

}  // namespace

TEST_CASE("fix: a round takes whole fixes that do not overlap; a file included twice gets its edits once") {
    const auto sources = two_instances_of_one_file();
    std::vector<diag::Diagnostic> found = {
        finding(0, 1, 1, 5, "LINE"),
        finding(1, 1, 1, 5, "LINE"),        // the same fix through the second include: applied once
        finding(0, 1, 3, 7, "XXXX"),        // overlaps the first: the next round
        finding(1, 2, 6, 9, "TWO"),         // another line of the same file, named through the second instance
        finding(0, 2, 1, 1, "\n"),          // an inserted line: a judgement, taken at the unsafe level only
        finding(0, 1, 6, 9, "ONE", false),  // unsafe: not at the safe level
    };
    edit::FixRound round = edit::choose_fixes(sources, found, edit::FixLevel::Safe);
    CHECK(round.fixes == 3);  // the first fix mends two findings
    CHECK(round.deferred == 1);
    CHECK(round.unusable == 1);
    REQUIRE(round.edits.size() == 1);
    CHECK(round.edits.begin()->first == "/decks/common.inc");
    CHECK(round.edits.begin()->second.size() == 2);

    round = edit::choose_fixes(sources, found, edit::FixLevel::Unsafe);
    CHECK(round.fixes == 5);
    CHECK(round.unusable == 0);
    CHECK(round.edits.begin()->second.size() == 4);
}

TEST_CASE("fix: a fix is taken whole or not at all") {
    const auto sources = two_instances_of_one_file();
    diag::Diagnostic first = finding(0, 1, 1, 3, "AB");
    diag::Diagnostic second = finding(0, 2, 1, 3, "CD");
    second.fixes[0].edits.push_back({grammar::Span{0, 1, 2, 4}, "xy"});  // overlaps the first fix's edit
    const edit::FixRound round = edit::choose_fixes(sources, {first, second}, edit::FixLevel::Safe);
    CHECK(round.fixes == 1);
    CHECK(round.deferred == 1);
    CHECK(round.edits.begin()->second.size() == 1);
}

TEST_CASE("fix: rounds on a deck and its include, line endings and untouched files kept") {
    test::TempDir dir;
    const std::string deck = dir.write("main.k",
                                       "*KEYWORD\n*INCLUDE\ncontrols.k\n*INCLUDE\ncontrols.k\n"
                                       "*INCLUDE\nclean.k\n*END\n");
    dir.write("controls.k", mistaken_deck);
    dir.write("clean.k", "*KEYWORD\n*CONTROL_SPH\n*END\n");
    engine::Documents documents;
    edit::FixOutcome outcome = edit::fix_deck(deck, documents, {}, edit::FixLevel::Safe);
    REQUIRE(outcome.files.size() == 1);  // the deck and clean.k change nothing
    const edit::FixedFile& file = outcome.files[0];
    CHECK(fs::path(file.path).filename() == "controls.k");
    CHECK(file.original == mistaken_deck);
    CHECK(file.fixed ==
          "*KEYWORD\r\n"
          "*CONTROL_TERMINATION\r\n"
          "$#  endtim    endcyc     dtmin    endeng    endmas     nosol\r\n"
          "    1.0E-3         0       0.0\r\n"
          "*CONTROL_TIMESTPE\r\n"
          "       0.0       0.9\r\n"
          "*END\r\n");
    CHECK(outcome.fixed == 4);  // two findings in each instance of the file, whose text is edited once
    CHECK(test::count_code(outcome.remaining.diagnostics, "DK029") == 0);
    CHECK(test::count_code(outcome.remaining.diagnostics, "DK021") == 0);
    CHECK(test::count_code(outcome.remaining.diagnostics, "DK001") == 2);  // unsafe: left, in both instances
    CHECK(slurp(dir.path() / "controls.k") == mistaken_deck);              // fix_deck writes nothing itself

    engine::Documents again;
    outcome = edit::fix_deck(deck, again, {}, edit::FixLevel::Unsafe);
    REQUIRE(outcome.files.size() == 1);
    CHECK(outcome.files[0].fixed.find("*CONTROL_TIMESTEP\r\n") != std::string::npos);
    CHECK(test::count_code(outcome.remaining.diagnostics, "DK001") == 0);
}

TEST_CASE("fix: the lines between two texts, as whole-line edits for the diff") {
    const auto edits = edit::line_edits_between("a\r\nbb\nc", "a\r\nBB\nC");
    REQUIRE(edits.size() == 2);
    CHECK(edits[0].span.line == 2);
    CHECK(edits[0].span.end_column == 3);
    CHECK(edits[0].replacement == "BB");
    CHECK(edits[1].span.line == 3);
    CHECK(edits[1].replacement == "C");
}

TEST_CASE("fix: lines a fix inserted join the old line below them in the diff's edits") {
    // A line inserted above line 2, line 4 changed, a line inserted above the last line.
    const std::string original = "a\r\nb\r\nc\r\nd\r\ne\r\n";
    const std::string fixed = "a\r\n\r\nb\r\nc\r\nD\r\nnew\r\ne\r\n";
    const auto edits = edit::line_edits_between(original, fixed);
    REQUIRE(edits.size() == 2);
    CHECK(edits[0].span.line == 2);
    CHECK(edits[0].replacement == "\r\nb");
    CHECK(edits[1].span.line == 4);  // a changed line takes the inserted lines up to the next old one
    CHECK(edits[1].replacement == "D\r\nnew");
    CHECK(text::apply_edits(original, edits).text == fixed);
    CHECK(edit::line_edits_between("a\nb\n", "a\n").empty());  // fixes never remove a line
}

TEST_CASE("fix: DK032's blank heading is inserted by --unsafe-fixes only") {
    test::TempDir dir;
    const std::string deck = dir.write("part.k", slurp(fs::path(SPHDECK_SOURCE_DIR) / "decks/tests/dk/DK032_fires.k"));
    engine::Documents safe_documents;
    edit::FixOutcome outcome = edit::fix_deck(deck, safe_documents, {}, edit::FixLevel::Safe);
    CHECK(outcome.files.empty());
    CHECK(test::count_code(outcome.remaining.diagnostics, "DK032") == 1);

    engine::Documents documents;
    outcome = edit::fix_deck(deck, documents, {}, edit::FixLevel::Unsafe);
    REQUIRE(outcome.files.size() == 1);
    const std::string& fixed = outcome.files[0].fixed;
    CHECK(fixed.find("$ expect: DK032\n\n         1         1         1         1\n") != std::string::npos);
    CHECK(test::count_code(outcome.remaining.diagnostics, "DK032") == 0);
    for (const auto& d : outcome.remaining.diagnostics) CHECK(d.severity == diag::Severity::Info);
    CHECK(
        text::apply_edits(outcome.files[0].original, edit::line_edits_between(outcome.files[0].original, fixed)).text ==
        fixed);
}

TEST_CASE("fix: DK016's tab expanded only when the layout it shows is certain") {
    const std::vector<grammar::FixedField> fields = {{0, 10}, {10, 10}, {20, 10}, {30, 10}};
    // At stops of 8 "1.0e-3" fills field 2; at stops of 4 it would cross into it from field 1.
    CHECK(grammar::expand_tabs_if_certain("     0.002\t\t1.0e-3", fields) == "     0.002              1.0e-3");
    // At stops of 8 "500000" crosses the end of field 1.
    CHECK_FALSE(grammar::expand_tabs_if_certain("     0.002\t500000", fields));
    // A value neither right- nor left-aligned in its field at stops of 8: not laid out on purpose.
    CHECK_FALSE(grammar::expand_tabs_if_certain("\t   1.0", fields));
    // At stops of 8 the start of field 2, at stops of 4 the start of field 1: which was meant is a guess.
    const std::vector<grammar::FixedField> narrow = {{0, 4}, {4, 4}, {8, 4}, {12, 4}};
    CHECK_FALSE(grammar::expand_tabs_if_certain("\t1.0", narrow));
    CHECK(grammar::expand_tabs_if_certain("\t  1.0", fields) == "          1.0");
}

TEST_CASE("fix: check --fix writes the mended files, --diff prints and writes nothing") {
    test::TempDir dir;
    dir.write("deck.k", mistaken_deck);
    const std::string original = mistaken_deck;

    auto run = test::run_sphdeck(dir, "check --no-config --diff deck.k");
    CHECK(run.exit_code == 1);
    CHECK(run.out.rfind("--- a/deck.k\n+++ b/deck.k\n", 0) == 0);
    CHECK(run.out.find("-*control_termination\r\n+*CONTROL_TERMINATION\r\n") != std::string::npos);
    CHECK(run.err.find("would fix 2, 1 remaining") != std::string::npos);
    CHECK(slurp(dir.path() / "deck.k") == original);

    run = test::run_sphdeck(dir, "check --no-config --unsafe-fixes deck.k");
    CHECK(run.exit_code == 2);  // never writes without --fix
    CHECK(slurp(dir.path() / "deck.k") == original);

    run = test::run_sphdeck(dir, "check --no-config --format concise --fix deck.k");
    CHECK(run.exit_code == 1);  // the misspelt keyword remains
    CHECK(run.err.find("2 fixed, 1 remaining") != std::string::npos);
    CHECK(run.out.find("DK001") != std::string::npos);
    CHECK(run.out.find("DK029") == std::string::npos);
    const std::string fixed = slurp(dir.path() / "deck.k");
    CHECK(fixed.find("*CONTROL_TERMINATION\r\n") != std::string::npos);

    const auto modified = fs::last_write_time(dir.path() / "deck.k");
    run = test::run_sphdeck(dir, "check --no-config --diff deck.k");
    CHECK(run.out.empty());
    CHECK(run.exit_code == 1);  // no diff, but the remaining error
    run = test::run_sphdeck(dir, "check --no-config --fix deck.k");
    CHECK(fs::last_write_time(dir.path() / "deck.k") == modified);  // nothing to fix: not written

    run = test::run_sphdeck(dir, "check --no-config --fix --unsafe-fixes deck.k");
    CHECK(run.exit_code == 0);
    CHECK(run.out.find("1 fixed, 0 remaining") != std::string::npos);
}

namespace {

bool is_main_test_deck(const fs::path& p) {
    const bool engine = grammar::radioss::is_engine_file_name(p.filename().string());
    if (p.extension() != ".k" && (p.extension() != ".rad" || engine)) return false;
    for (const auto& part : p)
        if (part == "include") return false;
    return true;
}

}  // namespace

TEST_CASE("fix: every rule whose findings carry fixes in the deck tests says so in the registry, and back") {
    std::map<std::string, std::set<bool>> seen;  // code -> safety of the fixes its findings carry
    for (const char* folder : {"tests", "demo"})
        for (const auto& e : fs::recursive_directory_iterator(fs::path(SPHDECK_SOURCE_DIR) / "decks" / folder))
            if (e.is_regular_file() && is_main_test_deck(e.path()))
                for (const auto& d : engine::check_file(e.path().string()).diagnostics)
                    for (const auto& fix : d.fixes) seen[d.code].insert(fix.safe);
    for (const lint::RuleInfo& rule : lint::all_rules()) {
        CAPTURE(rule.code);
        const auto found = seen.find(std::string(rule.code));
        const std::set<bool> kinds = found == seen.end() ? std::set<bool>{} : found->second;
        switch (rule.fix) {
            case lint::Fixable::None: CHECK(kinds.empty()); break;
            case lint::Fixable::Safe: CHECK(kinds == std::set<bool>{true}); break;
            case lint::Fixable::Unsafe: CHECK(kinds == std::set<bool>{false}); break;
            case lint::Fixable::Mixed: CHECK(kinds == std::set<bool>{false, true}); break;
        }
    }
}
}  // namespace test_fix_cpp
