// The reference solver's neighbour lists against brute force (every pair within the radius once in
// the half lists (plus at most a few within the single-precision margin), every ghost in range in the ghost lists, the
// full lists for FORM 1), on any thread count; and the symmetric pair loop: the same results for the same thread count,
// and round-off agreement between one and two threads.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "refsolver/neighbour_list.hpp"
#include "refsolver/symmetry_ghosts.hpp"
#include "refsolver/verlet_skin.hpp"
#include "test_refsolver_decks.hpp"

namespace test_refsolver_neighbours_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using namespace sphdeck::refsolver;

namespace {

// A deterministic cloud in [0, 1]^3 (a small linear congruential generator), a few inactive.
Particles random_cloud(std::size_t n) {
    Particles s;
    s.resize_real(n);
    std::uint64_t state = 12345;
    const auto next = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) / double(1ull << 53);
    };
    for (std::size_t i = 0; i < n; ++i) {
        s.x[i] = next(), s.y[i] = next(), s.z[i] = next();
        s.model_index[i] = static_cast<std::uint32_t>(i);
        s.active[i] = i % 17 != 3;
        s.h[i] = 0.05, s.m[i] = 1, s.rho[i] = 1;
    }
    return s;
}

double distance2(const Particles& s, std::size_t a, std::size_t b) {
    const double dx = s.x[a] - s.x[b], dy = s.y[a] - s.y[b], dz = s.z[a] - s.z[b];
    return dx * dx + dy * dy + dz * dz;
}

using Pairs = std::set<std::pair<std::uint32_t, std::uint32_t>>;

}  // namespace

