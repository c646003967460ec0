// The keyword names and layouts generated from the starter's CFG files
// (grammar/radioss/generated/radioss_layouts.cpp): every header is known, an unknown one is an
// error with did-you-mean, the engine's keywords by its own reader, the generated cards typed.
#include <doctest/doctest.h>

#include <string>

#include "engine/check.hpp"
#include "grammar/radioss/generated_layouts.hpp"
#include "grammar/radioss/keyword_lookup.hpp"
#include "grammar/read_deck.hpp"
#include "test_support.hpp"

namespace test_radioss_generated_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;
using test::find_code;
namespace rad = grammar::radioss;

namespace {

std::string i10(const std::string& v) { return std::string(v.size() < 10 ? 10 - v.size() : 0, ' ') + v; }

std::string deck(const std::string& body, int version = 2026) {
    return "#RADIOSS STARTER\n/BEGIN\nrun\n" + i10(std::to_string(version)) + "\n" + body + "/END\n";
}

engine::CheckResult check(const std::string& text, const std::string& name = "deck_0000.rad") {
    return engine::check_buffer(text, name, {}, grammar::DeckFormat::Radioss);
}

std::size_t unknown_errors(const engine::CheckResult& r) {
    std::size_t n = 0;
    for (const auto& d : r.diagnostics) n += d.code == "DK001" && d.severity == diag::Severity::Error;
    return n;
}

}  // namespace

TEST_CASE("radioss generated: every header of the CFG files, written once into a deck, is known") {
    // The 1,492 names of the CFG files' HEADERs (the starter's and the engine's): a starter deck
    // and an engine deck with each once, an id after it, no line of cards.
    std::string starter, engine_deck;
    std::size_t names = 0;
    for (const rad::generated::LayoutEntry& e : rad::generated::layouts()) {
        (e.body.substr(0, 3).find('e') != std::string_view::npos ? engine_deck : starter) +=
            std::string(e.name) + "/1\n";
        ++names;
    }
    CHECK(names > 1400);
    const auto r = check(deck(starter));
    CHECK(unknown_errors(r) == 0);
    for (const auto& d : r.diagnostics)
        if (d.code == "DK001" && d.severity == diag::Severity::Error) FAIL_CHECK(d.message);
    const auto e = check("/RUN/run/1\n" + engine_deck + "/END\n", "run_0001.rad");
    CHECK(unknown_errors(e) == 0);
}

TEST_CASE("radioss generated: an unknown header is an error at its line, with did-you-mean and a fix") {
    auto r = check(deck("/SHEL/1\n" + i10("1") + "\n/INTER/TYPO7/3\n/FOO/BAR/1\n"));
    REQUIRE(unknown_errors(r) == 3);
    const diag::Diagnostic* d = find_code(r.diagnostics, "DK001");
    CHECK(d->span.line == 5);
    CHECK(d->message.find("did you mean /SHELL?") != std::string::npos);
    REQUIRE(d->fixes.size() == 1);
    CHECK_FALSE(d->fixes[0].safe);
    CHECK(d->fixes[0].edits[0].replacement == "/SHELL");
    CHECK(d->fixes[0].edits[0].span.end_column == 6);
    bool inter = false;
    for (const auto& f : r.diagnostics) inter |= f.message.find("did you mean /INTER/TYPE7?") != std::string::npos;
    CHECK(inter);
    // A family table reads any law, but the name must be one: /MAT/LAW999 is no keyword.
    CHECK(unknown_errors(check(deck("/MAT/LAW999/1\ntitle\n"))) == 1);
    CHECK(unknown_errors(check(deck("/MAT/LAW36/1\ntitle\n"))) == 0);
}

TEST_CASE("radioss generated: the starter reads a name by its characters once the first segment is whole") {
    // /TH/SHELL reads as /TH/SHEL (the reader's longest prefix), blanks around segments are dropped.
    CHECK(rad::lookup_keyword("/TH/SHELL/1").known);
    CHECK(rad::lookup_keyword("/GRNOD/NODE    /2").known);
    CHECK_FALSE(rad::lookup_keyword("/SHELLX/1").known);
    CHECK(rad::lookup_keyword("/SUBMODEL/1").known);
    CHECK(rad::lookup_keyword("//ENDSUB").known);
}

