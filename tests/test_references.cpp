// Regressions of the REF rules found by the deck sweep.
#include <doctest/doctest.h>

#include <chrono>
#include <fmt/format.h>

#include "engine/check.hpp"
#include "grammar/keywords/schema.hpp"
#include "test_support.hpp"

namespace test_references_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;

namespace {
const std::string kPart =
    "*KEYWORD\n*SECTION_SPH\n         1\n*MAT_NULL\n         1    1000.0\n*EOS_MURNAGHAN\n         1       7.0    1.0e+5"
    "       1.0\n*PART\nwater\n         1         1         1         1\n";
}  // namespace

TEST_CASE("references: a missing node include makes a handful of findings, not one per particle") {
    std::string cards;
    for (int i = 1; i <= 1000; ++i) cards += fmt::format("{:8d}       1           0.001\n", i);
    auto r = engine::check_buffer(kPart + "*ELEMENT_SPH\n" + cards, "d.k");
    CHECK(count_code(r.diagnostics, "REF001") == 6);  // five named, one summary of the 995 others
    // An NEND range needs the nodes it names: without them it is refused where it is written (issue 14).
    auto range = engine::check_buffer(kPart + "*ELEMENT_SPH\n       1       1           0.001    1000\n", "d.k");
    CHECK(count_code(range.diagnostics, "DK007") == 1);
    CHECK(count_code(range.diagnostics, "REF001") == 1);
}

TEST_CASE("references: a huge _GENERATE range is bounded, reported, and fast") {
    auto start = std::chrono::steady_clock::now();
    auto r =
        engine::check_buffer(kPart + "*NODE\n       1\n*SET_NODE_LIST_GENERATE\n         1\n         1 200000000\n",
                             "d.k");
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
    REQUIRE(r.model.node_sets.size() == 1);
    CHECK(r.model.node_sets[0].truncated);
    CHECK(count_code(r.diagnostics, "REF001") == 1);
}

TEST_CASE("references: integral reals in id fields are the ids DK004 says they are") {
    auto r = engine::check_buffer(
        "*KEYWORD\n*SECTION_SPH\n         1\n*MAT_NULL\n         1    1000.0\n*PART\np\n         1       1.0         1"
        "       0.0\n",
        "d.k");
    CHECK(count_code(r.diagnostics, "DK004") == 2);
    CHECK(count_code(r.diagnostics, "REF003") == 0);
    CHECK(count_code(r.diagnostics, "REF005") == 0);
}

TEST_CASE("references: *MAT_ADD_* and *MAT_THERMAL_* do not define materials") {
    auto r = engine::check_buffer(kPart + "*MAT_ADD_THERMAL_EXPANSION\n         1         0    1.0e-5\n", "d.k");
    CHECK(count_code(r.diagnostics, "REF006") == 0);
    CHECK(r.model.materials.size() == 1);
}

TEST_CASE("references: sections of *DEFINE_ADAPTIVE_SOLID_TO_SPH and parts of *PART_CONTACT count") {
    auto r = engine::check_buffer(
        kPart +
            "*SECTION_SPH\n         2\n*DEFINE_ADAPTIVE_SOLID_TO_SPH\n         1         0         1"
            "         3         2         0         0\n*PART_CONTACT\nsteel\n         7         1"
            "         1\n       0.1       0.1\n",
        "d.k");
    CHECK(count_code(r.diagnostics, "REF007") == 0);
    CHECK(r.model.part("7") != nullptr);
}

TEST_CASE("references: *DEFINE_ADAPTIVE_SOLID_TO_SPH_TITLE is read with its title line") {
    auto r =
        engine::check_buffer(kPart +
                                 "*SECTION_SPH\n         2\n*DEFINE_ADAPTIVE_SOLID_TO_SPH_TITLE\nsolid to particles\n"
                                 "         1         0         1         3         2         0         0\n",
                             "d.k");
    CHECK(count_code(r.diagnostics, "REF007") == 0);
    const auto match = keywords::find_keyword("*DEFINE_ADAPTIVE_SOLID_TO_SPH_TITLE");
    REQUIRE(match);
    CHECK_FALSE(match->schema->generated);
    CHECK(match->has("TITLE"));
}

TEST_CASE("references: an unreadable PID is DK002 only") {
    auto r = engine::check_buffer(kPart + "*NODE\n       1\n*ELEMENT_SPH\n       1     abc           0.001\n", "d.k");
    CHECK(count_code(r.diagnostics, "DK002") == 1);
    CHECK(count_code(r.diagnostics, "REF002") == 0);
}

