// OpenRadioss's time steps for SPH particles, used for OpenRadioss decks (learnt from the engine's
// Fortran, OpenRadioss, AGPL-3.0; not copied). Both are returned before the deck's scale factor.
//
// The particle (element) step, without /DT/NODA (mdtsph.F, with spdens.F's mu_max):
//   dt_i = d_i / (q_i + sqrt(q_i^2 + c_i^2)),   q_i = qb c_i + qa mu_max,i,
//   mu_max,i = max(0, max_j -d_ij v_ij.x_ij / (r_ij^2 + 0.01 d_ij^2)),  d_ij = (d_i + d_j) / 2,
// over the neighbours j within the support 2 d_ij (real particles and ghosts), d the smoothing
// length (the solver's h).
//
// The nodal step of /DT/NODA (dtnoda.F: dt = scale * min_i sqrt(2 m_i / K_i)), with the particle
// stiffness K_i summed over its pairs by the engine's pair loop (spforcp.F, "nodal stability"; the
// particle step's own stiffness 2 m / dt^2 that spstres.F leaves there is zeroed by forintp.F
// before the pair loop, so only the pairs count):
//   K_ij = 2 (m_i c_i^2 V_j^2 |g|^2 + m_j c_j^2 V_i^2 |g|^2) / s^2,   V = m / rho, g = grad_i W_ij,
//   s = sqrt(1 + z^2) - z,   z = C_ij / sqrt(2 K_ij m_i)   (the viscosity's damping, before / s^2),
//   C_ij = m_i m_j |Pi_ij| |g| / (|v_ij.x_ij| / r_ij),
//   Pi_ij = (qa mu^2 - qb c_ij mu) 2 / (rho_i + rho_j),  mu = min(0, d_ij v_ij.x_ij / (r^2 + 0.01 d_ij^2)) (f_i + f_j)
//   / 2,
// f_i = |div v_i| / (|div v_i| + |rot v_i|) the engine's viscosity switch (spdens.F's velocity
// gradient: grad v_i = -sum_j V_j v_ij (x) g_ij; spforcp.F). c is the sound speed (the engine's
// SSP_EQ, which adds the material viscosity: none for the laws the solver runs). A ghost adds
// its pair to its real neighbour only, with its source's f.
#pragma once

#include "refsolver/neighbour_list.hpp"
#include "refsolver/particles.hpp"

namespace sphdeck::refsolver {

// The smallest particle step before the scale factor; +infinity when no particle bounds it.
double radioss_particle_time_step(const Particles& s, const NeighbourList& list, double qa, double qb, int threads);

// The smallest nodal step sqrt(2 m_i / K_i) before the scale factor; +infinity when no particle
// has a neighbour.
// `f`: RadiossGradient::f at this state.
double radioss_nodal_time_step(const Particles& s, const NeighbourList& list, const std::vector<double>& f, double qa,
                               double qb, int threads);

// What the engine takes from its velocity gradient (spdens.F) besides the density rate, per real
// particle (0 for one that does not interact):
// - `second_order`: spdens.F's "2nd order correction" of the strain increment, which it adds to
//   each pair's share of the diagonal: E = D - dt1/2 (D^T D) per pair, so that the divergence
//   it integrates is div v - dt1/2 sum_j V_j^2 |v_ij|^2 |g_ij|^2 (the density and h follow it);
// - `f`: the viscosity switch |div v| / max(1e-20, |div v| + |rot v|) of spforcp.F, with that
//   divergence and rot v = sum_j V_j v_ij x g_ij.
struct RadiossGradient {
    std::vector<double> second_order, f;
};
RadiossGradient radioss_velocity_gradient(const Particles& s, const NeighbourList& list, double dt1);

}  // namespace sphdeck::refsolver
