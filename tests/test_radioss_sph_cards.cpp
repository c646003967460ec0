// The OpenRadioss SPH cards read per format version from the starter's CFG files: /SPH/INOUT
// (radioss140/LOADS/sph_inout.cfg), /SPHGLO (radioss2017/CARDS/sphglo.cfg) and /INISPHCEL/FULL
// (radioss2025/TABLE/inisphcel_full*.cfg).
#include <doctest/doctest.h>
#include <string>

#include "engine/check.hpp"
#include "model/radioss_builder.hpp"
#include "model/radioss_decoder.hpp"
#include "model/radioss_facts.hpp"
#include "test_support.hpp"

namespace test_radioss_sph_cards_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;

namespace {

std::string i10(const std::string& v) { return std::string(v.size() < 10 ? 10 - v.size() : 0, ' ') + v; }
std::string r20(const std::string& v) { return std::string(v.size() < 20 ? 20 - v.size() : 0, ' ') + v; }

std::string deck(const std::string& body, int version = 2026) {
    return "#RADIOSS STARTER\n/BEGIN\nrun\n" + i10(std::to_string(version)) + "\n" + body + "/END\n";
}

engine::CheckResult check(const std::string& text) {
    return engine::check_buffer(text, "deck_0000.rad", {}, grammar::DeckFormat::Radioss);
}

const model::RadiossFacts& facts(const engine::CheckResult& r) {
    REQUIRE(r.model.radioss.has_value());
    return *r.model.radioss;
}

// An outlet through three nodes with a cut-off frequency (card 1 of FORMAT(radioss140)).
const std::string kInout = "/SPH/INOUT/4\noutlet\n" + i10("2") + i10("2") + i10("0") + r20("2.5") + i10("11") +
                           i10("12") + i10("13") + r20("500.0") + "\n" + std::string(30, ' ') + i10("0") + r20("1.0") +
                           "\n\n";

}  // namespace

TEST_CASE("radioss sph cards: /SPH/INOUT reads node_ID1-3 and Fcut from format 140 on") {
    auto r = check(deck(kInout));
    REQUIRE(facts(r).inouts.size() == 1);
    const auto& io = facts(r).inouts[0];
    CHECK(io.id == 4);
    CHECK(io.itype.value == 2);
    CHECK(io.dist.value == 2.5);
    CHECK(io.nodes[0].value == 11);
    CHECK(io.nodes[2].value == 13);
    CHECK(io.fcut.value == 500.0);
    CHECK(count_code(r.diagnostics, "DK006") == 0);
    // Format 110 reads four fields: the nodes are text past the card's end, as in the starter.
    auto old = check(deck(kInout, 110));
    REQUIRE(facts(old).inouts.size() == 1);
    CHECK(facts(old).inouts[0].nodes[0].value == 0);
    CHECK(facts(old).inouts[0].dist.value == 2.5);
    CHECK(count_code(old.diagnostics, "DK006") == 1);
}

TEST_CASE("radioss sph cards: /SPH/INOUT ids are checked as the starter checks them") {
    auto r = check(deck(kInout));
    CHECK(count_code(r.diagnostics, "REF002") == 1);  // no /PART 2 (error 437)
    CHECK(count_code(r.diagnostics, "REF001") == 3);  // no nodes 11-13 (error 78)
}

TEST_CASE("radioss sph cards: /SPHGLO Isol2sph 0 or absent is 1 (hm_read_sphglo.F)") {
    CHECK(facts(check(deck("/SPHGLO\n" + r20("0.25") + i10("0") + i10("0") + i10("0") + i10("0") + "\n")))
              .sph_global.isol2sph.value == 1);
    CHECK(facts(check(deck("/SPHGLO\n" + r20("0.25") + i10("0") + i10("0") + i10("0") + i10("2") + "\n")))
              .sph_global.isol2sph.value == 2);
    CHECK(facts(check(deck(""))).sph_global.isol2sph.value == 1);
    // Format 120 has no Isol2sph cell: what stands there is past the card's end.
    auto v120 = check(deck("/SPHGLO\n" + r20("0.25") + i10("0") + i10("0") + i10("200") + i10("2") + "\n", 120));
    CHECK(facts(v120).sph_global.isol2sph.value == 1);
    CHECK(facts(v120).sph_global.nneigh.value == 200);
    CHECK(count_code(v120.diagnostics, "DK006") == 1);
}

