// The pairs of points that may lie within a small reach of each other (coincident particles), found
// without a neighbour grid sized for the kernel support: the neighbour counts' sampled path has cells
// too crowded to scan point by point, yet every coincident pair must still be counted (issue 40's
// coincident-pairs defect: sampled counts reported only the parts' nearest-neighbour pairs).
#pragma once

#include <cstdint>
#include <functional>
#include <span>

namespace sphdeck::preproc {

// Calls `pair(a, b)` (a != b, indices into x, y, z) once for every pair of points within `reach` of
// each other, and for some pairs farther apart (the caller tests the distance). Points are binned by
// 64-bit keys floor(p / cell) with cells of 2 reach (or more, where the coordinates' rounding needs it:
// close_pairs.cpp), sorted, and each key's points paired with their own key's and the 13 keys after it.
// Points with a non-finite coordinate are left out (no distance to them is within any reach). Work:
// n log n, plus the pairs sharing or neighbouring a key.
void for_each_close_pair(std::span<const double> x, std::span<const double> y, std::span<const double> z, double reach,
                         const std::function<void(std::uint32_t, std::uint32_t)>& pair);

}  // namespace sphdeck::preproc
