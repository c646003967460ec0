// SOL2SPH particle generation (sph-algorithms.md §9, docs/radioss.md): layouts and counts, mass
// conservation on unit, distorted and twisted bricks and on tetras, bad elements, and the
// `sphdeck sol2sph` command. Expected volumes are computed by hand or by an independent quadrature.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "engine/check.hpp"
#include "preproc/sol2sph.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_sol2sph_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

using Vec = std::array<double, 3>;

std::string node_line(long long id, const Vec& x) {
    return fmt::format("{:>10}{:>20.17g}{:>20.17g}{:>20.17g}\n", id, x[0], x[1], x[2]);
}

// One solid part 1 (property 1, Ndir `ndir`) releasing into SPH part 2; density rho.
std::string deck(const std::vector<Vec>& nodes, const std::string& elements, int ndir, double rho = 2.0) {
    std::string s =
        "#RADIOSS STARTER\n/BEGIN\nrun\n      2026\n"
        "/PART/1\nsolid\n         1         1         0\n/PART/2\nparticles\n         2         1         0\n"
        "/PROP/TYPE14/1\nsolid\n        24         0         0         0         0         0         0         2\n"
        "                 1.1                0.05                 0.1                 0.0                 0.0\n"
        "                 0.0                 0.0                 0.0                 0.0                 0.0\n";
    s += fmt::format("{:>10}         2         0\n", ndir);
    s +=
        "/PROP/SPH/2\nparticles\n                 0.0                 2.0                 1.0                 0.0         0         0\n"
        "         0                 0.1                 0.0\n";
    s += fmt::format("/MAT/LAW2/1\nm\n{:>20}\n               210.0                 0.3\n/NODE\n", rho);
    for (std::size_t i = 0; i < nodes.size(); ++i) s += node_line(static_cast<long long>(i + 1), nodes[i]);
    return s + elements + "/END\n";
}

std::string brick_line(long long id, std::array<int, 8> n) {
    std::string s = fmt::format("/BRICK/1\n{:>10}", id);
    for (int k : n) s += fmt::format("{:>10}", k);
    return s + "\n";
}

preproc::Sol2sph generate(const std::string& text) {
    const engine::CheckResult r = engine::check_buffer(text, "run_0000.rad", {}, grammar::DeckFormat::Radioss);
    REQUIRE(r.model.radioss.has_value());
    return preproc::generate_sol2sph(r.model);
}

const std::vector<Vec> kUnitCube = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

// The trilinear map of a brick written independently of the library, and the integral of its
// Jacobian by (exact) central differences and 3x3x3 Gauss points (exact for degree 5 per variable).
Vec map(const std::vector<Vec>& p, double r, double s, double t) {
    const int sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    Vec x{};
    for (int k = 0; k < 8; ++k)
        for (int i = 0; i < 3; ++i)
            x[i] += p[k][i] * (1 + sign[k][0] * r) * (1 + sign[k][1] * s) * (1 + sign[k][2] * t) / 8;
    return x;
}

double reference_volume(const std::vector<Vec>& p) {
    const double g[3] = {-std::sqrt(0.6), 0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    const double e = 0.5;  // the map is linear in each variable alone: central differences are exact
    double v = 0;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            for (int c = 0; c < 3; ++c) {
                const double q[3] = {g[a], g[b], g[c]};
                double j[3][3];
                for (int m = 0; m < 3; ++m) {
                    double lo[3] = {q[0], q[1], q[2]}, hi[3] = {q[0], q[1], q[2]};
                    lo[m] -= e, hi[m] += e;
                    const Vec xl = map(p, lo[0], lo[1], lo[2]), xh = map(p, hi[0], hi[1], hi[2]);
                    for (int i = 0; i < 3; ++i) j[i][m] = (xh[i] - xl[i]) / (2 * e);
                }
                const double det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
                                   j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
                                   j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
                v += w[a] * w[b] * w[c] * det;
            }
    return v;
}

}  // namespace

