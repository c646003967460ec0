// The similarity ODEs (derived here from the Euler equations; Sedov ch. IV writes the same system).
// With r_s = A t^delta, delta = 2 / (j + 2), xi = r / r_s and ' = d/d(ln xi):
//   u = (r / t) U(xi),  rho = rho0 G(xi),  p = rho0 (r / t)^2 P(xi).
// Continuity, momentum and the entropy equation become a linear system in (U', G', P'):
//   G U' + (U - delta) G'                          = -j G U
//   (U - delta) U'              + P' / G           = U - U^2 - 2 P / G
//        - gamma (U - delta) G' / G + (U - delta) P' / P = 2 - 2 U
// with determinant (U - delta)(gamma P / G - (U - delta)^2) / P, nonzero behind the shock (the flow is
// subsonic relative to it). Strong-shock values at xi = 1: U = 2 delta / (gamma + 1),
// G = (gamma + 1) / (gamma - 1), P = 2 delta^2 / (gamma + 1). The energy integral
//   E = sigma_j rho0 r_s^(j+2) / t^2 * int_0^1 xi^(j+1) (G U^2 / 2 + P / (gamma - 1)) dxi,
// sigma_j = 2, 2 pi, 4 pi, gives alpha. Integrated with classical RK4 in ln xi (the profiles are power
// laws of xi near the centre, smooth in ln xi).
#include "verify/sedov_exact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace sphdeck::verify {
namespace {

using Vec = std::array<double, 3>;  // U, G, P

Vec sedov_derivative(const Vec& y, int j, double gamma, double delta) {
    const double U = y[0], G = y[1], P = y[2], w = U - delta;
    const double b0 = -j * G * U, b1 = U - U * U - 2 * P / G, b2 = 2 - 2 * U;
    // Row 0: G U' + w G' = b0 -> U' = (b0 - w G') / G.
    // Row 2: -gamma w G'/G + w P'/P = b2 -> P' = P (b2 / w + gamma G' / G).
    // Row 1: w U' + P'/G = b1; substitute both:
    //   w (b0 - w G') / G + (P / G)(b2 / w + gamma G' / G) = b1
    //   G' (-w^2 / G + gamma P / G^2) = b1 - w b0 / G - P b2 / (w G)
    const double coefficient = (gamma * P / G - w * w) / G;
    const double dG = (b1 - w * b0 / G - P * b2 / (w * G)) / coefficient;
    const double dU = (b0 - w * dG) / G;
    const double dP = P * (b2 / w + gamma * dG / G);
    return {dU, dG, dP};
}

Vec axpy(const Vec& y, double a, const Vec& k) { return {y[0] + a * k[0], y[1] + a * k[1], y[2] + a * k[2]}; }

}  // namespace

std::optional<SedovSolution> solve_sedov(int j, double gamma) {
    if (j < 1 || j > 3 || !(gamma > 1)) return std::nullopt;
    SedovSolution s;
    s.j = j, s.gamma = gamma, s.density_ratio = (gamma + 1) / (gamma - 1);
    const double delta = 2.0 / (j + 2);
    const Vec shock{2 * delta / (gamma + 1), (gamma + 1) / (gamma - 1), 2 * delta * delta / (gamma + 1)};
    // Integrate from ln xi = 0 to ln xi = -lowest; the energy integrand falls as xi^(j+2) at least.
    constexpr double lowest = 30.0;  // xi = 1e-13
    constexpr int steps = 60000;     // d(ln xi) = 5e-4; RK4's error is far below what the tests need
    const double d = -lowest / steps;
    Vec y = shock;
    auto integrand = [&](const Vec& v, double xi) {
        return std::pow(xi, j + 2) * (0.5 * v[1] * v[0] * v[0] + v[2] / (gamma - 1));  // dxi = xi d(ln xi)
    };
    double integral = 0, previous = integrand(y, 1.0);
    s.profile.push_back({1.0, 1.0, 1.0, 1.0});
    for (int k = 1; k <= steps; ++k) {
        const Vec k1 = sedov_derivative(y, j, gamma, delta);
        const Vec k2 = sedov_derivative(axpy(y, 0.5 * d, k1), j, gamma, delta);
        const Vec k3 = sedov_derivative(axpy(y, 0.5 * d, k2), j, gamma, delta);
        const Vec k4 = sedov_derivative(axpy(y, d, k3), j, gamma, delta);
        for (int c = 0; c < 3; ++c) y[c] += d / 6 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
        if (!std::isfinite(y[0]) || !std::isfinite(y[1]) || !std::isfinite(y[2]) || y[1] <= 0) break;
        const double xi = std::exp(d * k);
        const double current = integrand(y, xi);
        integral += 0.5 * (previous + current) * -d;  // trapezoid in ln xi
        previous = current;
        // Profile in units of the post-shock state: u / u_2 = (xi U) / U(1), p / p_2 = xi^2 P / P(1).
        // Every step down to xi = 0.5 (the steep shell), every tenth inside.
        if (xi > 0.5 || k % 10 == 0)
            s.profile.push_back({xi, y[1] / shock[1], xi * y[0] / shock[0], xi * xi * y[2] / shock[2]});
    }
    const double sigma = j == 1 ? 2.0 : j == 2 ? 2 * std::numbers::pi : 4 * std::numbers::pi;
    s.alpha = sigma * integral;
    return s;
}

double SedovSolution::shock_radius(double energy, double rho0, double t) const {
    return std::pow(energy / (alpha * rho0), 1.0 / (j + 2)) * std::pow(t, 2.0 / (j + 2));
}

SedovSolution::State SedovSolution::sample(double r, double energy, double rho0, double t) const {
    const double rs = shock_radius(energy, rho0, t);
    const double xi = r / rs;
    if (xi > 1 || profile.empty()) return {rho0, 0, 0};
    const double delta = 2.0 / (j + 2), shock_speed = delta * rs / t;
    const double u2 = 2 / (gamma + 1) * shock_speed, p2 = 2 / (gamma + 1) * rho0 * shock_speed * shock_speed;
    const double rho2 = density_ratio * rho0;
    // profile is in descending xi: find the bracketing pair.
    auto it = std::lower_bound(profile.begin(), profile.end(), xi,
                               [](const SedovProfilePoint& q, double x) { return q.xi > x; });
    if (it == profile.end()) {
        const SedovProfilePoint& q = profile.back();
        return {q.rho * rho2, q.u * u2 * xi / q.xi, q.p * p2};  // the centre: rho -> 0, u linear, p flat
    }
    if (it == profile.begin()) return {it->rho * rho2, it->u * u2, it->p * p2};
    const SedovProfilePoint& a = *(it - 1);  // larger xi
    const SedovProfilePoint& b = *it;
    const double w = (a.xi - xi) / (a.xi - b.xi);
    return {rho2 * (a.rho + w * (b.rho - a.rho)), u2 * (a.u + w * (b.u - a.u)), p2 * (a.p + w * (b.p - a.p))};
}

}  // namespace sphdeck::verify
