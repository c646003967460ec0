// The right-hand side of one step: every physical term of one pair, gathered over each real
// particle's neighbours in a single pass (parallel over particles, no atomics; the pair terms
// live in continuity.hpp, momentum.hpp, viscosity.hpp, energy.hpp, smoothing_length.hpp).
// Per pair: x_ij, r, h_ij = (h_i + h_j)/2, g_ij = F(r, h_ij) x_ij (kernel.hpp), corrected under
// FORM 1 (renormalisation.hpp). Only pairs where both particles interact count (active and inside
// the SPH time window); ghosts act on real particles only.
#pragma once

#include <array>

#include "refsolver/kernel.hpp"
#include "refsolver/neighbour_list.hpp"
#include "refsolver/particles.hpp"
#include "refsolver/smoothing_length.hpp"
#include "refsolver/viscosity.hpp"

namespace sphdeck::refsolver {

struct RateParameters {
    CubicSpline kernel;
    MonaghanViscosity viscosity;
    bool renormalise = false;  // FORM 1
    SmoothingLengthRule h_rule = SmoothingLengthRule::Divergence;
    std::array<double, 3> body{0, 0, 0};  // body acceleration (body_load.hpp)
    int threads = 1;
};

// Fills ax, ay, az, drho, de, dh of the real particles.
void compute_rates(Particles& s, const NeighbourList& list, const RateParameters& parameters);

}  // namespace sphdeck::refsolver
