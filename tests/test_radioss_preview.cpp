// The Radioss preview (docs/radioss.md): initial h as spinih.F computes it, the symmetry mass
// split, ghost counts per plane, particle and nodal time steps, and the JSON of `sphdeck smooth`
// (same keys as for an LS-DYNA deck). Expected values are computed by hand in the comments.
#include <doctest/doctest.h>

#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <set>

#include "engine/check.hpp"
#include "preproc/preview.hpp"
#include "preproc/radioss_formulas.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_radioss_preview_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

const std::string kDecks = std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/rad/preview/";

struct Loaded {
    engine::CheckResult result;
    preproc::Preview preview;
};

Loaded load(const std::string& path) {
    Loaded l{engine::check_file(path), {}};
    REQUIRE(l.result.model.radioss.has_value());
    l.preview = preproc::compute_preview(l.result.model);
    REQUIRE(l.preview.radioss.has_value());
    return l;
}

double h_of(const Loaded& l, long long node) {
    const auto& p = l.result.model.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.node[i] == node) return l.preview.particles.h[i];
    FAIL("no particle ", node);
    return 0;
}

const preproc::PartPreview& part(const Loaded& l, long long id) {
    for (const auto& pv : l.preview.parts)
        if (pv.part == id) return pv;
    FAIL("no part ", id);
    return l.preview.parts.front();
}

std::set<std::string> keys(const nlohmann::json& j) {
    std::set<std::string> out;
    for (auto it = j.begin(); it != j.end(); ++it) out.insert(it.key());
    return out;
}

}  // namespace

TEST_CASE("radioss preview: formulas of spinih.F and inspcnd.F") {
    // (sqrt2 V)^(1/3): V = sqrt2 gives 2^(1/3), V = 2 gives 2^(1/2).
    CHECK(preproc::radioss_h_from_volume(std::sqrt(2.0)) == doctest::Approx(std::cbrt(2.0)));
    CHECK(preproc::radioss_h_from_volume(2.0) == doctest::Approx(std::sqrt(2.0)));
    CHECK(preproc::radioss_h_from_volume(0.0) == 0.0);
    // Property h wins for a cell without mass; a cell's own mass or volume ignores it.
    CHECK(preproc::radioss_cell_h(0, 0, true, 0.7, 2.0, 1.0).h == 0.7);
    CHECK(preproc::radioss_cell_h(0, 0, true, 0.0, 2.0, 1.0).h == doctest::Approx(std::sqrt(2.0)));
    CHECK(preproc::radioss_cell_h(1, 4.0, false, 0.7, 2.0, 1.0).h == doctest::Approx(std::pow(2.0, 5.0 / 6)));
    CHECK(preproc::radioss_cell_h(2, 2.0, false, 0.7, 2.0, 1000.0).h == doctest::Approx(std::sqrt(2.0)));
    CHECK(preproc::radioss_cell_h(1, 4.0, false, 0.0, 2.0, 0.0).source == preproc::RadiossHSource::Unknown);
    // m / (1 + n): 1/2, 1/3, 1/4 on one, two, three planes (not m / n, not m / 2^n).
    CHECK(preproc::radioss_symmetry_mass(1.0, 0) == 1.0);
    CHECK(preproc::radioss_symmetry_mass(1.0, 1) == 0.5);
    CHECK(preproc::radioss_symmetry_mass(1.0, 2) == doctest::Approx(1.0 / 3));
    CHECK(preproc::radioss_symmetry_mass(1.0, 3) == 0.25);
    // On the plane: dd < 1e-3 h_ref, negative dd included.
    CHECK(preproc::radioss_on_plane(0.0009, 1.0));
    CHECK_FALSE(preproc::radioss_on_plane(0.001, 1.0));
    CHECK(preproc::radioss_on_plane(-5.0, 1.0));
    CHECK(preproc::radioss_symmetry_reference_h(0.0, 2.0, 1.0) == doctest::Approx(std::sqrt(2.0)));
    // Ghosts: documented d^2 <= 1.25 (h_i + h_j)^2; coded dd <= sqrt(1.25) (h_i + h_max).
    CHECK(preproc::radioss_ghost_documented(2.2, 1.0, 1.0, 0.25));  // 2.2 <= 2.236
    CHECK_FALSE(preproc::radioss_ghost_documented(2.3, 1.0, 1.0, 0.25));
    CHECK(preproc::radioss_ghost_documented(-2.2, 1.0, 1.0, 0.25));  // unsigned
    CHECK(preproc::radioss_ghost_coded(-50.0, 1.0, 1.0, 0.25));      // signed: the wrong side always
    CHECK_FALSE(preproc::radioss_ghost_coded(2.3, 1.0, 1.0, 0.25));
    // Nodal step with the starter's stiffness 2 m / dt^2: DTsca dt.
    const double k = preproc::radioss_particle_stiffness(3.0, 0.01);
    CHECK(k == doctest::Approx(2 * 3.0 / 1e-4));
    CHECK(preproc::radioss_nodal_time_step(0.67, 3.0, k) == doctest::Approx(0.0067));
}

