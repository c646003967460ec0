// Specific internal energy, the form that conserves energy with momentum.hpp:
//   de_i/dt = 1/2 sum_j m_j A_ij v_ij . g_ij,  A_ij = p_i / rho_i^2 + p_j / rho_j^2 + Pi_ij
// (Monaghan 1992, Annu. Rev. Astron. Astrophys. 30, 543, eq. 2.23 with the viscous term; literature,
// cited from general knowledge). Summed with the kinetic energy the pair terms cancel:
// d/dt sum_i m_i (v_i^2 / 2 + e_i) = sum_i m_i v_i . a_body, so the total drifts only by the time
// integration error (viscous heating keeps the energy the viscosity removes).
#pragma once

namespace sphdeck::refsolver {

inline double energy_term(double m_j, double a_ij, double v_dot_g) { return 0.5 * m_j * a_ij * v_dot_g; }

}  // namespace sphdeck::refsolver
