// Radioss card layouts as the starter's CFG files give them per deck version
// (hm_cfg_files/config/CFG/radiossNNNN/...), and the cards sphdeck does not read: no finding on
// their fields. Each case is a pattern of a starter-accepted QA deck of the corpus.
#include <doctest/doctest.h>

#include "grammar/read_deck.hpp"
#include "engine/check.hpp"
#include "test_support.hpp"

namespace test_radioss_layouts_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;

namespace {

std::string i10(const std::string& v) { return std::string(v.size() < 10 ? 10 - v.size() : 0, ' ') + v; }
std::string r20(const std::string& v) { return std::string(v.size() < 20 ? 20 - v.size() : 0, ' ') + v; }

std::string deck(const std::string& body, int version) {
    return "#RADIOSS STARTER\n/BEGIN\nrun\n" + i10(std::to_string(version)) + "\n" + body + "/END\n";
}

engine::CheckResult check(const std::string& text) {
    return engine::check_buffer(text, "deck_0000.rad", {}, grammar::DeckFormat::Radioss);
}

std::size_t warnings_and_errors(const engine::CheckResult& r) {
    std::size_t n = 0;
    for (const auto& d : r.diagnostics) n += d.severity != diag::Severity::Info;
    return n;
}

const model::RadiossFacts& facts(const engine::CheckResult& r) {
    REQUIRE(r.model.radioss.has_value());
    return *r.model.radioss;
}

}  // namespace

TEST_CASE("radioss layouts: /BEGIN reads the input and work unit lines from format 100") {
    for (int version : {100, 2017, 2019, 2026}) {
        const std::string units = r20("kg") + r20("mm") + r20("ms") + "\n" + r20("g") + r20("m") + r20("s") + "\n";
        auto r = check(deck(units, version));
        CAPTURE(version);
        CHECK(count_code(r.diagnostics, "DK009") == 0);
        CHECK(facts(r).input_units[1] == "mm");
        CHECK(facts(r).work_units[0] == "g");
    }
    // Text after Irun: the starter reads it silently (QA SUBMODEL/update_v_100 FAIL deck).
    auto r = check("#RADIOSS STARTER\n/BEGIN\nrun\n       100         0                   1\n/END\n");
    CHECK(count_code(r.diagnostics, "DK006") == 0);
    // Version 51 has no unit lines: two more lines are extra.
    CHECK(count_code(check(deck(r20("kg") + "\n" + r20("kg") + "\n", 51)).diagnostics, "DK009") == 1);
}

TEST_CASE("radioss layouts: /MAT reads the density and E, nu where it knows the law; the rest is not checked") {
    // LAW2 (matl2_plas_johns.cfg 2025): E nu Iflag VP Pmin on card 2 (a 2019 deck reads format 140's E nu
    // Iflag: VP is text past the card, read by nobody), then a, b, n when Iflag is not 1.
    const std::string plas = "/MAT/PLAS_JOHNS/1\nsteel\n" + r20("7.8E-9") + r20("0") + "\n" + r20("210000") +
                             r20("0.3") + i10("2") + i10("0") + "\n" + r20("250") + r20("300") + r20("0.3") + "\n";
    // LAW44 in a 2017 deck (QA LOI44): card 4 `%20lg%20lg%10d%10d%20lg` is no row of five reals.
    const std::string cowper =
        "/MAT/COWPER/2\nc\n     0.780000000E-02      0.00000000\n      2.05000000E+05"
        "          0.3\n        400.0                 5.0                  1         0       "
        ".000000000E00\n";
    // LAW30 (its CFG reads free text lines): integers in what a 20-wide grid would cut as one cell.
    const std::string law30 = "/MAT/LAW30/3\nx\n" + r20("1.0") + "\n" + i10("7") + i10("7") + i10("0") + "\n";
    // Gas and multi-material laws have no density card (mat_gas.cfg, mat_law51.cfg).
    const std::string gas = "/MAT/GAS/PREDEF/4\nInitial gaz\nAIR\n";
    const std::string law51 = "/MAT/LAW51/5\nmm\n" + i10("0") + "  " + i10("1") + i10("2") + "\n";
    auto r = check(deck(plas + cowper + law30 + gas + law51, 2019));
    CHECK(warnings_and_errors(r) == 0);
    const auto& f = facts(r);
    REQUIRE(f.material(1) != nullptr);
    CHECK(f.material(1)->young == 210000);
    CHECK(f.material(1)->poisson == 0.3);
    CHECK(f.material(1)->density == 7.8E-9);
    CHECK(f.material(2)->young == 2.05E5);
    CHECK(f.material(3)->density == 1.0);
    REQUIRE(f.material(4) != nullptr);  // /MAT/GAS/<kind>/<id>: the id is the fourth segment
    CHECK(f.material(5) != nullptr);
}

