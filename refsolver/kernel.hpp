// The cubic B-spline kernel (sph-algorithms.md §1.1, LS-DYNA SPHKERN = 0), in 2D and 3D:
//   W(r, h) = C_d / h^d * theta(q), q = r / h, support 2h,
//   theta = 1 - 1.5 q^2 + 0.75 q^3 (q <= 1), 0.25 (2 - q)^3 (1 < q <= 2), 0 beyond;
//   C_2 = 10 / (7 pi), C_3 = 1 / pi.
// The solver evaluates every pair with the symmetric h_ij = (h_i + h_j) / 2, so the gradient
// grad_i W_ij = x_ij * F(r, h_ij) is exactly antisymmetric in i and j (momentum conservation).
#pragma once

#include <numbers>

namespace sphdeck::refsolver {

struct CubicSpline {
    int dimension = 3;

    static constexpr double support_factor = 2.0;  // support radius over h

    double normalisation() const {  // C_d
        return dimension == 2 ? 10.0 / (7.0 * std::numbers::pi) : 1.0 / std::numbers::pi;
    }
    double h_power(double h) const { return dimension == 2 ? h * h : h * h * h; }

    // W(r, h).
    double value(double r, double h) const {
        const double q = r / h;
        double theta = 0;
        if (q <= 1)
            theta = 1 - 1.5 * q * q + 0.75 * q * q * q;
        else if (q < 2)
            theta = 0.25 * (2 - q) * (2 - q) * (2 - q);
        return normalisation() / h_power(h) * theta;
    }

    // F = (1/r) dW/dr, so that grad_i W_ij = x_ij * F (§1.1: theta' = -3q + 2.25q^2 for q <= 1,
    // -0.75 (2 - q)^2 for 1 < q <= 2; dW/dr = C_d / h^(d+1) theta'). 0 outside the support.
    // Finite at r = 0 (the q <= 1 branch divided by q is -3 + 2.25 q).
    double gradient_factor(double r, double h) const {
        const double q = r / h;
        const double scale = normalisation() / (h_power(h) * h * h);  // C_d / h^(d+2)
        if (q <= 1) return scale * (-3.0 + 2.25 * q);
        if (q < 2) return -scale * 0.75 * (2 - q) * (2 - q) / q;
        return 0.0;
    }

    // dW/dh at fixed r: -C_d / h^(d+1) (d theta(q) + q theta'(q)), for FORM 0's Omega (grad_h.hpp).
    // Its integral over space is 0 (W integrates to 1 at every h).
    double h_derivative(double r, double h) const {
        const double q = r / h;
        double theta = 0, slope = 0;
        if (q <= 1)
            theta = 1 - 1.5 * q * q + 0.75 * q * q * q, slope = -3.0 * q + 2.25 * q * q;
        else if (q < 2)
            theta = 0.25 * (2 - q) * (2 - q) * (2 - q), slope = -0.75 * (2 - q) * (2 - q);
        return -normalisation() / (h_power(h) * h) * (dimension * theta + q * slope);
    }
};

}  // namespace sphdeck::refsolver
