#include "refsolver/eos.hpp"

#include <algorithm>
#include <cmath>

namespace sphdeck::refsolver {

namespace {

// (rho / rho0)^(gamma - 1) of *EOS_MURNAGHAN: by repeated squaring when gamma is a small whole
// number (7 for water), a few ulps like std::pow at a fraction of its cost (the EOS runs for every
// particle at every step); std::pow otherwise.
double murnaghan_power(double ratio, double gamma) {
    const double n = gamma - 1;
    if (!(n >= 0 && n <= 32 && n == std::floor(n))) return std::pow(ratio, n);
    double result = 1, base = ratio;
    for (auto k = static_cast<unsigned>(n); k != 0; k >>= 1) {
        if (k & 1u) result *= base;
        base *= base;
    }
    return result;
}

}  // namespace

double EquationOfState::raw_pressure(double mu, double E) const {
    switch (kind) {
        case Kind::LinearPolynomial: {
            // §10.1: in expansion (mu < 0) the mu^2 terms C2 and C6 are dropped (†).
            const double mu2 = mu < 0 ? 0.0 : mu * mu;
            return c[0] + c[1] * mu + c[2] * mu2 + c[3] * mu * mu * mu + (c[4] + c[5] * mu + c[6] * mu2) * E;
        }
        case Kind::Gruneisen: {
            // §10.2: compression and expansion branches (†).
            if (mu <= 0) return rho0 * C * C * mu + (gamma0 + a * mu) * E;
            const double num = rho0 * C * C * mu * (1 + (1 - 0.5 * gamma0) * mu - 0.5 * a * mu * mu);
            const double den = 1 - (S1 - 1) * mu - S2 * mu * mu / (mu + 1) - S3 * mu * mu * mu / ((mu + 1) * (mu + 1));
            return num / (den * den) + (gamma0 + a * mu) * E;
        }
        case Kind::Murnaghan:
            // §10.3: p = k0 [(rho/rho0)^gamma - 1], the power as (rho/rho0)^(gamma-1) (rho/rho0):
            // evaluate() needs the first for c too.
            return k0 * (murnaghan_power(1 + mu, gamma) * (1 + mu) - 1);
    }
    return 0;
}

double EquationOfState::pressure(double rho, double e) const {
    return std::max(raw_pressure(rho / rho0 - 1, rho0 * e), pressure_cutoff);
}

void EquationOfState::evaluate(double rho, double e, double& p, double& c_out) const {
    const double mu = rho / rho0 - 1, E = rho0 * e;
    if (kind == Kind::Murnaghan) {  // one power for p and c (raw_pressure's, term for term)
        const double below = murnaghan_power(1 + mu, gamma);
        p = std::max(k0 * (below * (1 + mu) - 1), pressure_cutoff);
        const double c2 = k0 * gamma * below / rho0;  // dp/dmu / rho0; p does not depend on E
        c_out = c2 > 0 && std::isfinite(c2) ? std::sqrt(c2) : 0.0;
        return;
    }
    const double p_raw = raw_pressure(mu, E);
    p = std::max(p_raw, pressure_cutoff);
    double dp_dmu = 0, dp_dE = 0;  // partial derivatives at (mu, E)
    switch (kind) {
        case Kind::LinearPolynomial: {
            const bool expansion = mu < 0;
            dp_dmu = c[1] + (expansion ? 0 : 2 * c[2] * mu) + 3 * c[3] * mu * mu +
                     (c[5] + (expansion ? 0 : 2 * c[6] * mu)) * E;
            dp_dE = c[4] + c[5] * mu + (expansion ? 0 : c[6] * mu * mu);
            break;
        }
        case Kind::Gruneisen: {
            // The compression branch has no short derivative: a central difference.
            const double d = 1e-6 * (1 + std::abs(mu));
            dp_dmu = (raw_pressure(mu + d, E) - raw_pressure(mu - d, E)) / (2 * d);
            dp_dE = gamma0 + a * mu;
            break;
        }
        case Kind::Murnaghan:  // returned above
            break;
    }
    const double c2 = dp_dmu / rho0 + dp_dE * rho0 * p_raw / (rho * rho);
    c_out = c2 > 0 && std::isfinite(c2) ? std::sqrt(c2) : 0.0;
}

double EquationOfState::sound_speed(double rho, double e) const {
    double p = 0, c_out = 0;
    evaluate(rho, e, p, c_out);
    return c_out;
}

}  // namespace sphdeck::refsolver
