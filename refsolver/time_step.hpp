// The explicit time step (sph-algorithms.md §7.1, LS-DYNA SPH [unverified]):
//   dt = TSSFAC * min_i h_i / (c_i + |v_i|)
// over the active particles, TSSFAC from *CONTROL_TIMESTEP (0.9 by default). A particle without
// a sound speed at rest (an ideal gas at e = 0, a free particle under gravity) would allow any
// step, so the acceleration bound of Monaghan (1992, §10: dt <= sqrt(h / |a|), literature cited
// from general knowledge) is taken too, with the same factor:
//   dt = TSSFAC * min_i min(h_i / (c_i + |v_i|), sqrt(h_i / |a_i|)).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "refsolver/particles.hpp"

namespace sphdeck::refsolver {

// One particle's bound before TSSFAC, from its h, c, |v| and |a|; +infinity when it bounds nothing.
inline double particle_time_step(double h, double c, double speed, double accel) {
    double bound = std::numeric_limits<double>::infinity();
    if (c + speed > 0) bound = std::min(bound, h / (c + speed));
    if (accel > 0) bound = std::min(bound, std::sqrt(h / accel));
    return bound;
}

// +infinity when no active particle bounds the step.
double stable_time_step(const Particles& s, double tssfac, int threads);

}  // namespace sphdeck::refsolver
