// Density by continuity (sph-algorithms.md §5 FORM 0, and §11 as OpenRadioss codes it), in one of two
// forms, with grad_i W_ij evaluated at h_ij (kernel.hpp). Mass is carried by the particles and never
// changes.
// - FORM 0, the number-density form:  d rho_i / dt = (m_i / Omega_i) sum_j v_ij . grad_i W_ij,
//   the time derivative of rho_i = m_i sum_j W_ij (Omega_i = 1: at fixed h; Omega_i, the grad-h
//   factor, where a thinning particle's h grows: grad_h.hpp): the density stays what the particles'
//   positions say. For equal masses it is the common sum_j m_j v_ij . grad W; unlike that one it has
//   no jump where the masses jump on an even lattice (Sod's contact, 8:1), where the heavy neighbours'
//   masses would drive a light particle's density negative.
// - FORM 1, the volume-weighted form:  d rho_i / dt = rho_i sum_j (m_j / rho_j) v_ij . g_ij,
//   g_ij the renormalised gradient (renormalisation.hpp). The correction B_i = -sum_j V_j ... is built
//   with the neighbours' volumes V_j, and with the same weights the divergence of a linear velocity
//   field is exact, which is what FORM 1 is for.
// Why FORM 0 changed (Nov 2026, docs/verification.md §5): the volume-weighted form is the derivative
// of no density of the positions. It integrates the kernel-smoothed divergence along the particle's
// path, and a particle slows down as it crosses a shock, so it lingers where the kernel still sees the
// shock's compression behind it and ends too dense by the same share at every resolution (Noh,
// exact 16: 20.5 / 21.4 at 50 x 50 / 100 x 100 with FORM 0, 15.5 / 16.0 with the number density).
// FORM 1 keeps it (Noh 17.3 / 17.8): with the number density the 8 hot particles of the Sedov decks
// (FORM 1), 1,000 times hotter than their neighbours, are thinned to a negative density and thrown out.
// Lending the pair's mean density, m_j / rho_ij, instead of V_j takes Noh's drift out (15.1 at 100 x 100)
// but leaves the density variable 18 % below the positions at Sedov's shell peak, 25 % low at N = 100
// (gate 20 %): §5's fourth round, not adopted.
#pragma once

namespace sphdeck::refsolver {

// The per-particle values the pair terms read (packed_particle.hpp s6, s7):
// FORM 0 (number density): p V^2 / Omega and 1 / m (0 for a particle that does not interact), Omega
// the grad-h factor (grad_h.hpp; 1 on most particles);
// FORM 1 (volume-weighted): p / rho and V = m / rho.
struct FormValues {
    double s6, s7;
};
inline FormValues form_values(bool volume_weighted, double p, double rho, double m_or_zero, double m,
                              double omega = 1.0) {
    const double volume = m_or_zero / rho;
    if (volume_weighted) return {p / rho, volume};
    return {p * volume * volume / omega, m_or_zero > 0 ? 1.0 / m : 0.0};
}

// One neighbour's share of d rho_i / dt before the factor continuity_factor: V_j v_ij . g_ij (FORM 1),
// v_ij . g_ij (FORM 0). A neighbour that does not interact (s7 = 0 in both forms) adds nothing.
template <bool VolumeWeighted>
inline double continuity_term(double s7_j, double v_dot_g) {
    if constexpr (VolumeWeighted) return s7_j * v_dot_g;
    return s7_j > 0 ? v_dot_g : 0.0;
}

// rho_i (FORM 1) or m_i / Omega_i (FORM 0, grad_h.hpp).
template <bool VolumeWeighted>
inline double continuity_factor(double rho_i, double m_i, double omega_i = 1.0) {
    return VolumeWeighted ? rho_i : m_i / omega_i;
}

}  // namespace sphdeck::refsolver