TEST_CASE("radioss preview: h from the property, the cell mass or volume, and h_1D 3") {
    const Loaded l = load(kDecks + "h_rules.rad");
    // rho = 1 (h_rules.rad): (sqrt2 m)^(1/3).
    CHECK(h_of(l, 1) == doctest::Approx(std::pow(2.0, 1.0 / 6)));   // mp 1 of the property
    CHECK(h_of(l, 2) == doctest::Approx(std::sqrt(2.0)));           // Type 1, MASS 2
    CHECK(h_of(l, 3) == doctest::Approx(std::pow(2.0, -1.0 / 6)));  // Type 0 with MASS 0.5
    CHECK(h_of(l, 4) == doctest::Approx(std::pow(2.0, 1.0 / 6)));   // Type 2, volume 1
    CHECK(h_of(l, 11) == doctest::Approx(0.7));                     // property h
    CHECK(h_of(l, 12) == doctest::Approx(std::sqrt(2.0)));          // own mass: property h ignored
    for (long long n = 101; n <= 127; ++n) CHECK(h_of(l, n) == doctest::Approx(1.5 * 0.5));  // hcst x spacing

    const auto& p1 = part(l, 1);
    REQUIRE(p1.radioss);
    CHECK(p1.radioss->cells_from_property == 1);
    CHECK(p1.radioss->cells_with_mass == 2);
    CHECK(p1.radioss->cells_with_volume == 1);
    // Masses as the starter takes them: 1 + 2 + 0.5 + rho 1 x volume 1.
    CHECK(p1.mass_total == doctest::Approx(4.5));
    // h0: the median of 2^(-1/6), 2^(1/6), 2^(1/6), 2^(1/2).
    CHECK(p1.h0 == doctest::Approx(std::pow(2.0, 1.0 / 6)));
    CHECK(p1.h_min == 0.0);  // h_1D 0: unbounded
    const auto& p3 = part(l, 3);
    CHECK(p3.h0 == doctest::Approx(0.75));
    CHECK(p3.h_min == doctest::Approx(0.5 * 0.75));
    CHECK(p3.h_max == doctest::Approx(3.0 * 0.75));
    CHECK(p3.radioss->h_1d == 3);
    CHECK(p3.support == doctest::Approx(1.5));
    // The centre of the 3x3x3 lattice has all 26 others within 2h = 1.5 (the farthest at 0.5 sqrt3).
    CHECK(p3.neighbours.max == 26);
    CHECK(p3.mass_total == doctest::Approx(27 * 0.125));
}

TEST_CASE("radioss preview: mass on one, two and three symmetry planes, ghosts per plane") {
    const Loaded l = load(kDecks + "symmetry_corner.rad");
    const auto& p1 = part(l, 1);
    REQUIRE(p1.radioss);
    const auto& r = *p1.radioss;
    // 5x5x5 lattice, coordinates 0..4 with planes x = 0, y = 0, z = 0: 4^3 = 64 inside, 3 x 4^2 = 48
    // on one face, 3 x 4 = 12 on an edge, 1 at the corner.
    CHECK(r.on_planes[0] == 64);
    CHECK(r.on_planes[1] == 48);
    CHECK(r.on_planes[2] == 12);
    CHECK(r.on_planes[3] == 1);
    CHECK(r.mass_before == doctest::Approx(125.0));
    CHECK(r.mass_after == doctest::Approx(64 + 48 / 2.0 + 12 / 3.0 + 1 / 4.0));  // 92.25
    CHECK(p1.mass_total == doctest::Approx(92.25));
    CHECK(h_of(l, 1) == doctest::Approx(std::pow(2.0, 1.0 / 6)));
    const auto& g = *l.preview.radioss;
    REQUIRE(g.planes.size() == 3);
    for (const auto& plane : g.planes) CHECK(plane.on_plane == 25);
    CHECK(g.alpha_sort == 0.25);
    CHECK(g.h_max == doctest::Approx(3.0));
    // Documented: |dd| <= sqrt(1.25) x 2 x 2^(1/6) = 2.51: layers 0, 1, 2 = 75 particles per plane.
    // Coded: dd <= sqrt(1.25) (2^(1/6) + h_max 3) = 4.61: all 125. Part 2 (at 100) creates none.
    for (std::size_t k = 0; k < 3; ++k) {
        CHECK(r.ghosts[k] == 75);
        CHECK(r.ghosts_coded[k] == 125);
        CHECK(g.planes[k].ghosts == 75);
        CHECK(g.planes[k].ghosts_coded == 125);
        CHECK(part(l, 2).radioss->ghosts[k] == 0);
    }
    CHECK(part(l, 2).radioss->mass_after == 1.0);
    // The particle step at rest, qb = 1, no engine deck: 0.9 h / (c (1 + sqrt2)), c = sqrt(100 / 1).
    CHECK(p1.sound_speed == doctest::Approx(10.0));
    CHECK(r.dt_particle == doctest::Approx(0.9 * std::pow(2.0, 1.0 / 6) / (10 * (1 + std::sqrt(2.0)))));
    CHECK(part(l, 2).radioss->dt_particle == doctest::Approx(0.9 * 3 / (10 * (1 + std::sqrt(2.0)))));
    CHECK(r.dt_nodal == 0.0);  // no /DT/NODA
}