TEST_CASE("radioss sph cards: /INISPHCEL/FULL states, their LIST of nvarsph values skipped by count") {
    const std::string state_a = i10("1001") + i10("7") + "\n" + r20("5.0") + r20("1.0E-6") + r20("2.4") + "\n" +
                                r20("-1.0") + r20("-2.0") + r20("-3.0") + "\n" + r20("0.1") + "\n" + r20("1") +
                                r20("2") + r20("3") + r20("4") + r20("5") + "\n" + r20("6") + r20("7") + "\n";
    const std::string state_b = i10("1002") + i10("0") + "\n" + r20("6.0") + r20("2.0E-6") + r20("3.0") + "\n" +
                                r20("-4.0") + "\n" + r20("0.2") + "\n";
    const std::string sph = "/NODE\n" + i10("1001") + r20("0") + r20("0") + r20("0") + "\n" + i10("1002") + r20("1") +
                            r20("0") + r20("0") + "\n/SPHCEL/2\n" + i10("1001") + "\n" + i10("1002") + "\n";
    auto r = check(deck(sph + "/INISPHCEL/FULL\n" + state_a + state_b + i10("1003") + i10("0") + "\n"));
    const auto& s = facts(r).initial_states;
    REQUIRE(s.size() == 3);
    CHECK(s[0].cell == 1001);
    CHECK(s[0].nvar == 7);
    CHECK(s[0].rho == 1.0E-6);
    CHECK(s[0].sigma[2] == -3.0);
    CHECK(s[0].epsp == 0.1);
    CHECK(s[1].cell == 1002);  // after the two lines of values of the first state
    CHECK(s[1].eint == 6.0);
    CHECK(s[1].h == 3.0);
    CHECK(s[1].sigma[0] == -4.0);
    CHECK(s[1].epsp == 0.2);  // no value line with nvarsph 0
    CHECK(s[2].cell == 1003);
    CHECK(count_code(r.diagnostics, "REF001") == 1);  // 1003 is no particle (warning 3045)
    CHECK(count_code(r.diagnostics, "DK006") == 0);
    // Another kind than FULL is not read by the starter (CASE DEFAULT).
    CHECK(facts(check(deck(sph + "/INISPHCEL/OTHER\n" + state_b))).initial_states.empty());
}

TEST_CASE("radioss sph cards: /SPH/INOUT reads the cards of its Itype (sph_inout.cfg, hm_read_sphio.F)") {
    const std::string blank30(30, ' ');
    // Itype 1, an inlet through a surface: density and energy functions, then the velocity's.
    const std::string inlet = "/SPH/INOUT/1\ninlet\n" + i10("1") + i10("2") + i10("5") + r20("1.5") + "\n" + i10("11") +
                              r20("0") + blank30 + i10("12") + r20("2.0") + "\n" + i10("13") + "\n";
    // Itype 3 from format 140 without surface or nodes: the points M, M1, M2, then its card.
    const std::string frontier = "/SPH/INOUT/2\nfrontier\n" + i10("3") + i10("2") + i10("0") + r20("1.0") + "\n" +
                                 r20("0") + r20("0") + r20("0") + "\n" + r20("1") + r20("0") + r20("0") + "\n" +
                                 r20("0") + r20("1") + r20("4.5") + "\n" + blank30 + i10("7") + r20("0") + r20("0.5") +
                                 "\n\n";
    auto r = check(deck(inlet + frontier));
    REQUIRE(facts(r).inouts.size() == 2);
    const auto& in = facts(r).inouts[0];
    CHECK(in.density_function.value == 11);
    CHECK(in.density_scale.value == 1.0);  // 0 with a function: 1
    CHECK(in.energy_function.value == 12);
    CHECK(in.energy_scale.value == 2.0);
    CHECK(in.velocity_function.value == 13);
    CHECK(!in.by_points);
    const auto& nrf = facts(r).inouts[1];
    CHECK(nrf.by_points);
    CHECK(nrf.points[1][0].value == 1.0);
    CHECK(nrf.points[2][2].value == 4.5);
    CHECK(nrf.pressure_function.value == 7);
    CHECK(nrf.pressure_scale.value == 1.0);
    CHECK(nrf.length.value == 0.5);
    CHECK(count_code(r.diagnostics, "DK006") == 0);
    CHECK(count_code(r.diagnostics, "DK002") == 0);

    // Format 110 has no points: the Itype 3 card follows card 1.
    const std::string old = "/SPH/INOUT/3\nfrontier\n" + i10("3") + i10("2") + i10("0") + r20("1.0") + "\n" + blank30 +
                            i10("8") + r20("3.0") + r20("0.25") + "\n\n";
    auto v110 = check(deck(old, 110));
    REQUIRE(facts(v110).inouts.size() == 1);
    CHECK(!facts(v110).inouts[0].by_points);
    CHECK(facts(v110).inouts[0].pressure_function.value == 8);
    CHECK(facts(v110).inouts[0].pressure_scale.value == 3.0);
    CHECK(facts(v110).inouts[0].length.value == 0.25);
}

