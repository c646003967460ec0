// Momentum with the EOS pressure and the Monaghan viscosity (sph-algorithms.md §5 FORM 0 for a
// fluid, sigma = -p I; §6.1 for Pi_ij):
//   dv_i/dt = -sum_j m_j (p_i / rho_i^2 + p_j / rho_j^2 + Pi_ij) g_ij + a_body
// The bracket is symmetric in i and j and g_ij antisymmetric (h_ij, and under FORM 1 the mean of
// the two corrections), so sum_i m_i dv_i/dt = sum_i m_i a_body: momentum is conserved to round-off
// where no load or boundary acts.
#pragma once

namespace sphdeck::refsolver {

// The symmetric pair factor A_ij = p_i / rho_i^2 + p_j / rho_j^2 + Pi_ij, from the precomputed
// p / rho^2 of both particles.
inline double momentum_factor(double p_over_rho2_i, double p_over_rho2_j, double pi_ij) {
    return p_over_rho2_i + p_over_rho2_j + pi_ij;
}

}  // namespace sphdeck::refsolver
