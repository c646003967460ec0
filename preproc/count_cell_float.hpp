// The neighbour counts' inner loop in float lanes (issue 40 item 3): eight distance tests a 256-bit step
// instead of four, with the counts bit for bit those of the double loop (nearest_neighbours.cpp,
// count_cell). Every candidate whose float distance lies within a proven bound of the support (or of the
// coincidence tolerance) is tested again in double, with the double loop's very expression.
//
// Only for the plain uniform case (one support, no collapsed points), only on a CPU with AVX2, and only
// for a cell whose coordinates and supports the bound covers; otherwise the caller's double loop.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "preproc/neighbour_grid.hpp"

namespace sphdeck::preproc {

// The rows after a cell in cell order that hold its pairs once: the rest of its row, the row above it
// (y + 1) in its plane, the three rows of the next plane (count_symmetric).
inline constexpr NeighbourGrid::RowOffset count_half_rows[] = {
    {1, 1, 0, 0}, {-1, 1, 1, 0}, {-1, 1, -1, 1}, {-1, 1, 0, 1}, {-1, 1, 1, 1}};

// Whether a point (py, pz) of a cell with faces `box` (block_bounds at reach 0) is farther than
// sqrt(reach2) from every point of the corner rows of its half-block (ranges 2 and 4: y - 1 and y + 1 in
// the next plane): `first` for y - 1, `second` for y + 1. Its distances to the planes the row lies beyond,
// less a margin for the rounding of the binning (cell faces are computed, points are binned by a product
// rounded on its own): only ever a true statement, so skipping the row changes no count.
inline std::pair<bool, bool> corner_rows_out_of_reach(const NeighbourGrid& g, const NeighbourGrid::BlockBounds& box,
                                                      double py, double pz, double reach2) {
    const auto out = [reach2](double gap_y, double gap_z) {
        return gap_y > 0 && gap_z > 0 && gap_y * gap_y + gap_z * gap_z > reach2;
    };
    const double slack = 1e-9 * g.cell_size();
    const double margin_y = slack + 1e-13 * (std::abs(py) + std::abs(box.lower[1]) + std::abs(box.upper[1]));
    const double margin_z = slack + 1e-13 * (std::abs(pz) + std::abs(box.upper[2]));
    const double up = box.upper[2] - pz - margin_z;
    return {out(py - box.lower[1] - margin_y, up), out(box.upper[1] - py - margin_y, up)};
}

// A thread's buffers, kept from cell to cell, and what the float loop did (for tests).
struct FloatCellScratch {
    std::vector<float> x, y, z;                          // the block's coordinates less the cell's first point, scaled
    std::vector<std::int32_t> count;                     // counts gained by the buffered points in this cell
    std::vector<std::uint32_t> sorted;                   // each buffered point's sorted position
    std::uint64_t cells = 0, declined = 0, retests = 0;  // cells counted, left to the caller, exact re-tests
};

// Counts the pairs of the occupied cell [first, last) as count_cell<uniform, unweighted> does: with each
// other and with `ranges` (the cell's count_half_rows), adding to count[] and appending to close_points the
// points with a pair within sqrt(tol2). `support`: every point's (the counts' radius). `box`: the cell's
// faces. Returns false, having changed nothing, when the bound does not cover the cell.
using CountCellFloat = bool (*)(const NeighbourGrid& g, double support, std::uint32_t first, std::uint32_t last,
                                std::span<const NeighbourGrid::Range> ranges, double tol2, std::uint32_t* count,
                                std::vector<std::uint32_t>& close_points, const NeighbourGrid::BlockBounds& box,
                                FloatCellScratch& scratch);

// The float loop when this CPU has AVX2 (and the build is for x86-64), else null.
CountCellFloat count_cell_float();

}  // namespace sphdeck::preproc