TEST_CASE("radioss sph cards: /SPH/INOUT surf_ID is checked against the /SURF headers (starter error 438)") {
    const std::string inout = "/SPH/INOUT/1\noutlet\n" + i10("2") + i10("2") + i10("7") + r20("1.0") + "\n";
    const std::string part = "/PART/2\nwater\n" + i10("2") + i10("3") + "\n";
    CHECK(count_code(check(deck(part + inout)).diagnostics, "REF008") == 1);
    CHECK(count_code(check(deck(part + "/SURF/SEG/7\nface\n" + inout)).diagnostics, "REF008") == 0);
    CHECK(count_code(check(deck(part + inout + "/SURF/PART/EXT/7\nskin\n" + i10("2") + "\n")).diagnostics, "REF008") ==
          0);
    // A /SURF header whose id cannot be read: surface ids are not checked.
    CHECK(count_code(check(deck(part + "/SURF/PART\nno id\n" + inout)).diagnostics, "REF008") == 0);
}
}  // namespace test_radioss_sph_cards_cpp

namespace test_radioss_sph_cards_cpp {

// A fuzzer's /MAT/LAW6444444444444444 overflowed the int the law is read into (UBSan at CI).
TEST_CASE("radioss sph cards: a /MAT/LAW number is read only as long as a law can be") {
    CHECK(model::radioss_law("LAW6") == 6);
    CHECK(model::radioss_law("LAW006") == 6);
    CHECK(model::radioss_law("LAW151") == 151);
    CHECK(model::radioss_law("HYD_VISC") == 6);
    CHECK(model::radioss_law("LAW") == -1);
    CHECK(model::radioss_law("LAW6x") == -1);
    CHECK(model::radioss_law("LAW6444444444444444") == -1);
    CHECK(model::radioss_law("LAW2147483648") == -1);
    // The whole deck: read without a crash, the material's law unknown.
    const auto r = check(deck("/MAT/LAW6444444444444444/3\nwater\n      1000       0.0\n"));
    CHECK(r.model.radioss.has_value());
}

// An Invers the starter's 32-bit integer cannot hold is no version: not one its low bits make.
TEST_CASE("radioss sph cards: an Invers past an int is read as no version") {
    CHECK(model::radioss_version(check(deck("", 2017)).deck) == 2017);
    CHECK(model::radioss_version(check(deck("", 44)).deck) == 44);
    const int latest = model::radioss_version(check("#RADIOSS STARTER\n/END\n").deck);
    CHECK(model::radioss_version(check(deck("", 0)).deck) == latest);
    CHECK(model::radioss_version(check("#RADIOSS STARTER\n/BEGIN\nrun\n4294967298\n/END\n").deck) == latest);
}

}  // namespace test_radioss_sph_cards_cpp
