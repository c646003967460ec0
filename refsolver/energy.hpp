// Specific internal energy, consistent with the density by continuity (continuity.hpp) and with
// momentum.hpp:
//   de_i/dt = (p_i / rho_i^2) d rho_i/dt + 1/2 sum_j m_j Pi_ij v_ij . g_ij
//           = (p_i V_i / rho_i) sum_j v_ij . g_ij + ...         (FORM 0, number density)
//           = (p_i / rho_i) sum_j V_j v_ij . g_ij + ...         (FORM 1, volume-weighted)
// The first term is each particle's own pdV work (as an EOS integrates energy from its own volume
// change: de = -p dv, v = 1/rho), the second splits the viscous work of each pair equally (Monaghan
// 1992, Annu. Rev. Astron. Astrophys. 30, 543; literature, cited from general knowledge). Summed
// with the kinetic energy the pair terms cancel against momentum.hpp's:
// d/dt sum_i m_i (v_i^2 / 2 + e_i) = sum_i m_i v_i . a_body, so the total drifts only by the time
// integration error (viscous heating keeps the energy the viscosity removes).
// Before (up to Nov 2026) the solver split the pressure work of each pair equally too,
// 1/2 m_j (p_i / rho_i^2 + p_j / rho_j^2): it conserves energy with the p / rho^2 momentum form but
// heats a particle by its neighbour's pressure rather than by its own compression (docs/verification.md §4).
#pragma once

namespace sphdeck::refsolver {

// j's share of de_i, from i's and j's s6, s7 (continuity.hpp FormValues; s7_j = 0: j does not interact).
template <bool VolumeWeighted>
inline double energy_term(double s6_i, double s7_i, double s7_j, double m_j, double pi_ij, double v_dot_g) {
    const double own_work = VolumeWeighted ? s7_j * s6_i : s7_j > 0 ? s6_i * s7_i : 0.0;
    return (own_work + 0.5 * m_j * pi_ij) * v_dot_g;
}

}  // namespace sphdeck::refsolver