TEST_CASE("radioss layouts: LAW6 and LAW3 carry C0-C3 up to format 2017 only") {
    const std::string law6 =
        "/MAT/HYD_VISC/1\nw\n" + r20("1.0") + "\n" + r20("0.0") + "\n" + r20("0") + r20("2.2E3") + "\n";
    CHECK(facts(check(deck(law6, 2017))).material(1)->bulk == 2.2E3);
    CHECK(facts(check(deck(law6, 2019))).material(1)->bulk == 0.0);  // 2018+: /EOS gives it
}

TEST_CASE("radioss layouts: /PROP/TYPE14 and /PROP/TYPE6 by format (prop_p14_solid.cfg, prop_p6_sol_orth.cfg)") {
    // 2017 (format 140): card 3 is dt_min Istrain Imod, no five reals; Iframe in cell 8.
    const std::string card1 = i10("0") + i10("0") + i10("") + i10("0") + i10("") + i10("0") + i10("0") + i10("2");
    const std::string solid = "/PROP/TYPE14/1\ns\n" + card1 + "\n" + r20("0") + r20("0") + r20("0") + "\n" + r20("0") +
                              i10("0") + i10("0") + "\n";
    auto r = check(deck(solid, 2017));
    CHECK(warnings_and_errors(r) == 0);
    CHECK(facts(r).solid_property(1)->iframe.value == 2);
    // The same card 3 in a 2023 deck is cut as five reals: two integers in the vdef_min cell.
    CHECK(count_code(check(deck(solid, 2023)).diagnostics, "RAD025") == 1);
}

TEST_CASE("radioss layouts: /EOS/POLYNOMIAL, /ANALY and /DEF_SOLID by format") {
    const std::string eos = "/EOS/POLYNOMIAL/1\np\n" + r20("0") + r20("1") + r20("0") + r20("0") + "\n" + r20("0") +
                            r20("0") + r20("0") + r20("0") + r20("1") + "\n";
    auto r = check(deck(eos, 2019));
    CHECK(warnings_and_errors(r) == 0);  // RHO_0 ends card 2 up to format 2022 (mat_EOS.cfg)
    CHECK(facts(r).eos.front().rho0 == 1.0);
    CHECK(count_code(check(deck(eos, 2023)).diagnostics, "DK006") == 1);  // 2023-2025: four fields
    auto a = check(deck("/ANALY\n" + i10("1") + i10("") + i10("1") + i10("0") + "\n", 2019));
    CHECK(warnings_and_errors(a) == 0);
    CHECK(facts(a).analysis == 1);
    // /DEF_SOLID (def_solid.cfg): Iframe in cell 8 in every format from 51.
    auto d = check(
        deck("/DEF_SOLID\n" + i10("14") + i10("") + i10("") + i10("") + i10("") + i10("") + i10("") + i10("1") + "\n",
             100));
    CHECK(facts(d).def_iframe == 1);
}

TEST_CASE("radioss layouts: /SKEW/FIX gives Y' and Z' (no origin before format 120); a blank one is global") {
    const std::string y_z = r20("0") + r20("0") + r20("1") + "\n" + r20("1") + r20("0") + r20("0") + "\n";
    auto r = check(deck("/SKEW/FIX/3\nold\n" + y_z + "/SKEW/FIX/4\nblank\n\n\n\n", 110));
    const auto& f = facts(r);
    REQUIRE(f.frames.size() == 2);
    // Y' = z, Z' = x: X' = Y' x Z' = y (hm_read_skw.F).
    CHECK(f.frames[0].axes[0][1] == doctest::Approx(1.0));
    CHECK(f.frames[0].axes[1][2] == doctest::Approx(1.0));
    CHECK(f.frames[0].axes[2][0] == doctest::Approx(1.0));
    // No x, z in Y' (no x, y in Z'): the global axis; a blank skew is the global system.
    CHECK(f.frames[1].geometry);
    CHECK(f.frames[1].axes[0][0] == doctest::Approx(1.0));
    CHECK(f.frames[1].axes[1][1] == doctest::Approx(1.0));
    CHECK(f.frames[1].axes[2][2] == doctest::Approx(1.0));
}

