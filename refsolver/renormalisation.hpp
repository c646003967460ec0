// FORM 1, renormalisation (Randles-Libersky type, sph-algorithms.md §5):
//   B_i = sum_j V_j (x_j - x_i) (x) grad_i W_ij = -sum_j V_j F_ij x_ij x_ij^T,
// symmetric since grad_i W_ij = F_ij x_ij; the corrected gradient is B_i^-1 grad_i W_ij, exact for
// linear fields. The solver uses the pair mean g_ij = (B_i^-1 + B_j^-1)/2 grad_i W_ij, which stays
// antisymmetric, so momentum and energy remain conserved (a choice of this solver; LS-DYNA's exact
// FORM 1 pairing is not documented in the references). Where B_i is near-singular (few
// neighbours: det B < 0.01 in the d-dimensional block) the plain gradient is used (B^-1 = I).
#pragma once

#include "refsolver/kernel.hpp"
#include "refsolver/neighbour_list.hpp"
#include "refsolver/particles.hpp"

namespace sphdeck::refsolver {

// Fills Particles::correction of the real particles (B_i^-1); ghosts copy theirs in update_ghosts.
void compute_corrections(Particles& s, const NeighbourList& list, const CubicSpline& kernel, int threads);

// B^-1 of a symmetric B (xx yy zz xy xz yz) in `dimension` (2: the z row and column are ignored);
// the identity when det B < `min_det`.
std::array<double, 6> inverse_correction(const std::array<double, 6>& b, int dimension, double min_det = 0.01);

}  // namespace sphdeck::refsolver