TEST_CASE("sol2sph: particle counts and layouts per Ndir") {
    CHECK(preproc::sol2sph_brick_count(1) == 1);
    CHECK(preproc::sol2sph_brick_count(2) == 8);
    CHECK(preproc::sol2sph_brick_count(3) == 27);
    CHECK(preproc::sol2sph_brick_count(4) == 64);
    // Tetras: 1, 4, 10, 20 (the documentation's 22 for Ndir 4 is not what the code creates).
    const std::size_t tetra[] = {1, 4, 10, 20, 35, 56, 84, 120, 165};
    for (int n = 1; n <= 9; ++n) {
        const auto layout = preproc::sol2sph_tetra_barycentrics(n);
        CHECK(layout.size() == tetra[n - 1]);
        CHECK(preproc::sol2sph_tetra_count(n) == layout.size());
        for (const auto& l : layout) {
            CHECK(l[0] + l[1] + l[2] + l[3] == doctest::Approx(1.0));
            for (double v : l) CHECK(v > 0);
        }
    }
    // Ndir 2: the permutations of (1/2, 1/6, 1/6, 1/6).
    for (const auto& l : preproc::sol2sph_tetra_barycentrics(2)) {
        int halves = 0, sixths = 0;
        for (double v : l) halves += std::abs(v - 0.5) < 1e-15, sixths += std::abs(v - 1.0 / 6) < 1e-15;
        CHECK(halves == 1);
        CHECK(sixths == 3);
    }
    // Ndir 3: 4 permutations of (5/8, 1/8, 1/8, 1/8) and 6 of (3/8, 3/8, 1/8, 1/8).
    int corner = 0, edge = 0;
    for (const auto& l : preproc::sol2sph_tetra_barycentrics(3)) {
        int fives = 0, threes = 0;
        for (double v : l) fives += v == 0.625, threes += v == 0.375;
        corner += fives == 1, edge += threes == 2;
    }
    CHECK(corner == 4);
    CHECK(edge == 6);
    const auto a = preproc::sol2sph_brick_abscissae(3);
    REQUIRE(a.size() == 3);
    CHECK(a[0] == doctest::Approx(-2.0 / 3));
    CHECK(a[1] == doctest::Approx(0.0));
    CHECK(a[2] == doctest::Approx(2.0 / 3));
}

TEST_CASE("sol2sph: a unit brick, Ndir 1 to 3") {
    for (int n = 1; n <= 3; ++n) {
        CAPTURE(n);
        const auto s = generate(deck(kUnitCube, brick_line(7, {1, 2, 3, 4, 5, 6, 7, 8}), n));
        REQUIRE(s.parts.size() == 1);
        CHECK(s.issues.empty());
        const auto& p = s.parts[0];
        CHECK(p.bricks == 1);
        CHECK(p.particles == static_cast<std::size_t>(n * n * n));
        CHECK(p.element_mass == doctest::Approx(2.0));  // rho 2 x volume 1
        CHECK(std::abs(p.relative_difference()) < 1e-12);
        CHECK(std::abs(p.starter_relative_difference()) < 1e-12);  // exact for a parallelepiped
        CHECK(p.pitch == doctest::Approx(1.0 / n));
        CHECK(p.sph_part == 2);
        // Sub-cell centres (2k - 1) / (2n), each with mass 2 / n^3.
        std::set<long long> seen;
        for (std::size_t i = 0; i < s.particles.size(); ++i) {
            CHECK(s.particles.mass[i] == doctest::Approx(2.0 / (n * n * n)));
            CHECK(s.particles.element[i] == 7);
            const double kx = s.particles.x[i] * 2 * n, ky = s.particles.y[i] * 2 * n, kz = s.particles.z[i] * 2 * n;
            for (double k : {kx, ky, kz}) {
                CHECK(std::abs(k - std::round(k)) < 1e-9);
                CHECK(static_cast<long long>(std::round(k)) % 2 == 1);
            }
            seen.insert(std::llround(kx) * 10000 + std::llround(ky) * 100 + std::llround(kz));
        }
        CHECK(seen.size() == s.particles.size());  // all distinct
    }
}