TEST_CASE("radioss preview: /DT/SPHCEL and /DT/NODA scales of the engine deck") {
    test::TempDir dir;
    const std::string starter = R"(#RADIOSS STARTER
/BEGIN
run
      2026
/PART/1
p
         1         1         0
/PROP/SPH/1
p
                 8.0                 2.0                 0.5                 0.0         0         0
         0                 0.0                 0.0
/MAT/LAW1/1
m
                 4.0
               400.0                 0.0
/NODE
         1                 0.0                 0.0                 0.0
         2                 5.0                 0.0                 0.0
/SPHCEL/1
         1         0
         2         1                16.0
/END
)";
    const std::string path = dir.write("run_0000.rad", starter);
    dir.write("run_0001.rad", "/RUN/run/1\n  1.0\n/DT/SPHCEL/STOP\n 0.3 1.0E-9\n/DT/NODA/CST\n0.67 0.0\n/END\n");
    const Loaded l = load(path);
    const auto& g = *l.preview.radioss;
    CHECK(g.engine_deck);
    CHECK(g.dt_scale_particle == 0.3);
    CHECK(g.nodal);
    CHECK(g.dt_scale_nodal == 0.67);
    // rho 4, c = sqrt(400 / 4) = 10; node 1: h = (sqrt2 x 8 / 4)^(1/3) = (2 sqrt2)^(1/3) = sqrt2;
    // node 2: (sqrt2 x 16 / 4)^(1/3) = (4 sqrt2)^(1/3) = 2^(5/6). qb 0.5: qb + sqrt(qb^2 + 1) = 1.618.
    const double factor = 10 * (0.5 + std::sqrt(1.25));
    CHECK(h_of(l, 1) == doctest::Approx(std::sqrt(2.0)));
    const auto& r = *part(l, 1).radioss;
    CHECK(r.qb == 0.5);
    CHECK(r.dt_particle == doctest::Approx(0.3 * std::sqrt(2.0) / factor));
    // Nodal: 0.67 sqrt(2 m / K), K = 2 m / dt^2 with dt the unscaled particle step: 0.67 h / factor.
    CHECK(r.dt_nodal == doctest::Approx(0.67 * std::sqrt(2.0) / factor));
}

TEST_CASE("radioss preview: sphdeck smooth JSON has the LS-DYNA keys plus 'radioss'") {
    test::TempDir dir;
    const auto rad = test::run_sphdeck(dir, "smooth --format json '" + kDecks + "symmetry_corner.rad'");
    const auto dyna = test::run_sphdeck(dir, "smooth --format json '" + std::string(SPHDECK_SOURCE_DIR) +
                                                 "/decks/tests/preview/SPH113_silent.k'");
    REQUIRE(rad.exit_code == 0);
    REQUIRE(dyna.exit_code == 0);
    const auto a = nlohmann::json::parse(rad.out), b = nlohmann::json::parse(dyna.out);
    std::set<std::string> top = keys(a);
    CHECK(top.erase("radioss") == 1);
    CHECK(top == keys(b));
    REQUIRE(!a["parts"].empty());
    REQUIRE(!b["parts"].empty());
    std::set<std::string> per_part = keys(a["parts"][0]);
    CHECK(per_part.erase("radioss") == 1);
    CHECK(per_part == keys(b["parts"][0]));
    CHECK(a["parts"][0]["radioss"]["mass_after_symmetry"].get<double>() == doctest::Approx(92.25));
    CHECK(a["radioss"]["planes"].size() == 3);

    const auto table = test::run_sphdeck(dir, "smooth '" + kDecks + "symmetry_corner.rad' --csv p.csv");
    CHECK(table.exit_code == 0);
    CHECK(table.out.find("mass 125 before the symmetry split, 92.25 after") != std::string::npos);
    std::ifstream csv(dir.path() / "p.csv");
    std::string header;
    std::getline(csv, header);
    CHECK(header.find(",planes") != std::string::npos);
}

