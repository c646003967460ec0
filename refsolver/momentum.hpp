// Momentum with the EOS pressure and the Monaghan viscosity (sph-algorithms.md §5 FORM 0 for a
// fluid, sigma = -p I; §6.1 for Pi_ij), in the form that pairs with the density by continuity of
// continuity.hpp, d rho_i/dt = rho_i sum_j V_j v_ij . g_ij:
//   dv_i/dt = -sum_j m_j ((p_i + p_j) / (rho_i rho_j) + Pi_ij) g_ij + a_body
// With that continuity the pressure work of the pairs is sum_pairs V_i V_j (p_i + p_j) v_ij . g_ij
// (energy.hpp), so this is the momentum equation that makes kinetic plus internal energy a constant
// of the motion while e follows de = (p / rho^2) d rho exactly (the thermodynamically consistent
// pair; a Lagrangian derivation with rho from continuity gives it, literature cited from general
// knowledge). It equals the familiar p_i / rho_i^2 + p_j / rho_j^2 where neighbours have the same
// density. Why not that form (docs/verification.md §4): with it, the energy equation that conserves
// energy is the symmetric one, whose pdV heating does not match each particle's own compression;
// across a strong shock (neighbours at density ratios up to 6) particles ended too dense (Sedov:
// peak 6.75 against 6.16 with this form, 100 x 100).
// The bracket is symmetric in i and j and g_ij antisymmetric (h_ij, and under FORM 1 the mean of
// the two corrections), so sum_i m_i dv_i/dt = sum_i m_i a_body: momentum is conserved to round-off
// where no load or boundary acts.
#pragma once

namespace sphdeck::refsolver {

// The symmetric pair factor A_ij = (p_i + p_j) / (rho_i rho_j) + Pi_ij, from the precomputed p / rho
// of both particles.
inline double momentum_factor(double p_over_rho_i, double rho_i, double p_over_rho_j, double rho_j, double pi_ij) {
    return (p_over_rho_i * rho_i + p_over_rho_j * rho_j) / (rho_i * rho_j) + pi_ij;
}

}  // namespace sphdeck::refsolver
