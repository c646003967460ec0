// Deviatoric stress of *MAT_ELASTIC parts: isotropic hypoelasticity (lsdyna-sph-cards.md §17.2:
// RO, E, PR). Literature, cited from general knowledge: Libersky & Petschek 1991 (Lect. Notes
// Phys. 395, 248) and Gray, Monaghan & Swift 2001 (CMAME 190, 6641, eqs. 2.4-2.8), the scheme of
// sph-algorithms.md §5 FORM 0 with sigma = -p I + S:
//   K = E / (3 (1 - 2 PR)), G = E / (2 (1 + PR)), p = K (rho / rho0 - 1) (§10.1 with C1 = K)
//   L = dv/dx, eps_dot = (L + L^T) / 2, Omega = (L - L^T) / 2
//   dS/dt = 2 G (eps_dot - tr(eps_dot) / 3 I) + S Omega^T + Omega S   (Jaumann rate)
// Velocity gradient (gradient correction of Bonet & Lok 1999, CMAME 180, 97; literature): with
// P = sum_j V_j v_ij (x) g_ij and Q = sum_j V_j x_ij (x) g_ij, L = P Q^-1, exact for a linear velocity
// field (so a rigid rotation gives eps_dot = 0 to round-off, at free surfaces too, where the plain
// sum -P is not). Q^-1 is replaced by -I when det(-Q) < 0.01 (as FORM 1 does with B, §5).
// Plane strain (IDIM 2): L has no z row or column, so eps_dot_zz = 0 and S_zz = -(S_xx + S_yy)
// evolves by -2 G tr(eps_dot) / 3: the out-of-plane stress plane strain requires.
// Time step: the dilatational wave speed c = sqrt((K + 4 G / 3) / rho0) (sph-algorithms.md §10.4).
#pragma once

#include <array>
#include <cmath>

namespace sphdeck::refsolver {

using SymmetricTensor = std::array<double, 6>;  // xx yy zz xy xz yz
using Tensor = std::array<double, 9>;           // row-major, [3 a + b]

struct ElasticModuli {
    double bulk = 0, shear = 0;

    static ElasticModuli from_young(double young, double poisson) {
        return {young / (3 * (1 - 2 * poisson)), young / (2 * (1 + poisson))};
    }
    double wave_speed(double rho0) const { return std::sqrt((bulk + 4 * shear / 3) / rho0); }
};

// L = P Q^-1 in `dimension` dimensions (the z row and column stay zero in 2D).
inline Tensor velocity_gradient(const Tensor& P, const Tensor& Q, int dimension) {
    double inv[9] = {-1, 0, 0, 0, -1, 0, 0, 0, -1};  // the fallback: Q = -I
    if (dimension == 2) {
        const double det = Q[0] * Q[4] - Q[1] * Q[3];  // det(-Q) = det(Q) for a 2x2 block
        if (det >= 0.01) inv[0] = Q[4] / det, inv[1] = -Q[1] / det, inv[3] = -Q[3] / det, inv[4] = Q[0] / det;
        inv[8] = 0;
    } else {
        const double c0 = Q[4] * Q[8] - Q[5] * Q[7], c1 = Q[5] * Q[6] - Q[3] * Q[8], c2 = Q[3] * Q[7] - Q[4] * Q[6];
        const double det = Q[0] * c0 + Q[1] * c1 + Q[2] * c2;
        if (-det >= 0.01) {  // det(-Q) = -det(Q)
            inv[0] = c0 / det, inv[1] = (Q[2] * Q[7] - Q[1] * Q[8]) / det, inv[2] = (Q[1] * Q[5] - Q[2] * Q[4]) / det;
            inv[3] = c1 / det, inv[4] = (Q[0] * Q[8] - Q[2] * Q[6]) / det, inv[5] = (Q[2] * Q[3] - Q[0] * Q[5]) / det;
            inv[6] = c2 / det, inv[7] = (Q[1] * Q[6] - Q[0] * Q[7]) / det, inv[8] = (Q[0] * Q[4] - Q[1] * Q[3]) / det;
        }
    }
    Tensor L{};
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            for (int c = 0; c < 3; ++c) L[3 * a + b] += P[3 * a + c] * inv[3 * c + b];
    return L;
}

// dS/dt by the Jaumann rate (header comment). (S Omega^T)_ab = (Omega S)_ba, so the rotation part
// is (Omega S)_ab + (Omega S)_ba: symmetric, and zero-trace whenever S is.
inline SymmetricTensor jaumann_stress_rate(const Tensor& L, const SymmetricTensor& s6, double shear) {
    const double S[9] = {s6[0], s6[3], s6[4], s6[3], s6[1], s6[5], s6[4], s6[5], s6[2]};
    double eps[9], omega[9];
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
            eps[3 * a + b] = 0.5 * (L[3 * a + b] + L[3 * b + a]);
            omega[3 * a + b] = 0.5 * (L[3 * a + b] - L[3 * b + a]);
        }
    const double third_trace = (eps[0] + eps[4] + eps[8]) / 3;
    double os[9] = {};  // Omega S
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            for (int c = 0; c < 3; ++c) os[3 * a + b] += omega[3 * a + c] * S[3 * c + b];
    const auto rate = [&](int a, int b) {
        return 2 * shear * (eps[3 * a + b] - (a == b ? third_trace : 0.0)) + os[3 * a + b] + os[3 * b + a];
    };
    return {rate(0, 0), rate(1, 1), rate(2, 2), rate(0, 1), rate(0, 2), rate(1, 2)};
}

}  // namespace sphdeck::refsolver
