// The neighbour counts in float lanes (preproc/count_cell_float.hpp): every count, and every coincident pair,
// the double loop's bit for bit, on clouds built to sit at the float test's edge: pairs exactly at the
// support and one or two double ulps either side of it, far from the origin, at tiny spacings, on decimal
// lattices whose distances round. Against brute force over all pairs (the same expression in double), both
// through count_neighbours and through the float loop alone (cell by cell, as count_symmetric calls it),
// which must have decided the cells itself and tested the undecided pairs again.
#include <doctest/doctest.h>

#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <random>
#include <vector>

#include "preproc/count_cell_float.hpp"
#include "preproc/nearest_neighbours.hpp"

namespace test_count_cell_float_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

struct Cloud {
    std::vector<double> x, y, z;
    void add(double a, double b, double c) { x.push_back(a), y.push_back(b), z.push_back(c); }
    std::size_t size() const { return x.size(); }
};

// An n^3 lattice of spacing h at `origin`, and, beside every fifth point, points at `support` from it along
// an axis, a face diagonal and a body diagonal, each also `ulps` double ulps nearer and farther.
Cloud edge_cloud(int n, double h, double origin, double support, int ulps) {
    Cloud c;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) c.add(origin + i * h, origin + j * h, origin + k * h);
    const double inf = std::numeric_limits<double>::infinity();
    const std::size_t lattice = c.size();
    for (std::size_t p = 0; p < lattice; p += 5) {
        const double px = c.x[p], py = c.y[p], pz = c.z[p];
        const double axis = px + support, face = support / std::sqrt(2.0), body = support / std::sqrt(3.0);
        double a = axis, b = axis;
        for (int u = 0; u < ulps; ++u) a = std::nextafter(a, -inf), b = std::nextafter(b, inf);
        c.add(axis, py, pz), c.add(a, py, pz), c.add(b, py, pz);
        c.add(px + face, py + face, pz);
        c.add(px, std::nextafter(py + face, inf), std::nextafter(pz + face, -inf));
        c.add(px + body, py + body, pz + body);
    }
    return c;
}

std::vector<std::uint32_t> brute_counts(const Cloud& c, double support) {
    return preproc::count_neighbours_all_pairs(c.x, c.y, c.z, std::vector<double>(c.size(), support));
}

// The float loop alone over every occupied cell of a grid of `support`-sized cells, as count_symmetric
// calls it: the counts in input order, and what it did.
struct FloatRun {
    std::vector<std::uint32_t> count;
    std::vector<std::uint32_t> close;  // input indices of the points with a pair within the tolerance
    preproc::FloatCellScratch scratch;
};
FloatRun float_loop(const Cloud& c, double support, double tolerance) {
    const preproc::NeighbourGrid g(c.x, c.y, c.z, std::max(support, tolerance));
    std::vector<std::uint32_t> sorted(c.size(), 0);
    std::vector<std::uint32_t> close;
    FloatRun run;
    const preproc::CountCellFloat loop = preproc::count_cell_float();
    g.for_each_cell_rows(preproc::count_half_rows, [&](std::size_t o, preproc::NeighbourGrid::Cell at,
                                                       const std::vector<preproc::NeighbourGrid::Range>& ranges) {
        const auto [first, last] = g.occupied_range(o);
        REQUIRE(loop(g, support, first, last, ranges, tolerance * tolerance, sorted.data(), close,
                     g.block_bounds(at, 0), run.scratch));
    });
    run.count.resize(c.size());
    for (std::size_t k = 0; k < c.size(); ++k) run.count[g.order()[k]] = static_cast<std::uint32_t>(sorted[k]);
    for (const std::uint32_t k : close) run.close.push_back(g.order()[k]);
    std::sort(run.close.begin(), run.close.end());
    return run;
}

}  // namespace

