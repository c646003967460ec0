// Verlet neighbour lists (sph-algorithms.md §12.1), built for a symmetric pair loop (rates.cpp):
// - `forward`: every pair of real particles within `radius` once, listed under the particle that
//   comes first in cell order (a half list: the pair loop updates both particles);
// - `ghost`: for every real particle, the symmetry-plane ghosts within `radius` (one-sided: ghosts
//   act on real particles only).
// radius = support + skin at the build; the lists hold every pair within the support until some
// distance may have shrunk by the skin (simulation.cpp tests that and rebuilds). They may also hold
// a few pairs just beyond the radius (the single-precision candidate test has a margin); the pair
// loop keeps only the pairs inside the support. Candidates come from preproc's NeighbourGrid
// with cells of radius / 2 (a 5x5x5 block); a real particle scans only the forward half of the
// block, and only particles that have ghosts themselves (near a plane) scan the ghosts' grid.
// The build re-sorts the real particles into the grid's cell order (§12.1: cache locality), so
// index order is cell order and "forward" means a larger index. Parallel over blocks of cells.
#pragma once

#include <cstdint>
#include <vector>

#include "refsolver/particles.hpp"

namespace sphdeck::refsolver {

// Candidates of a list build's scans, in a grid's sorted order: single-precision coordinates
// relative to a point of the domain (tested four at a time), whether each may be listed, and its
// index in the pair arrays. Padded by 4 entries so that a block of four may run past a range's end.
struct ScanCandidates {
    std::vector<float> x, y, z;
    std::vector<std::uint8_t> usable;
    std::vector<std::uint32_t> id;
};

struct NeighbourList {
    // Half list of real pairs: j in forward[forward_offsets[i] .. forward_offsets[i + 1]) has j > i.
    std::vector<std::uint32_t> forward_offsets, forward;
    // Ghosts (indices >= real) near real particle i, same layout.
    std::vector<std::uint32_t> ghost_offsets, ghost;
    // Full lists (every real and ghost neighbour of each real particle), built only when asked
    // (`full` in build: FORM 1's renormalisation.cpp reads them).
    std::vector<std::uint32_t> offsets, neighbours;
    double radius = 0;
    std::uint64_t builds = 0;  // counts build(): what is derived from the lists can tell they changed

    // Sorts the real particles of `s` into cell order (ghosts must be built: their sources are
    // renumbered) and lists the pairs within `radius` of each active real particle; inactive
    // particles (and ghosts of inactive sources) are left out.
    void build(Particles& s, double radius, int threads, bool full = false);
    std::size_t pairs() const { return forward.size() + ghost.size(); }  // real pairs counted once

private:
    // Per-thread output of the last build, kept to avoid reallocating at every rebuild.
    struct Chunk {
        std::vector<std::uint32_t> forward, ghost;
    };
    std::vector<Chunk> chunks_;
    // Work arrays of a build, kept too: fresh ones cost page faults and zeroing at every rebuild.
    ScanCandidates reals_, images_;
    std::vector<std::uint8_t> near_plane_;
    void fill_full_lists();
};

}  // namespace sphdeck::refsolver
