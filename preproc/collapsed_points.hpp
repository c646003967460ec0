// Points at one place counted as one (issue: coincident particles cost time and memory without bound).
// m particles at bit for bit the same coordinates make m (m - 1) / 2 pairs: the neighbour counts would
// evaluate them all (m^2 work, the pair budget then sampling the counts) and the coincident pairs would
// list them all. Each set of at least `least` points with the same coordinates, support and tolerance
// becomes one point that stands for them (its weight): the counts take a neighbour of weight w as w
// neighbours, and the pairs are made from the sets' members (nearest_neighbours.cpp, count_neighbours).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "preproc/nearest_neighbours.hpp"
#include "preproc/neighbour_grid.hpp"

namespace sphdeck::preproc {

struct CollapsedPoints {
    std::vector<double> x, y, z;        // per collapsed point: its place
    std::vector<std::uint32_t> weight;  // per collapsed point: the points it stands for
    std::vector<std::uint32_t> group;   // per collapsed point: the group (GroupedRadii) of its points
    std::vector<std::uint32_t> of;      // per input point: its collapsed point
    // Per collapsed point c: its input points, ascending, members[member_begin[c] .. member_begin[c + 1]).
    std::vector<std::uint32_t> member_begin, members;

    bool empty() const { return weight.empty(); }
    std::span<const std::uint32_t> members_of(std::uint32_t c) const {
        return {members.data() + member_begin[c], members.data() + member_begin[c + 1]};
    }
};

// The sets of at least `least` points of `g` (a grid over the input points) with bit for bit the same
// coordinates, support and tolerance, each made one point; the other points stay themselves, in input
// order. Empty (nothing copied) when there is no such set: only cells of `least` points or more are
// looked into, so a deck without such a crowd costs one pass over the occupied cells.
CollapsedPoints collapse_coincident(const NeighbourGrid& g, const GroupedRadii& radii, std::uint32_t least);

}  // namespace sphdeck::preproc
