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

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <array>
#include <cmath>

#include "refsolver/tensor3.hpp"

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

// L = P Q^-1 in `dimension` dimensions (the z row and column stay zero in 2D). Q^-1 as adj(Q) / det(Q)
// (the cofactors, not Eigen's inverse(), which multiplies by 1 / det: the same digits as before Eigen).
inline Tensor velocity_gradient(const Tensor& P, const Tensor& Q, int dimension) {
    const Eigen::Map<const RowMajorMatrix3d> q = tensor_view(Q);
    Eigen::Matrix3d inverse = -Eigen::Matrix3d::Identity();  // the fallback: Q = -I
    if (dimension == 2) {
        const double det = q.topLeftCorner<2, 2>().determinant();  // det(-Q) = det(Q) for a 2x2 block
        if (det >= 0.01) inverse.topLeftCorner<2, 2>() << q(1, 1) / det, -q(0, 1) / det, -q(1, 0) / det, q(0, 0) / det;
        inverse(2, 2) = 0;
    } else {
        // Column k of adj(Q) is row(k+1) x row(k+2) of Q; det(Q) = row 0 . (row 1 x row 2).
        Eigen::Matrix3d adjugate;
        adjugate.col(0) = q.row(1).cross(q.row(2)).transpose();
        adjugate.col(1) = q.row(2).cross(q.row(0)).transpose();
        adjugate.col(2) = q.row(0).cross(q.row(1)).transpose();
        const double det = q.row(0).dot(adjugate.col(0));
        if (-det >= 0.01) inverse = adjugate / det;  // det(-Q) = -det(Q)
    }
    Tensor L;
    tensor_view(L).noalias() = tensor_view(P) * inverse;
    return L;
}

// dS/dt by the Jaumann rate (header comment). (S Omega^T)_ab = (Omega S)_ba, so the rotation part
// is (Omega S)_ab + (Omega S)_ba: symmetric, and zero-trace whenever S is.
inline SymmetricTensor jaumann_stress_rate(const Tensor& L, const SymmetricTensor& s6, double shear) {
    const Eigen::Map<const RowMajorMatrix3d> l = tensor_view(L);
    const Eigen::Matrix3d strain_rate = 0.5 * (l + l.transpose()), spin = 0.5 * (l - l.transpose());
    const Eigen::Matrix3d os = spin * symmetric_matrix(s6);
    const Eigen::Matrix3d deviator = strain_rate - strain_rate.trace() / 3 * Eigen::Matrix3d::Identity();
    return symmetric_entries(2 * shear * deviator + os + os.transpose());
}

}  // namespace sphdeck::refsolver
