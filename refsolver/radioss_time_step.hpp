// OpenRadioss's SPH particle time step (the engine's mdtsph.F with spdens.F's mu_max; seed page
// radioss_sph_symmetry_timestep.txt, "particle time step"), used for OpenRadioss decks:
//   dt = scale * min_i d_i / (q_i + sqrt(q_i^2 + c_i^2)),   q_i = qb c_i + qa mu_max,i,
//   mu_max,i = max(0, max_j -d_ij v_ij.x_ij / (r_ij^2 + 0.01 d_ij^2)),  d_ij = (d_i + d_j) / 2,
// over the neighbours j within the support 2 d_ij (real particles and ghosts), d the smoothing
// length (the solver's h). The viscosity enters the step: with qb = 1 the bound at rest is
// d / (c (1 + sqrt2)), which the solver's h / (c + |v|) overshoots by 2.4 times.
// The engine's nodal step (/DT/NODA, dtnoda.F: sqrt(2 m / K*) with the pair stiffness of
// spforcp.F) is not computed: with /DT/NODA the deck's scale multiplies this particle step.
#pragma once

#include "refsolver/neighbour_list.hpp"
#include "refsolver/particles.hpp"

namespace sphdeck::refsolver {

// The smallest particle step before the scale factor; +infinity when no particle bounds it.
double radioss_particle_time_step(const Particles& s, const NeighbourList& list, double qa, double qb, int threads);

}  // namespace sphdeck::refsolver
