// The local bound of the Verlet skin test (simulation.cpp, needs_rebuild). A pair missing from the
// lists was at least the list radius apart at the build; it can have come within the support only
// if its distance shrank by |d_a - d_b| (d: displacement since the build). The global bound of that
// (the diagonal of the box bounding every displacement) grows with the spread of velocities over the
// whole body: a collapsing column has 7 m/s between its corners while neighbours move together.
// Here: pairs within the support now were within support + 2 max|d| of each other at the build, so
// with cells of that size (binned by build position) both lie in the same or adjacent cells, and
// |d_a - d_b| is at most the diagonal of the box bounding the displacements of the two cells.
#pragma once

#include <vector>

#include "refsolver/particles.hpp"
#include "refsolver/symmetry_ghosts.hpp"

namespace sphdeck::refsolver {

// The box bounding some displacements (empty: lo > hi).
struct DisplacementBox {
    double lo[3], hi[3];
};

// An upper bound of |d_a - d_b| over every pair of active particles (real, or a ghost that exists;
// a ghost's build position and displacement are its source's, mirrored) that lie within `support`
// of each other now. Reads x, y, z and x_built, y_built, z_built; `cells` is scratch, kept by the
// caller between calls (no allocation per step). +infinity when the state is not finite. On
// `threads` threads; the result does not depend on how many.
double closing_bound(const Particles& s, const std::vector<SymmetryPlane>& planes, double support,
                     std::vector<DisplacementBox>& cells, int threads = 1);

}  // namespace sphdeck::refsolver
