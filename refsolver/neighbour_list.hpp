// Verlet neighbour lists (sph-algorithms.md §12.1): for every real particle, the real and ghost
// particles within radius = support + skin at the time of the build, found on preproc's
// NeighbourGrid (cells of radius / 2, a 5x5x5 block: fewer candidates than 3x3x3 cells of the
// full radius). The lists stay exact until some particle has moved more than skin / 2 (the
// caller tests that and rebuilds), so the grid is not rebuilt every step.
// The build also re-sorts the real particles into the grid's cell order (§12.1: cache locality),
// so one grid serves both; the lists are filled cell by cell, each cell's 25 row ranges found once.
#pragma once

#include <cstdint>
#include <vector>

#include "refsolver/particles.hpp"

namespace sphdeck::refsolver {

struct NeighbourList {
    std::vector<std::uint32_t> offsets;     // real + 1 entries (CSR)
    std::vector<std::uint32_t> neighbours;  // indices into the pair arrays (real or ghost)
    double radius = 0;

    // Sorts the real particles of `s` into cell order (ghosts must be built: they are binned too)
    // and lists the pairs within `radius` of each active real particle; inactive ones are left out.
    void build(Particles& s, double radius, int threads);
    std::size_t pairs() const { return neighbours.size(); }
};

}  // namespace sphdeck::refsolver