TEST_CASE("references: findings on an OpenRadioss deck name its own keywords") {
    const std::string deck =
        "#RADIOSS STARTER\n/BEGIN\nREF\n      2026\n"
        "                  kg                  mm                  ms\n"
        "                  kg                  mm                  ms\n"
        "/PART/2\nwater\n         7         9         0\n"
        "/NODE\n      1001                 1.0                 1.0                 1.0\n"
        "/SPHCEL/2\n      1001         0\n      1002         0\n/END\n";
    auto r = engine::check_buffer(deck, "ref_0000.rad", {}, std::nullopt);
    const diag::Diagnostic* node = test::find_code(r.diagnostics, "REF001");
    const diag::Diagnostic* section = test::find_code(r.diagnostics, "REF003");
    const diag::Diagnostic* material = test::find_code(r.diagnostics, "REF004");
    REQUIRE(node);
    REQUIRE(section);
    REQUIRE(material);
    CHECK(node->message.find("/NODE") != std::string::npos);
    CHECK(section->message.find("/PROP") != std::string::npos);
    CHECK(material->message.find("/MAT") != std::string::npos);
    CHECK(node->message.find('*') == std::string::npos);
}

TEST_CASE("references: ids named by generated keywords are followed (REF009 and friends)") {
    const std::string load = "*LOAD_NODE_POINT\n        80         3        12       1.0\n*NODE\n      80\n";
    auto r = engine::check_buffer(kPart + load, "d.k");
    REQUIRE(count_code(r.diagnostics, "REF009") == 1);
    CHECK(r.model.id_references.size() == 2);  // NID (node 80) and LCID (curve 12)
    // Defined as a *DEFINE_CURVE_TITLE (title line first), a table or a function: the same id space.
    for (const char* curve :
         {"*DEFINE_CURVE_TITLE\nload\n        12\n       0.0       1.0\n",
          "*DEFINE_TABLE\n        12\n       0.0         1\n", "*DEFINE_FUNCTION\n        12\nf(t)=t\n"})
        CHECK(count_code(engine::check_buffer(kPart + load + curve, "d.k").diagnostics, "REF009") == 0);
    // A curve defined through a parameter cannot be judged: the kind is skipped.
    CHECK(count_code(engine::check_buffer(kPart + "*PARAMETER\nI lc              13\n" + load + "*DEFINE_CURVE\n&lc\n",
                                          "d.k")
                         .diagnostics,
                     "REF009") == 0);
    // Ids in a missing include cannot be matched.
    CHECK(count_code(engine::check_buffer(kPart + load + "*INCLUDE\nmissing.k\n", "d.k").diagnostics, "REF009") == 0);
}

TEST_CASE("references: a type field decides what a generated keyword's id names") {
    const std::string contact =
        "*CONTACT_AUTOMATIC_NODES_TO_SURFACE\n         9         1         {}         3\n       0.1\n";
    // SURFATYP 3: part 9 (undefined, REF002); 4: node set 9 (REF008); 5: all (not judged);
    // 0 on the node side of a node-to-surface contact: not a segment set.
    CHECK(count_code(engine::check_buffer(kPart + fmt::format(fmt::runtime(contact), 3), "d.k").diagnostics,
                     "REF002") == 1);
    CHECK(count_code(engine::check_buffer(kPart + fmt::format(fmt::runtime(contact), 4), "d.k").diagnostics,
                     "REF008") == 1);
    for (int type : {0, 5}) {
        auto r = engine::check_buffer(kPart + fmt::format(fmt::runtime(contact), type), "d.k");
        CHECK(count_code(r.diagnostics, "REF002") + count_code(r.diagnostics, "REF008") == 0);
    }
    // The data card of a *PART_ variant: its SECID is the part's, reported once by REF003.
    auto jet = engine::check_buffer(kPart + "*PART_INERTIA\nsteel\n         7         5         5\n", "d.k");
    CHECK(count_code(jet.diagnostics, "REF003") == 1);  // the part's own SECID, once (not again as a link)
}

TEST_CASE("references: *FREQUENCY_DOMAIN_FRF ids are not followed (pydyna's layout has a card more)") {
    auto r = engine::check_buffer(kPart +
                                      "*FREQUENCY_DOMAIN_FRF\n         0         0         1         1         0"
                                      "      20.0\n      0.01         0\n         2         1\n",
                                  "d.k");
    CHECK(r.model.id_references.empty());
}

TEST_CASE("references: a material named by a generated keyword is used, an undefined one is REF004") {
    const std::string group = "*MAT_NULL\n         2     900.0\n*ALE_STRUCTURED_MULTI_MATERIAL_GROUP\n{}";
    auto used = engine::check_buffer(kPart + fmt::format(fmt::runtime(group), "         1         2\n"), "d.k");
    CHECK(count_code(used.diagnostics, "REF007") == 0);
    CHECK(count_code(used.diagnostics, "REF004") == 0);
    auto missing = engine::check_buffer(kPart + fmt::format(fmt::runtime(group), "         1         3\n"), "d.k");
    CHECK(count_code(missing.diagnostics, "REF007") == 1);  // material 2
    CHECK(count_code(missing.diagnostics, "REF004") == 1);  // material 3
}

