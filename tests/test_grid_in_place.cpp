// A neighbour grid over points already in cell order reads them in place (preproc/neighbour_grid.hpp, issue
// 40): the same grid as the copying one in every respect that queries see (order, ranges, coordinates), the
// same nearest neighbours, on 1, 2 and 16 threads; points one step out of order are copied as before; a copy of
// a grid reads its own coordinates once the original is gone.
#include <doctest/doctest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "preproc/nearest_neighbours.hpp"
#include "preproc/neighbour_grid.hpp"

namespace test_grid_in_place_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

struct Points {
    std::vector<double> x, y, z;
};

// A jittered side^3 lattice of spacing 1, x fastest, then y, then z.
Points lattice(int side, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    Points p;
    for (int k = 0; k < side; ++k)
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i) {
                p.x.push_back(i + jitter(rng)), p.y.push_back(j + jitter(rng)), p.z.push_back(k + jitter(rng));
            }
    return p;
}

// The points in the cell order of a grid of cells of `cell` over them (the same points, so the same box):
// what a lattice in node order is to its grid, made sure of.
Points in_cell_order(const Points& p, double cell) {
    const preproc::NeighbourGrid g(p.x, p.y, p.z, cell);
    return {{g.x().begin(), g.x().end()}, {g.y().begin(), g.y().end()}, {g.z().begin(), g.z().end()}};
}

// Everything a query reads of a grid.
void check_same_grid(const preproc::NeighbourGrid& a, const preproc::NeighbourGrid& b) {
    REQUIRE(a.size() == b.size());
    CHECK(a.order() == b.order());
    CHECK(std::equal(a.x().begin(), a.x().end(), b.x().begin(), b.x().end()));
    CHECK(std::equal(a.y().begin(), a.y().end(), b.y().begin(), b.y().end()));
    CHECK(std::equal(a.z().begin(), a.z().end(), b.z().begin(), b.z().end()));
    REQUIRE(a.occupied() == b.occupied());
    bool same_ranges = true;
    for (std::size_t o = 0; o < a.occupied(); ++o)
        same_ranges =
            same_ranges && a.occupied_range(o) == b.occupied_range(o) && a.occupied_cell(o) == b.occupied_cell(o);
    CHECK(same_ranges);
}

}  // namespace

TEST_CASE("grid in place: points in cell order are read where they are, the grid otherwise the same") {
    for (const int threads : {1, 2, 16}) {
#ifdef _OPENMP
        const int saved = omp_get_max_threads();
        omp_set_num_threads(threads);
#endif
        CAPTURE(threads);
        const double cell = 0.98;
        const Points p = in_cell_order(lattice(40, 7), cell);  // 64,000 points: the binning's threads take part
        const preproc::NeighbourGrid copied(p.x, p.y, p.z, cell);
        const preproc::NeighbourGrid in_place(p.x, p.y, p.z, cell, true);
        CHECK_FALSE(copied.reads_in_place());
        REQUIRE(in_place.reads_in_place());
        CHECK(in_place.x().data() == p.x.data());  // not a copy
        check_same_grid(copied, in_place);
        // One pair of points swapped: out of cell order, copied.
        Points swapped = p;
        std::swap(swapped.x[100], swapped.x[2000]), std::swap(swapped.y[100], swapped.y[2000]);
        std::swap(swapped.z[100], swapped.z[2000]);
        const preproc::NeighbourGrid out_of_order(swapped.x, swapped.y, swapped.z, cell, true);
        CHECK_FALSE(out_of_order.reads_in_place());
        check_same_grid(preproc::NeighbourGrid(swapped.x, swapped.y, swapped.z, cell), out_of_order);
#ifdef _OPENMP
        omp_set_num_threads(saved);
#endif
    }
}

TEST_CASE("grid in place: nearest neighbours of a lattice in node order equal those of the same points shuffled") {
    const Points made = lattice(30, 11);
    const Points p = in_cell_order(made, preproc::estimated_spacing(made.x, made.y, made.z));
    REQUIRE(preproc::NeighbourGrid(p.x, p.y, p.z, preproc::estimated_spacing(p.x, p.y, p.z), true).reads_in_place());
    const preproc::NearestNeighbours direct = preproc::nearest_neighbours_grid(p.x, p.y, p.z);
    // The same points in a random order (read through a copy in cell order): the distances per point agree.
    std::vector<std::uint32_t> perm(p.x.size());
    for (std::uint32_t i = 0; i < perm.size(); ++i) perm[i] = i;
    std::shuffle(perm.begin(), perm.end(), std::mt19937_64(3));
    Points shuffled;
    for (const std::uint32_t i : perm)
        shuffled.x.push_back(p.x[i]), shuffled.y.push_back(p.y[i]), shuffled.z.push_back(p.z[i]);
    const preproc::NearestNeighbours other = preproc::nearest_neighbours_grid(shuffled.x, shuffled.y, shuffled.z);
    bool same = true;
    for (std::size_t k = 0; k < perm.size(); ++k) {
        same = same && other.distance[k] == direct.distance[perm[k]];
        same = same && perm[other.index[k]] == direct.index[perm[k]];
    }
    CHECK(same);
    // And the all-pairs reference.
    const preproc::NearestNeighbours reference = preproc::nearest_neighbours_all_pairs(p.x, p.y, p.z);
    CHECK(direct.distance == reference.distance);
}

TEST_CASE("grid in place: a copy of a grid reads its own coordinates once the original is gone") {
    const Points p = lattice(12, 5);
    const double cell = preproc::estimated_spacing(p.x, p.y, p.z);
    Points shuffled = p;
    std::reverse(shuffled.x.begin(), shuffled.x.end());  // out of cell order: the grid copies
    auto original = std::make_unique<preproc::NeighbourGrid>(shuffled.x, shuffled.y, shuffled.z, cell, true);
    REQUIRE_FALSE(original->reads_in_place());
    const std::vector<double> expected_x(original->x().begin(), original->x().end());
    preproc::NeighbourGrid copy = *original;
    preproc::NeighbourGrid assigned;
    assigned = *original;
    original.reset();
    CHECK(std::equal(copy.x().begin(), copy.x().end(), expected_x.begin(), expected_x.end()));
    CHECK(std::equal(assigned.x().begin(), assigned.x().end(), expected_x.begin(), expected_x.end()));
    // Moved, it reads the storage it took.
    const preproc::NeighbourGrid moved = std::move(copy);
    CHECK(std::equal(moved.x().begin(), moved.x().end(), expected_x.begin(), expected_x.end()));
}

}  // namespace test_grid_in_place_cpp
