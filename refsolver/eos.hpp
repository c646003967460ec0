// Equations of state of *MAT_NULL parts (sph-algorithms.md §10, lsdyna-sph-cards.md §18):
// pressure and isentropic sound speed from the density and the specific internal energy.
// LS-DYNA writes its EOS with E, the internal energy per unit *reference* volume, and
// mu = rho / rho0 - 1 (§10, †); the solver carries e per unit mass, so E = rho0 * e.
// For the ideal gas (§10.1: C4 = C5 = gamma - 1, the other C zero):
//   p = (C4 + C5 mu) E = (gamma - 1)(1 + mu) rho0 e = (gamma - 1) rho e.
#pragma once

#include <limits>

namespace sphdeck::refsolver {

struct EquationOfState {
    enum class Kind { LinearPolynomial, Gruneisen, Murnaghan };
    Kind kind = Kind::Murnaghan;
    double rho0 = 1;  // the material's RO
    // *EOS_LINEAR_POLYNOMIAL C0..C6.
    double c[7] = {0, 0, 0, 0, 0, 0, 0};
    // *EOS_GRUNEISEN.
    double C = 0, S1 = 0, S2 = 0, S3 = 0, gamma0 = 0, a = 0;
    // *EOS_MURNAGHAN.
    double gamma = 7, k0 = 0;
    // *MAT_NULL PC: the pressure never falls below it († general LS-DYNA usage: PC = 0 allows no
    // tension). -infinity: no cut-off.
    double pressure_cutoff = -std::numeric_limits<double>::infinity();

    // p(rho, e) with the cut-off applied.
    double pressure(double rho, double e) const;
    // c = sqrt(dp/drho at constant entropy), §10: c^2 = (1/rho0) dp/dmu|_E + dp/dE|_mu rho0 p / rho^2;
    // 0 where c^2 <= 0 (tension beyond the stiffness).
    double sound_speed(double rho, double e) const;
    // p and c together (the solver's per-step call).
    void evaluate(double rho, double e, double& p, double& c) const;

private:
    double raw_pressure(double mu, double E) const;  // without the cut-off
};

}  // namespace sphdeck::refsolver
