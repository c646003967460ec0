// OpenRadioss decks as the starter reads them (issue 37): a /SET stands for a group of its id, every
// /MAT law the CFG files lay out is checked by its own cards, a fragment's fields against every
// version's layout, and unknown headers of a known shape say their cause.
#include <doctest/doctest.h>

#include <string>

#include "engine/check.hpp"
#include "engine/id_lookup.hpp"
#include "grammar/radioss/generated_layouts.hpp"
#include "grammar/radioss/keyword_lookup.hpp"
#include "test_support.hpp"

namespace test_radioss_round3_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;
using test::find_code;
namespace rad = grammar::radioss;

namespace {

std::string right(const std::string& v, std::size_t width) {
    return std::string(v.size() < width ? width - v.size() : 0, ' ') + v;
}
std::string i10(const std::string& v) { return right(v, 10); }
std::string r20(const std::string& v) { return right(v, 20); }

std::string deck(const std::string& body, int version = 2026) {
    return "#RADIOSS STARTER\n/BEGIN\nrun\n" + i10(std::to_string(version)) + "\n" + r20("kg") + r20("mm") + r20("ms") +
           "\n" + r20("kg") + r20("mm") + r20("ms") + "\n" + body + "/END\n";
}

engine::CheckResult check(const std::string& text, const std::string& name = "deck_0000.rad") {
    return engine::check_buffer(text, name, {}, grammar::DeckFormat::Radioss);
}

const std::string nodes = "/NODE\n" + i10("1") + r20("0.0") + r20("0.0") + r20("0.0") + "\n" + i10("2") + r20("1.0") +
                          r20("0.0") + r20("0.0") + "\n" + i10("5") + r20("0.5") + r20("0.5") + r20("1.0") + "\n";

std::string rbody(const std::string& group) {
    return "/RBODY/1\nrb\n" + i10("5") + i10("0") + i10("0") + i10("0") + r20("0.0") + i10(group) + "\n";
}

}  // namespace

TEST_CASE("radioss round 3: a /SET of the id is the node group or surface a card names (fill_igr.F)") {
    const std::string set =
        "/SET/GENERAL/77\nrigid nodes\n" + right("NODE", 14) + right("1", 11) + right("2", 11) + "\n";
    auto ok = check(deck(nodes + rbody("77") + set));
    CHECK(count_code(ok.diagnostics, "REF008") == 0);
    auto bad = check(deck(nodes + rbody("76") + set));
    REQUIRE(count_code(bad.diagnostics, "REF008") == 1);
    CHECK(find_code(bad.diagnostics, "REF008")->message.find("names no /GRNOD or /SET") != std::string::npos);

    // The editor follows it: grnd_ID's definition is the /SET header, and the set's references hold it.
    const auto uses = engine::collect_ids(ok);
    const engine::IdUse* named = nullptr;
    for (const auto& u : uses)
        if (!u.defines && u.id == "77") named = &u;
    REQUIRE(named);
    CHECK(named->kind == "GRNOD");
    const auto definitions = engine::find_definitions(ok, named->kind, named->id);
    REQUIRE(definitions.size() == 1);
    CHECK(definitions[0].block->keyword == "/SET/GENERAL/77");
    CHECK(engine::ids_meet("SET", "SURF"));
    CHECK(engine::ids_meet("GRNOD", "SET"));
    CHECK_FALSE(engine::ids_meet("GRNOD", "SURF"));
    CHECK_FALSE(engine::ids_meet("PART", "SET"));
}

