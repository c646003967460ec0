// Monaghan artificial viscosity, LS-DYNA IAVIS = 0 (sph-algorithms.md §6.1, *CONTROL_SPH manual
// Remark 4):
//   Pi_ij = (-Q2 c_ij phi_ij + Q1 phi_ij^2) / rho_ij   when v_ij . x_ij < 0, else 0,
//   phi_ij = h_ij v_ij . x_ij / (|x_ij|^2 + (0.1 h_ij)^2),
// c_ij, rho_ij, h_ij the pair means; Q1 (quadratic) and Q2 (linear) from
// *CONTROL_BULK_VISCOSITY (defaults 1.5 and 0.06, §12 of lsdyna-sph-cards.md).
// OpenRadioss decks (qa, qb of /PROP/TYPE34) weight phi_ij by the engine's switch
// (f_i + f_j) / 2, f = |div v| / (|div v| + |rot v|) (spforcp.F; radioss_time_step.hpp): the
// viscosity fades where the flow shears rather than compresses. `weight` is 1 otherwise.
#pragma once

namespace sphdeck::refsolver {

struct MonaghanViscosity {
    double q1 = 1.5, q2 = 0.06;

    // `v_dot_x` = v_ij . x_ij, `r2` = |x_ij|^2.
    double pi(double v_dot_x, double r2, double h_ij, double c_ij, double rho_ij, double weight = 1.0) const {
        if (v_dot_x >= 0) return 0.0;
        const double phi = weight * h_ij * v_dot_x / (r2 + 0.01 * h_ij * h_ij);
        return (-q2 * c_ij * phi + q1 * phi * phi) / rho_ij;
    }
};

}  // namespace sphdeck::refsolver
