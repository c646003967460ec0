// The "grad-h" factor Omega of FORM 0's number-density continuity (continuity.hpp), on the particles
// that need it: those thinning out while h grows.
// The density FORM 0 follows is rho_i = m_i sum_j W(r_ij, h_ij) (the self term j = i at h_i), and
// DERIV 0 keeps h_i rho_i^(1/d) constant (sph-algorithms.md §3.1). With h changing too, the time
// derivative of the sum is
//   d rho_i/dt = (m_i / Omega_i) sum_j v_ij . grad_i W_ij,
//   Omega_i = 1 + (h_i / (d rho_i)) m_i sum_j dW(r_ij, h_ij)/dh,
// taking h_ij to change at h_i's rate: the Omega of variable-h SPH (Springel & Hernquist 2002, MNRAS
// 333, 649, eqs. 6-8; Price 2012, J. Comput. Phys. 231, 759, §2.5 eqs. 27-29; literature, cited from
// general knowledge), written for the solver's symmetric h_ij. Momentum and energy take the same
// 1 / Omega_i (momentum.hpp's p_i V_i^2 becomes p_i V_i^2 / Omega_i, Springel & Hernquist eq. 7), so
// kinetic plus internal energy stays a constant of the motion whatever Omega_i is.
// Why (29 Nov 2026, issue 41 item 4, docs/verification.md §5): without it, a particle whose h grows
// while its neighbours recede (the hot core of a Sedov blast run as FORM 0, 1,000 times hotter than
// its neighbours) lost more density than its neighbours had given it: the neighbours at the edge of
// its kernel, whose W grows with h (dW/dh > 0 beyond q ~ 1.1: Omega_i > 1), were never added by the
// continuity but were taken away as they left. Its density went negative and the time step
// collapsed (t = 0.08 of 0.5).
// Where it applies: Omega_i > 1 on a particle whose density fell at the last evaluation; elsewhere
// Omega_i = 1, the number-density continuity as before. Measured (docs/verification.md §5), Omega
// everywhere, or with each particle's own h (Price 2012's pairing), made h follow DERIV 0's isotropic
// h ~ rho^(-1/d) where the lattice is compressed in one direction only (the Noh inflow: tangentially,
// with its radial neighbours at the kernel's edge, Omega > 1), lowered the Noh plateau density to
// 14.9-15.0 and moved its front 5.4-6.0 % ahead (gate 5 %); at free surfaces (Omega 0.86 on the
// outer row of a lattice, h = 1.2 dx) it held back the dam-break front 4-7 % behind TrixiParticles'
// at T = 2.0-2.2 (gate 3 %). On compressing particles, at surfaces and in the bulk at rest
// (Omega 0.99 for a square lattice at h = 1.2 dx) nothing changes.
// Omega_i = 1 too where h_i does not follow the density: clamped at HMIN or HMAX, or DERIV 1. It is
// kept at most 1 / omega_floor = 5.
#pragma once

#include "refsolver/kernel.hpp"
#include "refsolver/neighbour_list.hpp"
#include "refsolver/particles.hpp"

namespace sphdeck::refsolver {

inline constexpr double omega_ceiling = 5.0;

// Omega of one particle of mass m, density rho and smoothing length h, from the sum over its
// interacting neighbours and itself of dW(r, h_ij)/dh, in `dimension` dimensions (unclamped).
inline double grad_h_omega(double h, double rho, double m, double dw_dh_sum, int dimension) {
    return rho > 0 ? 1.0 + h * m * dw_dh_sum / (dimension * rho) : 1.0;
}

// The Omega a particle's equations use: Omega where it exceeds 1 on a thinning particle (its density
// rate `drho` of the last evaluation below 0), at most omega_ceiling; else 1.
inline double applied_omega(double omega, double drho) {
    if (!(drho < 0) || !(omega > 1)) return 1.0;
    return omega < omega_ceiling ? omega : omega_ceiling;
}

// Fills Particles::omega of the real particles from the full lists, and of the ghosts from their
// sources. `follows_density` false (DERIV 1): every Omega is 1.
void compute_grad_h(Particles& s, const NeighbourList& list, const CubicSpline& kernel, bool follows_density,
                    int threads);

}  // namespace sphdeck::refsolver