TEST_CASE("radioss round 3: every /MAT law the CFG files lay out is checked by its own cards, no generic card") {
    std::size_t laws = 0;
    for (const rad::generated::LayoutEntry& e : rad::generated::layouts()) {
        if (e.name.substr(0, 5) != "/MAT/") continue;
        const rad::KeywordSpec* made = rad::generated::keyword_named(e.name);
        REQUIRE(made);
        const auto& first = made->formats.front().cards.front();
        if (first.fields.empty() || first.fields.front().cell == rad::Cell::Line) continue;  // text lines only
        const rad::KeywordLookup found = rad::lookup_keyword(std::string(e.name) + "/1");
        REQUIRE(found.cards);
        INFO(e.name);
        CHECK_FALSE(found.cards->fallback);  // a law's own table, hand-written or generated
        ++laws;
    }
    CHECK(laws > 300);
    // /PROP and /HEAT: never the family's catch-all that keeps every line as text.
    std::size_t others = 0;
    for (const rad::generated::LayoutEntry& e : rad::generated::layouts()) {
        if (e.name.substr(0, 6) != "/PROP/" && e.name.substr(0, 6) != "/HEAT/") continue;
        const rad::KeywordLookup found = rad::lookup_keyword(std::string(e.name) + "/1");
        REQUIRE(found.cards);
        INFO(e.name);
        CHECK(found.cards->name != "/PROP");
        ++others;
    }
    CHECK(others > 100);
}

TEST_CASE("radioss round 3: /MAT/VOID reads RHO, E and Nu in three 20-column cells (matl_void0.cfg)") {
    const std::string good = "/MAT/VOID/10\ndummy\n" + r20("2.2E-6") + r20("2.0") + r20("0.3") + "\n";
    auto ok = check(deck(good));
    CHECK(count_code(ok.diagnostics, "DK006") == 0);
    REQUIRE(ok.model.materials.size() == 1);
    CHECK(ok.model.materials[0].density.value == doctest::Approx(2.2e-6));
    // Nu is a checked field now: a value that is no number says so.
    auto bad = check(deck("/MAT/VOID/10\ndummy\n" + r20("2.2E-6") + r20("2.0") + r20("0.3x") + "\n"));
    const diag::Diagnostic* d = find_code(bad.diagnostics, "DK003");
    REQUIRE(d);
    CHECK(d->message.find("nu") != std::string::npos);
}

TEST_CASE("radioss round 3: /HEAT/MAT IFORM past column 80: obsolete in a 2022 deck, a field of 2019 in a fragment") {
    const std::string heat = "/HEAT/MAT/1\n" + r20("293.0") + r20("4.0") + r20("0.1") + r20("0.0") + i10("1") + "\n" +
                             r20("0.0") + r20("0.0") + r20("0.0") + r20("0.0") + "\n";
    auto in_2022 = check(deck(heat, 2022));
    const diag::Diagnostic* d = find_code(in_2022.diagnostics, "DK006");
    REQUIRE(d);
    CHECK(d->severity == diag::Severity::Info);
    CHECK(d->message.find("HEAT_Iform") != std::string::npos);
    CHECK(d->message.find("no longer reads") != std::string::npos);
    // In a 2019 deck the field is read: nothing to say.
    CHECK(count_code(check(deck(heat, 2019)).diagnostics, "DK006") == 0);
    // Alone, without /BEGIN: some version reads IFORM there, so it is no overflow; past it still is.
    CHECK(count_code(check(heat, "heat.inc").diagnostics, "DK006") == 0);
    const std::string beyond =
        "/HEAT/MAT/1\n" + r20("293.0") + r20("4.0") + r20("0.1") + r20("0.0") + i10("1") + i10("7") + "\n";
    CHECK(count_code(check(beyond, "heat.inc").diagnostics, "DK006") == 1);
}

TEST_CASE("radioss round 3: an unknown header of a known shape says its cause at the header") {
    // /GRSH3N/1: no group type and no title.
    auto group = check(deck(nodes + "/GRSH3N/1\n" + i10("1") + "\n"));
    const diag::Diagnostic* d = find_code(group.diagnostics, "DK001");
    REQUIRE(d);
    CHECK(d->severity == diag::Severity::Error);
    CHECK(d->span.line == 11);
    CHECK(d->message.find("/GRSH3N/<type>/<id>") != std::string::npos);
    CHECK(d->message.find("title") != std::string::npos);
    CHECK(d->message.find("did you mean") == std::string::npos);
    // /INCLUDE "mesh.inc": OpenRadioss includes by #include.
    auto include = check(deck("/INCLUDE \"mesh.inc\"\n"));
    d = find_code(include.diagnostics, "DK001");
    REQUIRE(d);
    CHECK(d->message.find("#include mesh.inc") != std::string::npos);
    REQUIRE(d->fixes.size() == 1);
    CHECK_FALSE(d->fixes[0].safe);
    CHECK(d->fixes[0].edits[0].replacement == "#include mesh.inc");
}

