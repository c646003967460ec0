// Density by continuity (sph-algorithms.md §5 FORM 0, and §11 as OpenRadioss codes it):
//   d rho_i / dt = rho_i sum_j (m_j / rho_j) v_ij . grad_i W_ij
// The volume-weighted form, not sum_j m_j v_ij . grad W: at a density jump (Sod, 8:1) the heavy
// neighbours' masses would otherwise drive a light particle's density negative within a few steps.
// with grad_i W_ij evaluated at h_ij (kernel.hpp) and, under FORM 1, the renormalised gradient
// (renormalisation.hpp). Mass is carried by the particles and never changes.
#pragma once

namespace sphdeck::refsolver {

// One neighbour's share before the factor rho_i: V_j (v_ij . g_ij), V_j = m_j / rho_j.
inline double continuity_term(double volume_j, double v_dot_g) { return volume_j * v_dot_g; }

}  // namespace sphdeck::refsolver