TEST_CASE("sol2sph: distorted and twisted bricks keep their mass and centroid") {
    // Node 7 raised by d = 0.6: the top surface z = 1 + d x y, volume 1 + d / 4 = 1.15 by hand.
    std::vector<Vec> raised = kUnitCube;
    raised[6] = {1, 1, 1.6};
    // Twisted: top face rotated and shifted, bottom corner pulled; volume by an independent quadrature.
    const std::vector<Vec> twisted = {{0, 0, 0},      {1.2, 0.1, 0},   {1, 1, 0.2},   {-0.1, 0.9, 0},
                                      {0.3, -0.2, 1}, {1.1, 0.3, 1.3}, {0.8, 1.3, 1}, {0, 0.8, 0.9}};
    for (const std::vector<Vec>* nodes : {static_cast<const std::vector<Vec>*>(&raised), &twisted}) {
        const double volume = nodes == &raised ? 1.15 : reference_volume(*nodes);
        for (int n = 1; n <= 3; ++n) {
            CAPTURE(n);
            const auto s = generate(deck(*nodes, brick_line(1, {1, 2, 3, 4, 5, 6, 7, 8}), n, 3.0));
            REQUIRE(s.parts.size() == 1);
            REQUIRE(s.issues.empty());
            const auto& p = s.parts[0];
            CHECK(p.element_mass == doctest::Approx(3.0 * volume).epsilon(1e-9));
            CHECK(std::abs(p.relative_difference()) < 1e-12);
            double total = 0;
            Vec mean{};
            for (std::size_t i = 0; i < s.particles.size(); ++i) {
                total += s.particles.mass[i];
                mean[0] += s.particles.x[i] / static_cast<double>(s.particles.size());
                mean[1] += s.particles.y[i] / static_cast<double>(s.particles.size());
                mean[2] += s.particles.z[i] / static_cast<double>(s.particles.size());
                if (nodes == &raised) {  // inside: 0 < x, y < 1, 0 < z < 1 + d x y
                    CHECK(s.particles.x[i] > 0);
                    CHECK(s.particles.x[i] < 1);
                    CHECK(s.particles.y[i] > 0);
                    CHECK(s.particles.y[i] < 1);
                    CHECK(s.particles.z[i] > 0);
                    CHECK(s.particles.z[i] < 1 + 0.6 * s.particles.x[i] * s.particles.y[i]);
                }
            }
            CHECK(total == doctest::Approx(3.0 * volume).epsilon(1e-12));
            // The particles' mean is the average of the 8 nodes (the grid is symmetric).
            const Vec centre = map(*nodes, 0, 0, 0);
            for (int i = 0; i < 3; ++i) CHECK(mean[i] == doctest::Approx(centre[i]).epsilon(1e-12));
        }
    }
    // The starter's det J at the sub-cell centre is exact for the raised brick (det J = 1 + d x y
    // is bilinear) but not for the twisted one.
    const auto raised1 = generate(deck(raised, brick_line(1, {1, 2, 3, 4, 5, 6, 7, 8}), 1, 3.0));
    CHECK(std::abs(raised1.parts[0].starter_relative_difference()) < 1e-12);
    const auto twisted1 = generate(deck(twisted, brick_line(1, {1, 2, 3, 4, 5, 6, 7, 8}), 1, 3.0));
    CHECK(std::abs(twisted1.parts[0].starter_relative_difference()) > 1e-6);
}