TEST_CASE("radioss round 3: a zero one column past its cell into a cell with its own value names the zero") {
    // BS '0.0' ends at column 81 of a 2019 /HEAT/MAT: IFORM's cell reads '0        1', so IFORM is 0.
    const std::string heat = "/HEAT/MAT/1\n" + r20("293.0") + r20("4.0") + r20("0.1") + right("0.0", 21) +
                             right("1", 9) + "\n" + r20("0.0") + r20("0.0") + r20("0.0") + r20("0.0") + "\n";
    auto r = check(deck(heat, 2019));
    const diag::Diagnostic* d = find_code(r.diagnostics, "RAD030");
    REQUIRE(d);
    CHECK(d->message.find("'0.0' straddles the end of cell HEAT_BS") != std::string::npos);
    CHECK(d->span.column == 79);
    CHECK(count_code(r.diagnostics, "RAD025") == 0);  // folded into the cause
    // The same zero with nothing else in the next cell changes no value.
    const std::string alone = "/HEAT/MAT/1\n" + r20("293.0") + r20("4.0") + r20("0.1") + right("0.0", 21) + "\n" +
                              r20("0.0") + r20("0.0") + r20("0.0") + r20("0.0") + "\n";
    CHECK(count_code(check(deck(alone, 2019)).diagnostics, "RAD030") == 0);
}
TEST_CASE("radioss round 3: a glued pair typed off its cells names both values and moves back whole") {
    // AS '0.1' glued to BS '1.00000000000000E-02' (which fills its cell), as machine-written decks write them.
    const std::string pair = "0.11.00000000000000E-02";
    const auto heat = [&](std::size_t blanks) {
        return "/HEAT/MAT/1\n" + r20("293.0") + r20("4.0") + std::string(blanks, ' ') + pair + "\n" + r20("0.0") +
               r20("0.0") + r20("0.0") + r20("0.0") + "\n";
    };
    CHECK(count_code(check(deck(heat(17))).diagnostics, "RAD030") == 0);  // in place: each value fills its cell
    // One column right: AS reads '0.', BS '11.00000000000000E-0' (11, not 0.01), '2' is past the last cell.
    auto r = check(deck(heat(18)));
    const diag::Diagnostic* d = find_code(r.diagnostics, "RAD030");
    REQUIRE(d);
    CHECK(d->message ==
          "'0.1' and '1.00000000000000E-02' are written glued 1 column right of the end of cell HEAT_AS (columns "
          "41-60): the starter reads HEAT_AS as '0.' and HEAT_BS as '11.00000000000000E-0', and '2' past the last "
          "cell is not read");
    CHECK(d->span.column == 59);
    CHECK(d->span.end_column == 82);
    REQUIRE(d->fixes.size() == 1);
    CHECK(d->fixes[0].safe);
    REQUIRE(d->fixes[0].edits.size() == 1);
    CHECK(d->fixes[0].edits[0].span.column == 58);
    CHECK(d->fixes[0].edits[0].replacement == pair);  // at the line's end: no blanks left behind
    // Two columns left: AS reads '0.11.' (no number), BS '00000000000000E-02'; the fix moves the pair right.
    r = check(deck(heat(15)));
    d = find_code(r.diagnostics, "RAD030");
    REQUIRE(d);
    CHECK(d->message.find("glued 2 columns left of the end of cell HEAT_AS") != std::string::npos);
    CHECK(d->message.find("reads HEAT_AS as '0.11.' and HEAT_BS as '00000000000000E-02'") != std::string::npos);
    REQUIRE(d->fixes.size() == 1);
    CHECK(d->fixes[0].edits[0].replacement == "  " + pair);
    // Off by more than four columns: another layout, not a slip; left to the other rules.
    CHECK(count_code(check(deck(heat(12))).diagnostics, "RAD030") == 0);
}

}  // namespace test_radioss_round3_cpp
