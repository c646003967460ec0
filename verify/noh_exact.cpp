#include "verify/noh_exact.hpp"

#include <cmath>

namespace sphdeck::verify {

double NohSolution::post_shock_density() const { return rho0 * std::pow((gamma + 1) / (gamma - 1), j); }

double NohSolution::pre_shock_density(double r, double t) const { return rho0 * std::pow(1 + u0 * t / r, j - 1); }

NohSolution::State NohSolution::sample(double r, double t) const {
    if (r < shock_radius(t)) {
        const double e = 0.5 * u0 * u0;
        const double rho = post_shock_density();
        return {rho, 0.0, (gamma - 1) * rho * e, e};
    }
    return {pre_shock_density(r, t), -u0, 0.0, 0.0};
}

}  // namespace sphdeck::verify