TEST_CASE("sol2sph: tetra layouts and bricks with four distinct nodes") {
    // Tetra (0,0,0), (2,0,0), (0,3,0), (0,0,4): volume 2 x 3 x 4 / 6 = 4.
    const std::vector<Vec> nodes = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 0, 4}};
    const std::string tetra = "/TETRA4/1\n       501         1         2         3         4\n";
    const std::size_t count[] = {1, 4, 10, 20};
    for (int n = 1; n <= 4; ++n) {
        CAPTURE(n);
        const auto s = generate(deck(nodes, tetra, n, 0.5));
        REQUIRE(s.parts.size() == 1);
        const auto& p = s.parts[0];
        CHECK(p.tetras == 1);
        CHECK(p.particles == count[n - 1]);
        CHECK(p.element_mass == doctest::Approx(2.0));
        CHECK(std::abs(p.relative_difference()) < 1e-12);
        Vec mean{};
        for (std::size_t i = 0; i < s.particles.size(); ++i) {
            CHECK(s.particles.mass[i] == doctest::Approx(2.0 / static_cast<double>(count[n - 1])));
            const double x = s.particles.x[i], y = s.particles.y[i], z = s.particles.z[i];
            CHECK(x / 2 + y / 3 + z / 4 < 1);  // inside
            CHECK(x > 0);
            CHECK(y > 0);
            CHECK(z > 0);
            mean[0] += x, mean[1] += y, mean[2] += z;
        }
        CHECK(mean[0] / static_cast<double>(p.particles) == doctest::Approx(0.5));  // centroid
        CHECK(mean[1] / static_cast<double>(p.particles) == doctest::Approx(0.75));
        CHECK(mean[2] / static_cast<double>(p.particles) == doctest::Approx(1.0));
    }
    // The same tetra written as a brick 1 2 3 3 4 4 4 4 (four distinct nodes), nodes reversed too.
    for (const auto& order : {std::array<int, 8>{1, 2, 3, 3, 4, 4, 4, 4}, std::array<int, 8>{2, 1, 3, 3, 4, 4, 4, 4}}) {
        const auto s = generate(deck(nodes, brick_line(9, order), 3, 0.5));
        REQUIRE(s.parts.size() == 1);
        CHECK(s.parts[0].tetras == 1);
        CHECK(s.parts[0].particles == 10);
        CHECK(s.parts[0].element_mass == doctest::Approx(2.0));
    }
}

TEST_CASE("sol2sph: bad elements get a message naming them, not a crash") {
    std::vector<Vec> nodes = kUnitCube;
    // Element 5 names node 99 (undefined); element 6 is inverted (top and bottom swapped); element 7
    // collapses to three distinct nodes; element 8 is fine.
    const std::string elements = brick_line(5, {1, 2, 3, 4, 5, 6, 7, 99}) + brick_line(6, {5, 6, 7, 8, 1, 2, 3, 4}) +
                                 brick_line(7, {1, 2, 3, 3, 3, 3, 3, 3}) + brick_line(8, {1, 2, 3, 4, 5, 6, 7, 8});
    const auto s = generate(deck(nodes, elements, 2));
    REQUIRE(s.parts.size() == 1);
    REQUIRE(s.issues.size() == 3);
    CHECK(s.issues[0].element == 5);
    CHECK(s.issues[0].message.find("node 99 is not defined") != std::string::npos);
    CHECK(s.issues[1].element == 6);
    CHECK(s.issues[1].message.find("non-positive volume") != std::string::npos);
    CHECK(s.issues[2].element == 7);
    CHECK(s.parts[0].bricks == 1);
    CHECK(s.parts[0].particles == 8);
    CHECK(s.parts[0].skipped == 3);
    CHECK(std::abs(s.parts[0].relative_difference()) < 1e-12);  // over the elements that got particles
}