TEST_CASE("refsolver neighbours: half and ghost lists hold exactly the pairs within the radius") {
    const std::vector<SymmetryPlane> planes = {{{1, 0, 0}, 0.0}, {{0, 1, 0}, 0.0}, {{0, 0, -1}, -1.0}};
    const double radius = 0.13;
    std::vector<Pairs> found_by_threads;
    for (int threads : {1, 2, 3}) {
        CAPTURE(threads);
        Particles s = random_cloud(1500);
        build_ghosts(s, planes, radius, threads);
        NeighbourList list;
        list.build(s, radius, threads, true);
        const std::size_t real = s.real;

        // The particles were re-sorted: model_index is still a permutation.
        std::vector<std::uint32_t> seen(s.model_index.begin(), s.model_index.end());
        std::sort(seen.begin(), seen.end());
        for (std::size_t k = 0; k < real; ++k) REQUIRE(seen[k] == k);

        Pairs expected_real, expected_ghost, listed_real, listed_ghost;
        for (std::size_t i = 0; i < real; ++i) {
            if (!s.active[i]) continue;
            for (std::size_t j = i + 1; j < real; ++j)
                if (s.active[j] && distance2(s, i, j) < radius * radius)
                    expected_real.insert({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
            for (std::size_t g = real; g < s.total(); ++g)
                if (s.active[s.ghost_source[g - real]] && distance2(s, i, g) < radius * radius)
                    expected_ghost.insert({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(g)});
        }
        for (std::uint32_t i = 0; i < real; ++i) {
            for (std::uint32_t k = list.forward_offsets[i]; k < list.forward_offsets[i + 1]; ++k) {
                CHECK(list.forward[k] > i);  // each pair once, under its first particle
                listed_real.insert({i, list.forward[k]});
            }
            for (std::uint32_t k = list.ghost_offsets[i]; k < list.ghost_offsets[i + 1]; ++k)
                listed_ghost.insert({i, list.ghost[k]});
        }
        // Every pair within the radius; beyond it, at most a few within the single-precision margin
        // of the candidate test (harmless: the pair loop keeps only the pairs inside the support).
        const auto within_margin = [&](const Pairs& listed) {
            for (const auto& [i, j] : listed)
                if (distance2(s, i, j) >= std::pow(radius + 1e-5, 2)) return false;
            return true;
        };
        CHECK(list.forward.size() == listed_real.size());  // no duplicates
        CHECK(std::includes(listed_real.begin(), listed_real.end(), expected_real.begin(), expected_real.end()));
        CHECK(std::includes(listed_ghost.begin(), listed_ghost.end(), expected_ghost.begin(), expected_ghost.end()));
        CHECK(within_margin(listed_real));
        CHECK(within_margin(listed_ghost));
        CHECK(listed_real.size() < expected_real.size() + 10);
        CHECK(!expected_ghost.empty());

        // Full lists: every neighbour of every particle, both directions, ghosts included.
        Pairs full, expected_full;
        for (const auto& [i, j] : expected_real) expected_full.insert({i, j}), expected_full.insert({j, i});
        expected_full.insert(expected_ghost.begin(), expected_ghost.end());
        for (std::uint32_t i = 0; i < real; ++i)
            for (std::uint32_t k = list.offsets[i]; k < list.offsets[i + 1]; ++k) full.insert({i, list.neighbours[k]});
        Pairs listed_full;
        for (const auto& [i, j] : listed_real) listed_full.insert({i, j}), listed_full.insert({j, i});
        listed_full.insert(listed_ghost.begin(), listed_ghost.end());
        CHECK(list.neighbours.size() == full.size());
        CHECK(full == listed_full);
        CHECK(std::includes(full.begin(), full.end(), expected_full.begin(), expected_full.end()));

        // In model numbering, the same pairs whatever the thread count.
        Pairs by_model;
        for (const auto& [i, j] : listed_real) by_model.insert(std::minmax(s.model_index[i], s.model_index[j]));
        found_by_threads.push_back(by_model);
    }
    CHECK(found_by_threads[0] == found_by_threads[1]);
    CHECK(found_by_threads[0] == found_by_threads[2]);
}

namespace {

// A jittered lattice of ideal gas in a box of symmetry planes, under gravity: the particles move,
// cross cells and get rebuilt lists.
test::TestDeck jittered_box() {
    test::TestDeck deck;
    deck.rho0 = 1.0;
    deck.q1 = 1.5, deck.q2 = 0.06;
    deck.eos = "*EOS_LINEAR_POLYNOMIAL\n1,0,0,0,0,0.4,0.4,0\n2.5,1\n";
    const int side = 9;
    const double dx = 0.1, L = side * dx;
    for (int k = 0; k < side; ++k)
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i) {
                const double jitter = 0.15 * dx * std::sin(12.9898 * i + 78.233 * j + 37.719 * k);
                deck.particles.push_back({(i + 0.5) * dx + jitter, (j + 0.5) * dx - 0.5 * jitter,
                                          (k + 0.5) * dx + 0.3 * jitter, dx * dx * dx});
            }
    for (const std::string& p :
         {fmt::format("0,0,0,1,0,0"), fmt::format("{},0,0,{},0,0", L, L - 1), fmt::format("0,0,0,0,1,0"),
          fmt::format("0,0,0,0,0,1"), fmt::format("0,0,{},0,0,{}", L, L - 1)})
        deck.extra += "*BOUNDARY_SPH_SYMMETRY_PLANE\n" + p + "\n";
    deck.extra += "*LOAD_BODY_Y\n1,0.5\n*DEFINE_CURVE\n1\n0,1\n100,1\n";
    deck.endtim = 100.0;
    return deck;
}

refsolver::ParticleState run(const test::TestDeck& deck, int threads, int steps, std::size_t& rebuilds) {
    refsolver::RunOptions options;
    options.threads = threads;
    auto setup = test::solver_for(deck, options);
    REQUIRE_MESSAGE(setup.simulation, test::unsupported_text(setup));
    for (int s = 0; s < steps; ++s) setup.simulation->step();
    rebuilds = setup.simulation->neighbour_rebuilds();
    return setup.simulation->state();
}

}  // namespace

TEST_CASE("refsolver neighbours: the symmetric pair loop is deterministic and thread counts agree to round-off") {
    for (int form : {0, 1}) {
        CAPTURE(form);
        test::TestDeck deck = jittered_box();
        deck.form = form;
        std::size_t rebuilds = 0, again = 0, two = 0;
        const refsolver::ParticleState a = run(deck, 1, 60, rebuilds);
        const refsolver::ParticleState b = run(deck, 1, 60, again);
        const refsolver::ParticleState c = run(deck, 2, 60, two);
        CHECK(rebuilds > 1);  // the lists were rebuilt while the gas moved
        double vmax = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            vmax = std::max(vmax, std::abs(a.vy[i]));
            CHECK(a.x[i] == b.x[i]);  // same thread count: bit for bit
            CHECK(a.vy[i] == b.vy[i]);
            CHECK(a.rho[i] == b.rho[i]);
            CHECK(a.e[i] == b.e[i]);
            CHECK(c.x[i] == doctest::Approx(a.x[i]).epsilon(1e-10));  // another order of the sums
            CHECK(c.vy[i] == doctest::Approx(a.vy[i]).epsilon(1e-6).scale(1e-9));
            CHECK(c.rho[i] == doctest::Approx(a.rho[i]).epsilon(1e-10));
        }
        CHECK(vmax > 0.01);  // the gas did move
    }
}

