// The nearest neighbours of the points whose grid walk would be long (nearest_neighbours.cpp): a point in a
// crowded block of cells (a tight blob, exact duplicates: the cells cannot shrink below the blob), or a point
// whose nearest neighbour lies many cells away (a lattice point beside a blob, whose crowding made the cells
// far smaller than the lattice's spacing; a stray point). The walk's cost grows with the cube of the cells it
// crosses and with the points per cell; a k-d tree over the same points costs about log n a query.
//
// The answers are the walk's, ties included. The walk keeps, among the points at the smallest squared
// distance, the first it meets: its 3x3x3 block first, then shell after shell, and within one of them the
// lowest sorted position. So the point chosen is the least (squared distance, shell, sorted position), the
// shell being the Chebyshev distance of the cells, at least 1. One exception: when the next block would hold
// more cells than there are points, the walk scans every point and keeps the lowest sorted position among
// those strictly closer than its best so far (walk_end below says when).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "preproc/neighbour_grid.hpp"

namespace sphdeck::preproc {

struct NearestFound {
    double best2 = std::numeric_limits<double>::infinity();  // infinite when there is no other point
    std::uint32_t best = 0xFFFFFFFFu;                        // sorted position, or none
};

class NearestTree {
public:
    // A tree over the grid's points with finite coordinates (no other point is ever nearest: their squared
    // distances are infinite or NaN). The grid must outlive the tree.
    explicit NearestTree(const NeighbourGrid& g);
    // The walk's answer for sorted point k; `visits` grows by the nodes and points looked at.
    NearestFound nearest(std::uint32_t k, std::uint64_t& visits) const;
    // The points its building passed over (about n log2(n / 8)).
    std::uint64_t building_work() const { return building_work_; }

private:
    struct Node {
        std::array<double, 3> lo, hi;          // the points' box
        NeighbourGrid::Cell cell_lo, cell_hi;  // their grid cells' box
        std::uint32_t begin, end;              // points_[begin, end)
        std::uint32_t first_position;          // the lowest sorted position among them
        std::uint32_t second;                  // the second child (the first is the next node); 0: a leaf
    };
    struct Query;
    std::uint32_t build(std::uint32_t begin, std::uint32_t end);
    NearestFound search(std::uint32_t k, bool by_shell, std::uint64_t& visits) const;
    void visit(Query& q, std::uint32_t node) const;

    // A point with its sorted position, in tree order: the leaves read their points in place.
    struct Point {
        double x, y, z;
        std::uint32_t position;
    };
    const NeighbourGrid& g_;
    std::vector<Point> points_;
    std::vector<Node> nodes_;
    std::uint64_t building_work_ = 0;
};

// The same answer by a scan over every point: for a few points, cheaper than building a tree.
NearestFound nearest_by_scan(const NeighbourGrid& g, std::uint32_t k, std::uint64_t& visits);

// Where the grid walk around sorted point k (in cell `at`) ends when `best2` is the smallest squared
// distance: the reach of the last block it searched, and whether it ended by scanning every point.
struct WalkEnd {
    std::uint32_t reach;
    bool scanned_all;
};
WalkEnd walk_end(const NeighbourGrid& g, std::uint32_t k, NeighbourGrid::Cell at, double best2);

}  // namespace sphdeck::preproc