TEST_CASE("count_cell_float: counts at the support's edge equal brute force") {
    const bool have = preproc::count_cell_float() != nullptr;
    if (!have) MESSAGE("no AVX2 here: the float loop is not run, count_neighbours' double loop is checked");
    for (const double origin : {0.0, 1e6, -3.7e3, 0.25}) {
        for (const double h : {1.0, 0.1, 0.3, 1e-6}) {
            for (const double factor : {1.0, 2.0, std::sqrt(2.0), std::sqrt(3.0), 2.64}) {
                const double support = factor * h;
                const Cloud c = edge_cloud(5, h, origin * (h < 1e-3 ? 1e-3 : 1.0), support, 1 + (factor > 2));
                CAPTURE(origin);
                CAPTURE(h);
                CAPTURE(factor);
                const auto brute = brute_counts(c, support);
                const auto grid = preproc::count_neighbours(c.x, c.y, c.z, std::vector<double>(c.size(), support),
                                                            std::vector<double>(c.size(), 0.0));
                CHECK(grid.count == brute);
                if (!have) continue;
                const FloatRun run = float_loop(c, support, 0.0);
                CHECK(run.count == brute);
                CHECK(run.scratch.declined == 0);
                CHECK(run.scratch.cells > 0);
                CHECK(run.scratch.retests > 0);  // the pairs at the edge went to the double test
            }
        }
    }
}

TEST_CASE("count_cell_float: jittered clouds with close pairs, coincident pairs the brute force's") {
    std::mt19937_64 rng(40);
    for (const double origin : {0.0, 1e6}) {
        std::uniform_real_distribution<double> jitter(-0.3, 0.3);
        Cloud c;
        for (int i = 0; i < 9; ++i)
            for (int j = 0; j < 9; ++j)
                for (int k = 0; k < 9; ++k) c.add(origin + i + jitter(rng), origin + j + jitter(rng), k + jitter(rng));
        // Pairs at one place, 1e-9 apart (within the tolerance) and just past the tolerance.
        const double tolerance = 1e-6;
        for (std::size_t p = 3; p < 300; p += 37) c.add(c.x[p], c.y[p], c.z[p]);
        for (std::size_t p = 5; p < 300; p += 41) c.add(c.x[p] + 1e-9, c.y[p], c.z[p]);
        for (std::size_t p = 7; p < 300; p += 43) c.add(c.x[p], c.y[p] + 1.0000001 * tolerance, c.z[p]);
        for (const double support : {1.0, 2.64, 1.3}) {
            CAPTURE(origin);
            CAPTURE(support);
            const auto brute = brute_counts(c, support);
            const auto grid = preproc::count_neighbours(c.x, c.y, c.z, std::vector<double>(c.size(), support),
                                                        std::vector<double>(c.size(), tolerance));
            CHECK(grid.count == brute);
            std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
            std::vector<std::uint32_t> close;
            for (std::uint32_t i = 0; i < c.size(); ++i)
                for (std::uint32_t j = i + 1; j < c.size(); ++j)
                    if (preproc::coincident_at(c.x[i], c.y[i], c.z[i], c.x[j], c.y[j], c.z[j], tolerance))
                        pairs.emplace_back(i, j), close.push_back(i), close.push_back(j);
            CHECK(grid.coincident == pairs);
            CHECK(grid.coincident_pairs == pairs.size());
            if (preproc::count_cell_float() == nullptr) continue;
            const FloatRun run = float_loop(c, support, tolerance);
            CHECK(run.count == brute);
            CHECK(run.scratch.declined == 0);
            // Each close point is the first of a pair in grid order: a subset of the pairs' points, and
            // one of every pair.
            for (const std::uint32_t p : run.close) CHECK(std::count(close.begin(), close.end(), p) > 0);
            for (const auto& [i, j] : pairs)
                CHECK((std::binary_search(run.close.begin(), run.close.end(), i) ||
                       std::binary_search(run.close.begin(), run.close.end(), j)));
        }
    }
}