namespace {

// A block of water-like fluid stretching as a collapsing column does (vx = U x / L, vy = -U y / L),
// over a floor and walls: neighbours move together while the block's corners move apart fast, so
// the local skin bound (refsolver/verlet_skin.hpp) keeps the lists far longer than the global one.
// `jostle`: each particle's velocity also varies by up to that much from its neighbours', so that
// pairs enter the support between rebuilds.
test::TestDeck stretching_block(double jostle) {
    test::TestDeck deck;
    deck.rho0 = 1000;
    deck.q1 = 1.0, deck.q2 = 1.0;
    deck.eos = "*EOS_MURNAGHAN\n1,7,2e5,1\n";
    const int side = 8;
    const double dx = 0.1, L = side * dx, U = 8.0;
    for (int k = 0; k < side; ++k)
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i) {
                const double x = (i + 0.5) * dx, y = (j + 0.5) * dx, z = (k + 0.5) * dx;
                const double wobble = jostle * std::sin(12.9898 * i + 78.233 * j + 37.719 * k);
                deck.particles.push_back(
                    {x, y, z, 1000 * dx * dx * dx, U * x / L + wobble, -U * y / L - 0.7 * wobble, 0.4 * wobble});
            }
    for (const char* p : {"0,0,0,1,0,0", "0,0,0,0,1,0", "0,0,0,0,0,1"})
        deck.extra += fmt::format("*BOUNDARY_SPH_SYMMETRY_PLANE\n{}\n", p);
    deck.extra += "*LOAD_BODY_Y\n1,9.81\n*DEFINE_CURVE\n1\n0,1\n100,1\n";
    deck.endtim = 100.0;
    return deck;
}

}  // namespace

TEST_CASE("refsolver neighbours: the skin test never lets a pair within the support go missing") {
    for (double jostle : {0.0, 1.0}) {
        CAPTURE(jostle);
        const test::TestDeck deck = stretching_block(jostle);
        refsolver::RunOptions every;
        every.rebuild_every_step = true;
        auto skin = test::solver_for(deck), reference = test::solver_for(deck, every);
        REQUIRE_MESSAGE(skin.simulation, test::unsupported_text(skin));
        REQUIRE(reference.simulation);
        for (int s = 0; s < 150; ++s) skin.simulation->step(), reference.simulation->step();
        const refsolver::ParticleState &a = skin.simulation->state(), &b = reference.simulation->state();
        // The same motion to round-off as with a rebuild at every step. (Pairs enter the support at its
        // edge, where the kernel gradient vanishes, so a bound that missed a few would hardly show
        // here: the next test checks the bound itself against brute force.)
        double moved = 0, gap_rho = 0, gap_v = 0, vmax = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            moved = std::max(moved, std::abs(a.x[i] - deck.particles[i].x));
            gap_rho = std::max(gap_rho, std::abs(a.rho[i] - b.rho[i]) / b.rho[i]);
            gap_v = std::max(
                {gap_v, std::abs(a.vx[i] - b.vx[i]), std::abs(a.vy[i] - b.vy[i]), std::abs(a.vz[i] - b.vz[i])});
            vmax = std::max({vmax, std::abs(b.vx[i]), std::abs(b.vy[i]), std::abs(b.vz[i])});
        }
        const std::size_t rebuilds = skin.simulation->neighbour_rebuilds();
        MESSAGE("jostle " << jostle << ": rebuilds " << rebuilds << " (every step: "
                          << reference.simulation->neighbour_rebuilds() << "), largest displacement " << moved
                          << ", relative gaps: rho " << gap_rho << ", v " << gap_v / vmax);
        CHECK(moved > 0.1);  // about a spacing: pairs entered and left the support
        CHECK(rebuilds > 1);
        CHECK(gap_rho < 1e-11);
        CHECK(gap_v / vmax < 1e-11);
        if (jostle == 0) CHECK(rebuilds < reference.simulation->neighbour_rebuilds() / 4);  // the local bound at work
    }
}