TEST_CASE("radioss layouts: a one-file deck (engine input, /END/ENGINE, starter input)") {
    // QA onefile_rad: the starter accepts it without a #RADIOSS STARTER line.
    auto r = check("# RADIOSS\n/RUN/run/1\n20.0\n/TFILE\n0.05\n/END/ENGINE\n/BEGIN\nrun\n      2022\n/END\n");
    CHECK(count_code(r.diagnostics, "RAD001") == 0);
    CHECK(count_code(r.diagnostics, "DK001") == 0);  // /RUN and /TFILE are read as engine keywords
    CHECK(count_code(check("# RADIOSS\n/BEGIN\nrun\n      2022\n/END\n").diagnostics, "RAD001") == 0);
    CHECK(count_code(check("/BEGIN\nrun\n      2022\n/END\n").diagnostics, "RAD001") == 1);
}

TEST_CASE("radioss layouts: /FRAME/MOV puts its Dir axis along N1N2 (hm_read_frm.F)") {
    const std::string nodes = "/NODE\n" + i10("1") + r20("0") + r20("0") + r20("0") + "\n" + i10("2") + r20("0") +
                              r20("0") + r20("2") + "\n" + i10("3") + r20("1") + r20("0") + r20("0") + "\n";
    const std::string frames = "/FRAME/MOV/1\nx\n" + i10("1") + i10("2") + i10("3") + i10("") + "\n/FRAME/MOV/2\ny\n" +
                               i10("1") + i10("2") + i10("3") + i10("Y") + "\n";
    auto r = check(deck(nodes + frames, 2026));
    const auto& f = facts(r);
    REQUIRE(f.frames.size() == 2);
    REQUIRE(f.frames[0].geometry);
    REQUIRE(f.frames[1].geometry);
    // Dir X: X' = N1N2 = +z, Z' = X' x N1N3 = +y, Y' = Z' x X' = +x.
    CHECK(f.frames[0].axes[0][2] == doctest::Approx(1.0));
    CHECK(f.frames[0].axes[2][1] == doctest::Approx(1.0));
    CHECK(f.frames[0].axes[1][0] == doctest::Approx(1.0));
    // Dir Y: Y' = +z, X' = Y' x N1N3 = +y, Z' = X' x Y' = +x.
    CHECK(f.frames[1].axes[1][2] == doctest::Approx(1.0));
    CHECK(f.frames[1].axes[0][1] == doctest::Approx(1.0));
    CHECK(f.frames[1].axes[2][0] == doctest::Approx(1.0));
}

TEST_CASE("radioss layouts: LAW2's cards after E and nu as matl2_plas_johns.cfg lays them out, by format and Iflag") {
    const auto law2 = [](const std::string& card2, const std::string& card3, const std::string& card4) {
        return "/MAT/PLAS_JOHNS/1\nsteel\n" + r20("7.8E-9") + "\n" + card2 + "\n" + card3 + "\n" + card4 + "\n";
    };
    const std::string abn = r20("250") + r20("300") + r20("0.3");
    const std::string rate = r20("0.01") + r20("1") + i10("1") + i10("0") + r20("0") + r20("0");
    // Clean in every format from 51 on (Chard from 100, Iflag from 140).
    for (int version : {51, 100, 140, 2019, 2023, 2025, 2026}) {
        CAPTURE(version);
        const std::string card2 = r20("210000") + r20("0.3") + (version >= 140 ? i10("0") : "");
        const std::string card4 = version >= 100 ? rate : rate.substr(0, 80);
        CHECK(warnings_and_errors(check(deck(law2(card2, abn, card4), version))) == 0);
    }
    // A letter O typed in a (card 3): the starter reads 25 of '25O' (its sscanf stops at the O), not the 250 meant.
    const std::string card2 = r20("210000") + r20("0.3") + i10("0");
    auto typo = check(deck(law2(card2, r20("25O") + r20("300") + r20("0.3"), rate), 2019));
    CHECK(count_code(typo.diagnostics, "DK003") == 1);
    // The starter's sscanf reads the number the cell begins with (hc_scan_double): the finding says so.
    for (const auto& d : typo.diagnostics)
        if (d.code == "DK003") CHECK(d.message.find("the starter reads 25 and ignores 'O'") != std::string::npos);
    // Iflag 1 reads SIG_Y, UTS, EUTS on card 3 (format 140 on): the same numbers, other names, still clean.
    auto uts = check(deck(law2(r20("210000") + r20("0.3") + i10("1"), abn, rate), 2019));
    CHECK(warnings_and_errors(uts) == 0);
    // Integers typed in 10-column cells where card 3 reads 20-column reals: RAD025, as for any such card.
    auto glued = check(deck(law2(card2, i10("2") + i10("0") + r20("1"), rate), 2019));
    CHECK(count_code(glued.diagnostics, "RAD025") == 1);
}
}  // namespace test_radioss_layouts_cpp