TEST_CASE("radioss generated: engine keywords by the engine's REDKEY0; each deck says when one is in the other") {
    CHECK(rad::is_engine_key("/RUN/run/1"));
    CHECK(rad::is_engine_key("/PARITH/ON"));  // PARIT
    CHECK(rad::is_engine_key("/ANIM/ELEM/EPSP"));
    CHECK_FALSE(rad::is_engine_key("/ANIMATION"));  // ANIMA is not ANIM
    CHECK_FALSE(rad::is_engine_key("/SHELL/1"));
    // An engine deck: a header the engine does not know is an error; a starter one says so.
    auto e = check("/RUN/run/1\n0.1\n/PARITH/ON\n/ANIMX/DT\n/SHELL/1\n/END\n", "run_0001.rad");
    CHECK(unknown_errors(e) == 1);
    bool starter_said = false;
    for (const auto& d : e.diagnostics)
        starter_said |= d.message.find("/SHELL is a starter keyword") != std::string::npos;
    CHECK(starter_said);
    // A starter deck: an engine keyword says so (an info: the starter ignores it).
    auto s = check(deck("/TFILE/4\n0.1\n"));
    CHECK(unknown_errors(s) == 0);
    const diag::Diagnostic* d = find_code(s.diagnostics, "DK001");
    REQUIRE(d);
    CHECK(d->severity == diag::Severity::Info);
    CHECK(d->message.find("engine keyword") != std::string::npos);
    // A starter keyword mistyped whose five characters are an engine key (/FUNCTT: FUNCT, /INTERR: INTER) is no
    // engine keyword out of place: no engine keyword has that first segment, a starter one begins with it.
    CHECK(rad::is_engine_only_key("/TFILE/4"));
    CHECK(rad::is_engine_only_key("/RUN/run/1"));
    CHECK_FALSE(rad::is_engine_only_key("/FUNCTT/17"));
    CHECK_FALSE(rad::is_engine_only_key("/INTERR/TYPE7/2"));
    auto typo = check(deck("/FUNCTT/17\nh7\n                 0.0                 1.0\n"));
    CHECK(unknown_errors(typo) == 1);
    const diag::Diagnostic* t = find_code(typo.diagnostics, "DK001");
    REQUIRE(t);
    CHECK(t->message.find("did you mean /FUNCT?") != std::string::npos);
    // What a mistyped header leaves undefined says so where it is missed: the part's REF003 names /PORP/SPH.
    auto part = check(deck("/PART/2\nwater\n" + i10("2") + i10("3") + "\n/PORP/SPH/2\nwater particles\n" +
                           "              8.0E-6\n/MAT/LAW6/3\nwater\n              1.0E-6\n"));
    const diag::Diagnostic* missing = find_code(part.diagnostics, "REF003");
    REQUIRE(missing);
    bool noted = false;
    for (const auto& n : missing->notes) noted |= n.message.find("unknown keyword /PORP/SPH") != std::string::npos;
    CHECK(noted);
}

TEST_CASE("radioss generated: cards of a keyword without a hand-written table are typed and cut by their format") {
    // /SHELL (ELEM/shell4n.cfg, format 110): %10d x5, %10s, %20lg x2, one line per shell.
    auto ok = check(deck("/SHELL/1\n" + i10("1") + i10("1") + i10("2") + i10("3") + i10("4") + "\n", 2026));
    CHECK(count_code(ok.diagnostics, "DK002") == 0);
    auto bad = check(deck("/SHELL/1\n" + i10("1") + i10("1.5") + i10("2") + i10("3") + i10("4") + "\n", 2026));
    const diag::Diagnostic* d = find_code(bad.diagnostics, "DK002");
    REQUIRE(d);
    CHECK(d->span.line == 6);
    CHECK(d->message.find("node_ID1") != std::string::npos);
    // Below the oldest CFG format (/SHELL has none before 110) nothing is checked.
    CHECK(count_code(check(deck("/SHELL/1\n" + i10("1") + i10("1.5") + "\n", 100)).diagnostics, "DK002") == 0);
}