namespace {

// A 3 x 3 x 3 lattice of pitch 1 whose cells take the property's mass; `card2` is the /PROP/SPH
// Order, h, Xi_Stab line (empty: no such line). Few neighbours either way: SPH118.
engine::CheckResult sparse_lattice(const std::string& mp, const std::string& card2) {
    std::string s =
        "#RADIOSS STARTER\n/BEGIN\nsparse\n      2026\n"    // lines 1-4
        "/PART/2\nwater\n         2         3         0\n"  // lines 5-7
        "/PROP/SPH/2\nwater particles\n" +                  // lines 8-9
        fmt::format("{:>20}                 0.0                 0.0                 0.0         0         0\n",
                    mp) +  // line 10
        card2 +            // line 11 when given
        "/MAT/LAW6/3\nwater\n              1.0E-6\n/NODE\n";
    long long id = 1;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                s += fmt::format("{:>10}{:>20.1f}{:>20.1f}{:>20.1f}\n", id++, i * 1.0, j * 1.0, k * 1.0);
    s += "/SPHCEL/2\n";
    for (long long n = 1; n < id; ++n) s += fmt::format("{:>10}         0\n", n);
    return engine::check_buffer(s + "/END\n", "sparse_0000.rad", {}, grammar::DeckFormat::Radioss);
}

}  // namespace

TEST_CASE("radioss preview: SPH118 points at the /PROP/SPH h field, or its header when h is blank") {
    // h = 0.4 given: the h cell of card 2 (columns 11-30, the value right-aligned).
    auto given = sparse_lattice("1.0E-6", "         0                 0.4                 0.0\n");
    const diag::Diagnostic* d = test::find_code(given.diagnostics, "SPH118");
    REQUIRE(d != nullptr);
    CHECK(given.deck.sources.file(d->span.file).display_name == "sparse_0000.rad");
    CHECK(d->span.line == 11);
    CHECK(d->span.column == 28);
    CHECK(d->span.end_column == 31);

    // h left blank (no card 2): h = (sqrt2 mp / rho)^(1/3) = 0.11 from mp 1e-9, rho 1e-6; the header.
    auto blank = sparse_lattice("1.0E-9", "");
    d = test::find_code(blank.diagnostics, "SPH118");
    REQUIRE(d != nullptr);
    CHECK(d->span.valid());
    CHECK(d->span.line == 8);
    CHECK(d->span.column == 1);
}

TEST_CASE("radioss preview: symmetry planes of a translated and rotated /FRAME/FIX (Y' and Z' given)") {
    // frame_rotated.rad: a 2 x 3 x 4 lattice at O + i X' + j Y' + k Z', O = (10, 20, 30),
    // X' = (0.6, 0.8, 0), Y' = (-0.8, 0.6, 0), Z' = (0, 0, 1); the frame card gives Y' as (-4, 3, 0)
    // and Z' as (0, 0, 5), and X' = Y' x Z'. Planes: Dir X (i = 0: 12 particles) and Dir Z (k = 0:
    // 6), 3 on both. By hand: 9 + 12 / 2 + 3 / 3 = 16 with mp 1; read as X' and Y' it would be 15.33.
    const Loaded l = load(kDecks + "frame_rotated.rad");
    const auto& frame = *l.result.model.radioss->frame(5);
    REQUIRE(frame.geometry);
    CHECK(frame.axes[0][0] == doctest::Approx(0.6));
    CHECK(frame.axes[0][1] == doctest::Approx(0.8));
    CHECK(frame.axes[1][0] == doctest::Approx(-0.8));
    CHECK(frame.axes[1][1] == doctest::Approx(0.6));
    CHECK(frame.axes[2][2] == doctest::Approx(1.0));
    const auto& r = *part(l, 1).radioss;
    CHECK(r.on_planes[0] == 9);
    CHECK(r.on_planes[1] == 12);
    CHECK(r.on_planes[2] == 3);
    CHECK(r.mass_before == doctest::Approx(24.0));
    CHECK(r.mass_after == doctest::Approx(16.0));
    CHECK(part(l, 1).mass_total == doctest::Approx(16.0));
    CHECK(test::count_code(l.result.diagnostics, "RAD008") == 0);
}
}  // namespace test_radioss_preview_cpp