namespace test_radioss_layouts_cpp {
TEST_CASE("radioss layouts: the elastic-plastic laws read whole by their CFG cards (LAW4 HYD_JCOOK, LAW1 ELAST)") {
    // matl4_hyd_jcook.cfg 2018 on: density, E nu, A B n epsmax sigmax, Pmin, C EPS_DOT_0 M Tmelt Tmax, RHOCP.
    const auto jcook = [](const std::string& b) {
        return "/MAT/HYD_JCOOK/5\ncopper\n" + r20("8.93") + r20("8.93") + "\n" + r20("1.16") + r20(".35") + "\n" +
               r20(".004") + r20(b) + r20("1") + r20("0") + r20("0") + "\n" + r20("0") + "\n" + r20("0") + r20("0") +
               r20("0") + r20("1E30") + r20("1E30") + "\n" + r20("3.409E-5") + "\n";
    };
    const std::string elast = "/MAT/ELAST/6\nsteel\n" + r20("7.8E-9") + "\n" + r20("210000") + r20("0.3") + "\n";
    auto clean = check(deck(jcook(".001") + elast, 2019));
    CHECK(warnings_and_errors(clean) == 0);
    const auto& f = facts(clean);
    REQUIRE(f.material(5) != nullptr);
    CHECK(f.material(5)->density == 8.93);
    CHECK(f.material(5)->young == 1.16);
    CHECK(f.material(5)->poisson == 0.35);
    REQUIRE(f.material(6) != nullptr);
    CHECK(f.material(6)->young == 210000);
    // The letter O typed for a zero in B (the yield card, text not checked before): DK003 on its cell.
    auto typo = check(deck(jcook(".OO1") + elast, 2019));
    REQUIRE(count_code(typo.diagnostics, "DK003") == 1);
    for (const auto& d : typo.diagnostics)
        if (d.code == "DK003") {
            CHECK(d.span.line == 9);  // the yield card
            CHECK(d.message.find("the starter reads no number there") != std::string::npos);
        }
}

TEST_CASE("radioss layouts: a zero written across a cell's end after the cell's own zero changes no value") {
    // QA LOI44 44SLD8: Fcut's cell holds '0' and the head of '.000000000E00', whose '00' runs past column 80.
    // The starter reads the cell's first word (sscanf): 0, the value the zero would give.
    const auto cowper = [](const std::string& fcut_cell_start) {
        return "/MAT/COWPER/2\nc\n     0.780000000E-02      0.00000000\n      2.05000000E+05          0.3\n" +
               r20("180.0") + r20("450.0") + r20("0.5") + r20("1.0") + r20("300.0") +
               "\n        400.0                 5.0                  1" + fcut_cell_start + ".000000000E00\n";
    };
    CHECK(warnings_and_errors(check(deck(cowper("         0       "), 2017))) == 0);
    // A cell's first word that is no zero: the zero's head is dropped and the cell read as 5 (RAD030 says so).
    auto five = check(deck(cowper("         5       "), 2017));
    CHECK(count_code(five.diagnostics, "RAD030") == 1);
}
}  // namespace test_radioss_layouts_cpp
