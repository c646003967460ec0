// Momentum with the EOS pressure and the Monaghan viscosity (sph-algorithms.md §5 FORM 0 for a
// fluid, sigma = -p I; §6.1 for Pi_ij), in the form that pairs with the deck's continuity
// (continuity.hpp):
//   dv_i/dt = -sum_j m_j (A_ij + Pi_ij) g_ij + a_body, with
//   FORM 0 (number density):   A_ij = (p_i V_i^2 / Omega_i + p_j V_j^2 / Omega_j) / (m_i m_j),   V = m / rho,
//                              Omega the grad-h factor (grad_h.hpp; 1 on most particles)
//   FORM 1 (volume-weighted):  A_ij = (p_i + p_j) / (rho_i rho_j)
// With either continuity the pressure work of the pairs is sum_pairs m_i m_j A_ij v_ij . g_ij
// (energy.hpp), so these are the momentum equations that make kinetic plus internal energy a constant
// of the motion while e follows de = (p / rho^2) d rho exactly (the thermodynamically consistent
// pairs; a Lagrangian derivation gives them, for FORM 0 with rho_i = m_i sum_j W_ij: Hopkins 2013,
// MNRAS 428, 2840; Saitoh & Makino 2013, ApJ 768, 44; literature, cited from general knowledge). For
// equal masses FORM 0's is the familiar p_i / rho_i^2 + p_j / rho_j^2; FORM 1's equals it where
// neighbours have the same density. Before Nov 2026, (p_i + p_j) / (rho_i rho_j) for both (Noh too
// dense with FORM 0, continuity.hpp); before that p_i / rho_i^2 + p_j / rho_j^2 with the symmetric
// energy equation (Sedov too dense: docs/verification.md §4).
// A_ij is symmetric in i and j and g_ij antisymmetric (h_ij, and under FORM 1 the mean of the two
// corrections), so sum_i m_i dv_i/dt = sum_i m_i a_body: momentum is conserved to round-off where no
// load or boundary acts.
#pragma once

namespace sphdeck::refsolver {

// A_ij + Pi_ij from both particles' s6, s7 (continuity.hpp FormValues) and densities.
template <bool VolumeWeighted>
inline double momentum_factor(double s6_i, double s7_i, double rho_i, double s6_j, double s7_j, double rho_j,
                              double pi_ij) {
    if constexpr (VolumeWeighted) return (s6_i * rho_i + s6_j * rho_j) / (rho_i * rho_j) + pi_ij;
    return (s6_i + s6_j) * s7_i * s7_j + pi_ij;
}

}  // namespace sphdeck::refsolver
