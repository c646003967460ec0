// Exact solution of the Riemann problem for the ideal gas (Toro, "Riemann Solvers and Numerical Methods
// for Fluid Dynamics", ch. 4): star pressure by Newton iteration on the pressure function, then the
// self-similar profile as a function of xi = (x - x0) / t. Used for the Sod shock tube
// (verification.md §1), whose table values the tests compare against.
#pragma once

#include <optional>

namespace sphdeck::verify {

struct GasState {
    double rho = 0, u = 0, p = 0;
};

// The four waves bounding the fans and plateaus, as speeds (dx/dt). A shock has head == tail.
struct RiemannSolution {
    double gamma = 1.4;
    GasState left, right;
    double p_star = 0, u_star = 0;
    double rho_star_left = 0, rho_star_right = 0;
    bool left_shock = false, right_shock = false;
    double left_head = 0, left_tail = 0;    // left wave: head (outermost) and tail speeds
    double right_tail = 0, right_head = 0;  // right wave: tail (innermost) and head speeds

    // The state at xi = (x - x0) / t (Toro §4.5, sampling).
    GasState sample(double xi) const;
    // Specific internal energy p / ((gamma - 1) rho) of a state.
    double internal_energy(const GasState& s) const { return s.p / ((gamma - 1.0) * s.rho); }
};

// nullopt when the data are not physical (rho or p <= 0, gamma <= 1) or create a vacuum
// (Toro eq. 4.40: 2 (c_L + c_R) / (gamma - 1) <= u_R - u_L), which this solver does not handle.
std::optional<RiemannSolution> solve_riemann(const GasState& left, const GasState& right, double gamma);

}  // namespace sphdeck::verify