namespace {
// kPart's part with TMID `tmid` (columns 71-80), under *CONTROL_SOLUTION SOLN `soln` (none: -1), with `more`.
engine::CheckResult thermal_deck(const std::string& tmid, int soln, const std::string& more = "") {
    std::string deck = kPart;
    deck.replace(deck.rfind("         1\n"), 11, fmt::format("         1         0         0         0{:>10}\n", tmid));
    if (soln >= 0) deck += fmt::format("*CONTROL_SOLUTION\n{:>10}\n", soln);
    return engine::check_buffer(deck + more, "d.k");
}
}  // namespace

TEST_CASE("references: a TMID no *MAT_THERMAL_ defines is REF004, an error only where a thermal run reads it") {
    for (int soln : {-1, 0, 1, 2}) {
        CAPTURE(soln);
        const auto r = thermal_deck("3", soln);
        REQUIRE(count_code(r.diagnostics, "REF004") == 1);
        const diag::Diagnostic* d = test::find_code(r.diagnostics, "REF004");
        CHECK(d->severity == (soln >= 1 ? diag::Severity::Error : diag::Severity::Warning));
        CHECK(d->message == "part 1 names thermal material 3 (TMID), which no *MAT_THERMAL_ defines");
        CHECK(d->span.line == 10);
        CHECK(d->span.column == 80);
        CHECK(d->fixes.empty());
    }
    // Defined (after the part, or as "03"), 0, blank: nothing.
    const std::string thermal = "*MAT_THERMAL_ISOTROPIC\n         3    1000.0\n    4180.0       0.6\n";
    CHECK(count_code(thermal_deck("3", 1, thermal).diagnostics, "REF004") == 0);
    CHECK(count_code(thermal_deck("03", 2, thermal).diagnostics, "REF004") == 0);
    CHECK(count_code(thermal_deck("0", 1).diagnostics, "REF004") == 0);
    CHECK(count_code(thermal_deck("", 1).diagnostics, "REF004") == 0);
    const std::string by_parameter =
        "*PARAMETER\nI   tmidp          7\n*MAT_THERMAL_ISOTROPIC\n    &tmidp    1000.0\n    4180.0       0.6\n";
    // A thermal material whose id is a parameter defines the parameter's value; one whose parameter sphdeck
    // cannot read (not defined before it, a character one) may define any id: TMID not judged.
    CHECK(count_code(thermal_deck("7", 1, by_parameter).diagnostics, "REF004") == 0);
    CHECK(count_code(thermal_deck("3", 1, by_parameter).diagnostics, "REF004") == 1);
    const std::string by_unknown = "*MAT_THERMAL_ISOTROPIC\n    &tmidq    1000.0\n    4180.0       0.6\n";
    CHECK(count_code(thermal_deck("3", 1, by_unknown).diagnostics, "REF004") == 0);
    const std::string by_text =
        "*PARAMETER\nC   tmidc    steel\n*MAT_THERMAL_ISOTROPIC\n    &tmidc    1000.0\n    4180.0       0.6\n";
    CHECK(count_code(thermal_deck("3", 1, by_text).diagnostics, "REF004") == 0);
    // Material 3 exists as a structural material: a thermal material 3 is still missing, and MID 3 missing too
    // is a finding of its own (the ids of the two kinds are apart).
    CHECK(count_code(thermal_deck("3", 1, "*MAT_NULL\n         3    1000.0\n").diagnostics, "REF004") == 1);
    auto both = thermal_deck("1", 1);
    CHECK(count_code(both.diagnostics, "REF004") == 1);  // TMID 1 (MID 1 is defined)
}

TEST_CASE("references: the letter O in a TMID is said so, with an unsafe fix that writes the digit") {
    for (const char* written : {"O", "1O", "o"}) {
        CAPTURE(written);
        const auto r = thermal_deck(written, -1);
        REQUIRE(count_code(r.diagnostics, "REF004") == 1);
        const diag::Diagnostic* d = test::find_code(r.diagnostics, "REF004");
        CHECK(d->severity == diag::Severity::Warning);
        const std::string digits = std::string(written) == "1O" ? "10" : "0";
        CHECK(d->message.find(fmt::format("(the letter O for the digit 0: {} meant?)", digits)) != std::string::npos);
        REQUIRE(d->fixes.size() == 1);
        CHECK_FALSE(d->fixes[0].safe);
        REQUIRE(d->fixes[0].edits.size() == 1);
        CHECK(d->fixes[0].edits[0].replacement == digits);
        CHECK(d->fixes[0].edits[0].span.end_column == 81);
        CHECK(d->fixes[0].edits[0].span.column == 81 - std::string(written).size());
    }
    // A label that is no letter-O slip: reported, without the fix.
    const auto label = thermal_deck("hot", -1);
    REQUIRE(count_code(label.diagnostics, "REF004") == 1);
    CHECK(test::find_code(label.diagnostics, "REF004")->fixes.empty());
}
}  // namespace test_references_cpp
