#include "verify/riemann.hpp"

#include <algorithm>
#include <cmath>

namespace sphdeck::verify {
namespace {

double sound_speed(const GasState& s, double gamma) { return std::sqrt(gamma * s.p / s.rho); }

// Toro eq. 4.6/4.7: the pressure function f_K(p) of one side and its derivative.
struct PressureFunction {
    double value, derivative;
};

PressureFunction pressure_function(double p, const GasState& k, double gamma) {
    const double c = sound_speed(k, gamma);
    if (p > k.p) {  // shock
        const double a = 2.0 / ((gamma + 1.0) * k.rho), b = (gamma - 1.0) / (gamma + 1.0) * k.p;
        const double q = std::sqrt(a / (p + b));
        return {(p - k.p) * q, q * (1.0 - 0.5 * (p - k.p) / (b + p))};
    }
    const double ratio = p / k.p;  // rarefaction
    return {2.0 * c / (gamma - 1.0) * (std::pow(ratio, (gamma - 1.0) / (2.0 * gamma)) - 1.0),
            1.0 / (k.rho * c) * std::pow(ratio, -(gamma + 1.0) / (2.0 * gamma))};
}

// Density behind the wave that brings side k to the star pressure (Toro eqs. 4.50, 4.53, 4.57, 4.60).
double star_density(double p_star, const GasState& k, double gamma) {
    const double ratio = p_star / k.p, g = (gamma - 1.0) / (gamma + 1.0);
    if (p_star > k.p) return k.rho * (ratio + g) / (g * ratio + 1.0);
    return k.rho * std::pow(ratio, 1.0 / gamma);
}

// Shock speed of side k, sign -1 for the left wave and +1 for the right one (Toro eqs. 4.52, 4.59).
double riemann_shock_speed(double p_star, const GasState& k, double gamma, double sign) {
    const double c = sound_speed(k, gamma);
    return k.u + sign * c * std::sqrt((gamma + 1.0) / (2.0 * gamma) * p_star / k.p + (gamma - 1.0) / (2.0 * gamma));
}

}  // namespace

std::optional<RiemannSolution> solve_riemann(const GasState& left, const GasState& right, double gamma) {
    if (!(gamma > 1.0) || !(left.rho > 0) || !(right.rho > 0) || !(left.p > 0) || !(right.p > 0)) return std::nullopt;
    const double cl = sound_speed(left, gamma), cr = sound_speed(right, gamma), du = right.u - left.u;
    if (2.0 * (cl + cr) / (gamma - 1.0) <= du) return std::nullopt;

    // Newton iteration from the primitive-variable guess (Toro eq. 4.47), kept positive.
    const double tiny = 1e-12 * std::min(left.p, right.p);
    double p = std::max(tiny, 0.5 * (left.p + right.p) - 0.125 * du * (left.rho + right.rho) * (cl + cr));
    for (int iteration = 0; iteration < 100; ++iteration) {
        const PressureFunction fl = pressure_function(p, left, gamma), fr = pressure_function(p, right, gamma);
        double next = p - (fl.value + fr.value + du) / (fl.derivative + fr.derivative);
        if (next < tiny) next = tiny;
        const double change = 2.0 * std::abs(next - p) / (next + p);
        p = next;
        if (change < 1e-14) break;
    }
    RiemannSolution s;
    s.gamma = gamma;
    s.left = left;
    s.right = right;
    s.p_star = p;
    s.u_star = 0.5 * (left.u + right.u) +
               0.5 * (pressure_function(p, right, gamma).value - pressure_function(p, left, gamma).value);
    s.rho_star_left = star_density(p, left, gamma);
    s.rho_star_right = star_density(p, right, gamma);
    s.left_shock = p > left.p;
    s.right_shock = p > right.p;
    if (s.left_shock) {
        s.left_head = s.left_tail = riemann_shock_speed(p, left, gamma, -1.0);
    } else {  // Toro eq. 4.55: head u_L - c_L, tail u* - c*_L
        s.left_head = left.u - cl;
        s.left_tail = s.u_star - cl * std::pow(p / left.p, (gamma - 1.0) / (2.0 * gamma));
    }
    if (s.right_shock) {
        s.right_head = s.right_tail = riemann_shock_speed(p, right, gamma, +1.0);
    } else {  // Toro eq. 4.62: head u_R + c_R, tail u* + c*_R
        s.right_head = right.u + cr;
        s.right_tail = s.u_star + cr * std::pow(p / right.p, (gamma - 1.0) / (2.0 * gamma));
    }
    return s;
}

GasState RiemannSolution::sample(double xi) const {
    const double g1 = gamma - 1.0, gp = gamma + 1.0;
    if (xi <= u_star) {  // left of the contact
        if (xi <= left_head) return left;
        if (xi >= left_tail) return {rho_star_left, u_star, p_star};
        // Inside the left fan (Toro eq. 4.56).
        const double cl = std::sqrt(gamma * left.p / left.rho);
        const double base = 2.0 / gp + g1 / (gp * cl) * (left.u - xi);
        return {left.rho * std::pow(base, 2.0 / g1), 2.0 / gp * (cl + 0.5 * g1 * left.u + xi),
                left.p * std::pow(base, 2.0 * gamma / g1)};
    }
    if (xi >= right_head) return right;
    if (xi <= right_tail) return {rho_star_right, u_star, p_star};
    // Inside the right fan (Toro eq. 4.63).
    const double cr = std::sqrt(gamma * right.p / right.rho);
    const double base = 2.0 / gp - g1 / (gp * cr) * (right.u - xi);
    return {right.rho * std::pow(base, 2.0 / g1), 2.0 / gp * (-cr + 0.5 * g1 * right.u + xi),
            right.p * std::pow(base, 2.0 * gamma / g1)};
}

}  // namespace sphdeck::verify
