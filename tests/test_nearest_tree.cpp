// preproc/nearest_tree: the nearest neighbours of clouds whose grid walk was long (tight blobs beside a
// lattice, a stray point, exact duplicates, a line): the same points as the walk alone, ties included, the
// same distances as all pairs, and work within a small multiple of the points (the walk alone: far more).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "preproc/nearest_neighbours.hpp"

namespace nearest_tree_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

struct Cloud {
    std::string name;
    std::vector<double> x, y, z;
    std::size_t size() const { return x.size(); }
    void add(double a, double b, double c) { x.push_back(a), y.push_back(b), z.push_back(c); }
};

// A jittered lattice of side n (spacing 1, jitter 0.1 of it), shifted by (ox, 0, 0).
void lattice(Cloud& c, int n, std::mt19937_64& rng, double ox = 0) {
    std::uniform_real_distribution<double> u(-0.1, 0.1);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) c.add(ox + i + u(rng), j + u(rng), k + u(rng));
}

// m points in a cube of side `width` at (cx, cy, cz): a blob the grid's cells cannot resolve.
void blob(Cloud& c, int m, double cx, double cy, double cz, double width, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0, width);
    for (int i = 0; i < m; ++i) c.add(cx + u(rng), cy + u(rng), cz + u(rng));
}

// The worst cases of the grid walk, at a size the walk alone still answers within a second.
std::vector<Cloud> pathological_clouds() {
    std::mt19937_64 rng(40);
    std::vector<Cloud> clouds;
    {  // a lattice, three blobs a few thousandths of its spacing wide, a stray point (the defect's cloud)
        Cloud c;
        c.name = "lattice with blobs";
        lattice(c, 12, rng);
        for (double f : {0.25, 0.5, 0.75}) blob(c, 150, 12 * f, 12 * f, 6, 3e-3, rng);
        c.add(1e4, 1e4, 1e4);
        clouds.push_back(c);
    }
    {  // every point but one in a tiny blob
        Cloud c;
        c.name = "one blob and a stray point";
        blob(c, 2000, 0, 0, 0, 5e-3, rng);
        c.add(1000, 500, 200);
        clouds.push_back(c);
    }
    {  // a lattice, one small blob and a stray point: a hashed grid refined once, to cells of about 0.8 of
       // the spacing, where many points need the second shell (its rows through cursors)
        Cloud c;
        c.name = "lattice, a small blob and a stray point";
        lattice(c, 20, rng);
        blob(c, 125, 10, 10, 10, 3e-3, rng);
        c.add(-5e3, 20, 7);
        clouds.push_back(c);
    }
    {  // two lattices far apart (a hashed grid)
        Cloud c;
        c.name = "two far clusters";
        lattice(c, 8, rng);
        lattice(c, 8, rng, 1e5);
        clouds.push_back(c);
    }
    {  // exact duplicates: 600 points at one place inside a lattice, and every 7th lattice point twice
        Cloud c;
        c.name = "exact duplicates";
        lattice(c, 8, rng);
        for (std::size_t i = 0; i < 512; i += 7) c.add(c.x[i], c.y[i], c.z[i]);
        for (int i = 0; i < 600; ++i) c.add(3.5, 3.5, 3.5);
        clouds.push_back(c);
    }
    {  // a line of points and a blob on it
        Cloud c;
        c.name = "line with a blob";
        for (int i = 0; i < 1500; ++i) c.add(i, 0, 0);
        blob(c, 300, 750.5, 0, 0, 3e-3, rng);
        clouds.push_back(c);
    }
    {  // ties everywhere: points on a coarse integer lattice, blobs at integer offsets, duplicates, strays
        Cloud c;
        c.name = "integer ties";
        std::uniform_int_distribution<int> pick(0, 9), coord(0, 6), offset(0, 4);
        for (int i = 0; i < 1200; ++i) {
            const int kind = pick(rng);
            if (kind < 6)
                c.add(0.25 * coord(rng), 0.25 * coord(rng), 0.25 * coord(rng));
            else if (kind < 8)
                c.add(0.5 + 1e-9 * offset(rng), 0.5 + 1e-9 * offset(rng), 0.5 + 1e-9 * offset(rng));
            else if (kind < 9)
                c.add(c.x[c.size() / 2], c.y[c.size() / 2], c.z[c.size() / 2]);
            else
                c.add(0.25 * (40 + coord(rng) * 100), 0.25 * coord(rng), 0);
        }
        clouds.push_back(c);
    }
    return clouds;
}

std::uint64_t total(const preproc::NearestWork& w) { return w.distances + w.rows + w.tree_visits; }

}  // namespace

TEST_CASE("nearest tree: the same neighbours as the grid walk alone and the same distances as all pairs") {
    for (const Cloud& c : pathological_clouds()) {
        CAPTURE(c.name);
        const auto grid = preproc::nearest_neighbours_grid(c.x, c.y, c.z);
        const auto walk = preproc::nearest_neighbours_walk_only(c.x, c.y, c.z);
        const auto pairs = preproc::nearest_neighbours_all_pairs(c.x, c.y, c.z);
        REQUIRE(grid.distance.size() == c.size());
        std::size_t other_point = 0, other_distance = 0, other_than_pairs = 0, wrong_index = 0;
        for (std::size_t i = 0; i < c.size(); ++i) {
            other_point += grid.index[i] != walk.index[i];  // ties included
            other_distance += grid.distance[i] != walk.distance[i];
            other_than_pairs += grid.distance[i] != pairs.distance[i];  // bit for bit
            const std::uint32_t j = grid.index[i];
            const double dx = c.x[i] - c.x[j], dy = c.y[i] - c.y[j], dz = c.z[i] - c.z[j];
            wrong_index += j == i || std::sqrt(dx * dx + dy * dy + dz * dz) != grid.distance[i];
        }
        CHECK(other_point == 0);
        CHECK(other_distance == 0);
        CHECK(other_than_pairs == 0);
        CHECK(wrong_index == 0);
    }
}

// The walk's work grows with the cube of the shells a point crosses (cells shrunk for the blobs) and with
// the points of a crowded block: a bound of 200 times the points (the tree takes about 100 on the lattice with blobs),
// which the walk alone breaks.
TEST_CASE("nearest tree: the work stays within a small multiple of the points") {
    for (const Cloud& c : pathological_clouds()) {
        CAPTURE(c.name);
        preproc::NearestWork work, walk_work;
        preproc::nearest_neighbours_grid(c.x, c.y, c.z, &work);
        preproc::nearest_neighbours_walk_only(c.x, c.y, c.z, &walk_work);
        const double n = static_cast<double>(c.size());
        CAPTURE(work.distances / n);
        CAPTURE(work.rows / n);
        CAPTURE(work.tree_visits / n);
        CAPTURE(total(walk_work) / n);
        CHECK(static_cast<double>(total(work)) <= 200 * n);
        if (c.name == "lattice with blobs" || c.name == "line with a blob" || c.name == "exact duplicates")
            CHECK(static_cast<double>(total(walk_work)) > 200 * n);  // the bound tells the two apart
    }
}

}  // namespace nearest_tree_cpp