TEST_CASE("sol2sph: the command writes .vtp and CSV and checks the mass") {
    test::TempDir dir;
    const std::string demo = std::string(SPHDECK_SOURCE_DIR) + "/decks/sol2sph/bumper_0000.rad";
    const auto r = test::run_sphdeck(dir, "sol2sph '" + demo + "' --out out");
    CHECK(r.exit_code == 0);
    // 6 bricks x 8 + 2 tetras x 10 particles.
    CHECK(r.out.find("68 particle(s)") != std::string::npos);
    CHECK(r.out.find("FAILED") == std::string::npos);
    std::ifstream csv(dir.path() / "out" / "bumper_0000_sol2sph.csv");
    REQUIRE(csv.good());
    std::string line;
    std::size_t rows = 0;
    std::getline(csv, line);
    CHECK(line.rfind("index,x,y,z,element", 0) == 0);
    while (std::getline(csv, line)) ++rows;
    CHECK(rows == 68);
    std::ifstream vtp(dir.path() / "out" / "bumper_0000_sol2sph.vtp");
    std::stringstream text;
    text << vtp.rdbuf();
    CHECK(text.str().find("NumberOfPoints=\"68\"") != std::string::npos);

    const auto j = test::run_sphdeck(dir, "sol2sph '" + demo + "' --format json");
    REQUIRE(j.exit_code == 0);
    const auto doc = nlohmann::json::parse(j.out);
    REQUIRE(doc["parts"].size() == 2);
    // Bricks: 4 of 1000 + 300 / 4 mm^3 (the raised node) and 2 of 1000; tetras 1000/6 + 2000/6.
    CHECK(doc["parts"][0]["element_mass"].get<double>() == doctest::Approx(7.8e-6 * 6300));
    CHECK(doc["parts"][1]["element_mass"].get<double>() == doctest::Approx(7.8e-6 * 500));
    CHECK(doc["parts"][0]["mass_check"].get<bool>());
    // Pitch: the median element (1075 mm^3, 8 particles): (1075 / 8)^(1/3).
    CHECK(doc["parts"][0]["pitch"].get<double>() == doctest::Approx(std::cbrt(1075.0 / 8)));

    // A bad element: exit 1 and the element's file and line in the message.
    dir.write("bad_0000.rad", deck(kUnitCube, brick_line(5, {1, 2, 3, 4, 5, 6, 7, 99}), 2));
    const auto bad = test::run_sphdeck(dir, "sol2sph bad_0000.rad");
    CHECK(bad.exit_code == 1);
    CHECK(bad.out.find("bad_0000.rad:") != std::string::npos);
    CHECK(bad.out.find("/BRICK 5: node 99 is not defined") != std::string::npos);
    // Not a Radioss deck: exit 2.
    const auto dyna =
        test::run_sphdeck(dir, "sol2sph '" + std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/preview/SPH113_silent.k'");
    CHECK(dyna.exit_code == 2);
}

TEST_CASE("sol2sph: a part that gets no particles is reported at the part, not as 'ok'") {
    // Only a 10-node tetra (corners and edge midpoints): SOL2SPH converts none.
    const std::vector<Vec> nodes = {{0, 0, 0},     {1, 0, 0},   {0, 1, 0},   {0, 0, 1},     {0.5, 0, 0},
                                    {0.5, 0.5, 0}, {0, 0.5, 0}, {0, 0, 0.5}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    const std::string tetra10 =
        "/TETRA10/1\n         1\n" +
        fmt::format("{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}\n", 1, 2, 3, 4, 5, 6, 7, 8, 9, 10);
    const std::string text = deck(nodes, tetra10, 2);
    const auto s = generate(text);
    REQUIRE(s.parts.size() == 1);
    const preproc::Sol2sphPart& p = s.parts[0];
    CHECK(p.particles == 0);
    CHECK(p.skipped == 1);
    CHECK(p.no_particles.find("no particles are generated: its 1 element(s) are all of kinds SOL2SPH does not "
                              "convert") == 0);
    CHECK(p.span.line == 5);    // /PART/1
    CHECK(p.span.column == 7);  // its id

    // A part without elements says so; Ndir outside 1-9 keeps its own note instead.
    CHECK(generate(deck(nodes, "", 2)).parts.at(0).no_particles ==
          "no particles are generated: the part has no elements");
    CHECK(generate(deck(nodes, "", 12)).parts.at(0).no_particles.empty());

    test::TempDir dir;
    dir.write("t10_0000.rad", text);
    const auto r = test::run_sphdeck(dir, "sol2sph t10_0000.rad");
    CHECK(r.exit_code == 0);  // a warning
    CHECK(r.out.find("t10_0000.rad:5:7: warning: part 1: no particles are generated") != std::string::npos);
    CHECK(r.out.find(" ok\n") == std::string::npos);
    CHECK(r.out.find(" none\n") != std::string::npos);
    const auto j = test::run_sphdeck(dir, "sol2sph t10_0000.rad --format json");
    const auto doc = nlohmann::json::parse(j.out);
    CHECK(doc["parts"][0]["mass_check"].is_null());
    CHECK(doc["parts"][0]["warnings"].size() == 1);
    CHECK(doc["parts"][0]["location"].get<std::string>() == "t10_0000.rad:5:7");
}
}  // namespace test_sol2sph_cpp