TEST_CASE("refsolver neighbours: the local skin bound covers every pair within the support") {
    // Build positions: the random cloud; ghosts for three planes. Then a stretching displacement
    // (large across the cloud, small between neighbours) plus a jitter.
    const std::vector<SymmetryPlane> planes = {{{1, 0, 0}, 0.0}, {{0, 1, 0}, 0.0}, {{0, 0, -1}, -1.0}};
    Particles s = random_cloud(1500);
    build_ghosts(s, planes, 0.13);
    s.x_built = s.x, s.y_built = s.y, s.z_built = s.z;
    for (std::size_t i = 0; i < s.real; ++i) {
        const double jitter = 0.004 * std::sin(12.9898 * double(i));
        s.x[i] += 0.05 * s.x[i] + jitter, s.y[i] -= 0.05 * s.y[i] - 0.5 * jitter, s.z[i] += 0.3 * jitter;
    }
    const double support = 0.1;
    std::vector<DisplacementBox> cells;
    const double bound = closing_bound(s, planes, support, cells);
    // On threads (each bins its share of the points into its own cells): the same bound, to the bit.
    for (int threads : {2, 3}) CHECK(closing_bound(s, planes, support, cells, threads) == bound);
    // Every point (active real particle, or ghost of one) now and at the build, by brute force.
    struct Point {
        double now[3], built[3];
    };
    std::vector<Point> points;
    const auto mirror = [&](double p[3], unsigned subset, bool vector) {
        for (std::size_t q = 0; q < planes.size(); ++q) {
            if (!(subset >> q & 1u)) continue;
            const auto& n = planes[q].normal;
            const double dd = p[0] * n[0] + p[1] * n[1] + p[2] * n[2] - (vector ? 0.0 : planes[q].offset);
            for (int a = 0; a < 3; ++a) p[a] -= 2 * dd * n[a];
        }
    };
    for (std::size_t i = 0; i < s.real; ++i)
        if (s.active[i]) points.push_back({{s.x[i], s.y[i], s.z[i]}, {s.x_built[i], s.y_built[i], s.z_built[i]}});
    for (std::size_t k = 0; k < s.ghosts(); ++k) {
        const std::size_t j = s.ghost_source[k];
        if (!s.active[j]) continue;
        Point p{{s.x[j], s.y[j], s.z[j]}, {s.x_built[j], s.y_built[j], s.z_built[j]}};
        mirror(p.now, s.ghost_planes[k], false), mirror(p.built, s.ghost_planes[k], false);
        points.push_back(p);
    }
    double needed = 0, spread = 0;  // the largest |d_a - d_b| within the support; over all pairs
    for (std::size_t a = 0; a < points.size(); ++a)
        for (std::size_t b = a + 1; b < points.size(); ++b) {
            double r2 = 0, dd2 = 0;
            for (int k = 0; k < 3; ++k) {
                const double r = points[a].now[k] - points[b].now[k];
                const double dd = (points[a].now[k] - points[a].built[k]) - (points[b].now[k] - points[b].built[k]);
                r2 += r * r, dd2 += dd * dd;
            }
            spread = std::max(spread, std::sqrt(dd2));
            if (r2 < support * support) needed = std::max(needed, std::sqrt(dd2));
        }
    MESSAGE("local bound " << bound << ", needed " << needed << ", largest |d_a - d_b| overall " << spread);
    CHECK(bound >= needed);
    CHECK(bound < 0.6 * spread);  // local: below what the global bound must allow
}
}  // namespace test_refsolver_neighbours_cpp