TEST_CASE("count_cell_float: pairs near the support far from their cell's first point") {
    // Isolated pairs a support (1 +- 1e-6) apart, each in a cell whose first point (an anchor at its low
    // corner) is two to three cells from them: the float values relative to it carry the largest rounding
    // the bound allows for. Each pair's count the double expression's.
    std::mt19937_64 rng(4040);
    std::uniform_real_distribution<double> inside(0.7, 0.95), unit(0.05, 1.0), relative(-1e-6, 1e-6);
    for (const double origin : {0.0, 1e3, -7e5}) {
        const double support = 0.37;
        Cloud c;
        std::vector<std::uint32_t> expected;
        for (int i = 0; i < 14; ++i)
            for (int j = 0; j < 14; ++j)
                for (int k = 0; k < 14; ++k) {
                    const double ax = origin + 5 * i * support, ay = origin + 5 * j * support, az = 5 * k * support;
                    c.add(ax, ay, az);
                    const double px = ax + inside(rng) * support, py = ay + inside(rng) * support,
                                 pz = az + inside(rng) * support;
                    double dx = unit(rng), dy = unit(rng), dz = unit(rng);
                    const double stretch = support * (1 + relative(rng)) / std::sqrt(dx * dx + dy * dy + dz * dz);
                    const double qx = px + dx * stretch, qy = py + dy * stretch, qz = pz + dz * stretch;
                    c.add(px, py, pz), c.add(qx, qy, qz);
                    const double ex = px - qx, ey = py - qy, ez = pz - qz;
                    const std::uint32_t in = ex * ex + ey * ey + ez * ez < support * support;
                    expected.insert(expected.end(), {0, in, in});
                }
        CAPTURE(origin);
        const auto grid = preproc::count_neighbours(c.x, c.y, c.z, std::vector<double>(c.size(), support),
                                                    std::vector<double>(c.size(), 0.0));
        CHECK(grid.count == expected);
        if (preproc::count_cell_float() == nullptr) continue;
        const FloatRun run = float_loop(c, support, 0.0);
        CHECK(run.count == expected);
        CHECK(run.scratch.declined == 0);
        CHECK(run.scratch.retests > 0);
    }
}

TEST_CASE("count_cell_float: declines what its bound does not cover; the counts stay the double loop's") {
    // A stray point clamped into a border cell of a dense grid makes the block's scaled coordinates huge; a
    // NaN coordinate; supports far shorter than the cell (the largest tolerance sets it).
    Cloud c;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
            for (int k = 0; k < 8; ++k) c.add(i * 0.7, j * 0.7, k * 0.7);
    c.add(1e9, 0.0, 0.0);
    c.add(std::numeric_limits<double>::quiet_NaN(), 1.0, 1.0);
    const double support = 1.5;
    const auto brute = brute_counts(c, support);
    const auto grid = preproc::count_neighbours(c.x, c.y, c.z, std::vector<double>(c.size(), support),
                                                std::vector<double>(c.size(), 0.0));
    CHECK(grid.count == brute);
    const auto tiny = preproc::count_neighbours(c.x, c.y, c.z, std::vector<double>(c.size(), 1e-7),
                                                std::vector<double>(c.size(), 1.0));
    CHECK(tiny.count == brute_counts(c, 1e-7));
    if (preproc::count_cell_float() == nullptr) return;
    preproc::FloatCellScratch scratch;
    const preproc::NeighbourGrid g(c.x, c.y, c.z, 1.0);
    std::vector<std::uint32_t> count(c.size(), 0);
    std::vector<std::uint32_t> close;
    std::uint64_t accepted = 0;
    g.for_each_cell_rows(preproc::count_half_rows, [&](std::size_t o, preproc::NeighbourGrid::Cell at,
                                                       const std::vector<preproc::NeighbourGrid::Range>& ranges) {
        const auto [first, last] = g.occupied_range(o);
        // Supports of 1e-7 in cells of 1: the bound would call every pair undecided; declined.
        const std::uint64_t declined = scratch.declined;
        if (preproc::count_cell_float()(g, 1e-7, first, last, ranges, 0.0, count.data(), close, g.block_bounds(at, 0),
                                        scratch))
            ++accepted;
        else
            CHECK(scratch.declined == declined + 1);
    });
    // A cell of one point alone (the stray one) has nothing to fear from the bound; every crowded cell declines.
    CHECK(accepted <= 1);
    CHECK(scratch.declined + accepted == g.occupied());
    CHECK(std::all_of(count.begin(), count.end(), [](std::uint32_t n) { return n == 0; }));
}

}  // namespace test_count_cell_float_cpp