TEST_CASE("radioss generated: a card read only when an earlier field says (CFG if on a field)") {
    // /RBODY (RBODY/rbody.cfg, 2021): the fifth card FN FT expN expT only when Ifail is not 0.
    const auto* rbody = rad::find_generated("/RBODY/1");
    REQUIRE(rbody);
    const rad::FormatSpec& f = rbody->format_for(2026);
    bool conditional = false;
    for (const auto& c : f.cards) conditional |= c.when == "Ifail!0";
    CHECK(conditional);
    CHECK_FALSE(rbody->title == false);
}

TEST_CASE("radioss generated: sphdeck keyword finds a generated layout where no hand-written table names it") {
    std::size_t segments = 0;
    const auto* shell = rad::find_generated("/PROP/SHELL/3", &segments);
    REQUIRE(shell);
    CHECK(shell->name == "/PROP/SHELL");
    CHECK(segments == 2);
    CHECK(shell->generated);
    // The hand-written family table still reads the block into the model.
    CHECK(rad::lookup_keyword("/PROP/SHELL/3").spec->name == "/PROP");
    CHECK(rad::lookup_keyword("/PROP/SHELL/3").known);
}

TEST_CASE("radioss generated: ids the CFG marks as references are followed (REF008, REF009)") {
    const std::string nodes = "/NODE\n" + i10("1") + "                 0.0                 0.0                 0.0\n";
    const std::string wall = "/RWALL/PLANE/1\nwall\n" + i10("0") + i10("0") + i10("5") + i10("99") + "\n" +
                             std::string(20, ' ') + "\n" + std::string(19, ' ') + "0\n" + std::string(19, ' ') + "1\n";
    auto r = check(deck(nodes + "/GRNOD/NODE/5\nnodes\n" + i10("1") + "\n" + wall));
    REQUIRE(count_code(r.diagnostics, "REF008") == 1);
    const diag::Diagnostic* d = find_code(r.diagnostics, "REF008");
    CHECK(d->message.find("excludeNodeSet_ID 99 of /RWALL/PLANE") != std::string::npos);
    CHECK(d->span.line == 12);
    // Defined: silent; a //SUBMODEL offsets ids, so nothing is judged.
    auto ok =
        check(deck(nodes + "/GRNOD/NODE/5\nnodes\n" + i10("1") + "\n/GRNOD/NODE/99\nmore\n" + i10("1") + "\n" + wall));
    CHECK(count_code(ok.diagnostics, "REF008") == 0);
    auto sub = check(deck(nodes + "//SUBMODEL/1\nsub\n" + wall + "//ENDSUB\n"));
    CHECK(count_code(sub.diagnostics, "REF008") == 0);
}

TEST_CASE("radioss generated: a generated card's line shifted under its # header is DK029") {
    // /PROP/SHELL card 3 (format 2018) one column right: every value read in the next cell.
    const std::string prop =
        "/PROP/SHELL/2\nShell\n" + i10("4") + i10("4") + "\n" + std::string(20, ' ') + "\n" +
        "#        N   Istrain               Thick              Ashear              Ithick     Iplas\n" + " " +
        i10("1") + i10("1") + std::string(19, ' ') + "3" + std::string(19, ' ') + "0" + std::string(19, ' ') + "1" +
        i10("0") + "\n";
    auto r = check(deck(prop, 2019));
    const diag::Diagnostic* d = find_code(r.diagnostics, "DK029");
    REQUIRE(d);
    CHECK(d->span.line == 10);
    REQUIRE(d->fixes.size() == 1);
    CHECK(d->fixes[0].safe);
}
}  // namespace test_radioss_generated_cpp
