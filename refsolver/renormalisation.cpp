#include "refsolver/renormalisation.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>

#include "refsolver/tensor3.hpp"

namespace sphdeck::refsolver {

std::array<double, 6> inverse_correction(const std::array<double, 6>& b, int dimension, double min_det) {
    const std::array<double, 6> identity{1, 1, 1, 0, 0, 0};
    const Eigen::Matrix3d m = symmetric_matrix(b);
    if (dimension == 2) {
        const Eigen::Matrix2d block = m.topLeftCorner<2, 2>();
        const double det = block.determinant();
        if (!(det >= min_det) || !std::isfinite(det)) return identity;
        Eigen::Matrix3d inverse = Eigen::Matrix3d::Identity();
        Eigen::Matrix2d adjugate;
        adjugate << block(1, 1), -block(0, 1), -block(1, 0), block(0, 0);
        inverse.topLeftCorner<2, 2>() = adjugate / det;
        return symmetric_entries(inverse);
    }
    // adj / det rather than Eigen's inverse(), which multiplies by 1 / det: the same digits as
    // before Eigen (issue 41 item 5).
    const Eigen::Matrix3d adjugate = symmetric_adjugate(m);
    const double det = m.col(0).dot(adjugate.col(0));
    if (!(det >= min_det) || !std::isfinite(det)) return identity;
    return symmetric_entries(adjugate / det);
}

void compute_corrections(Particles& s, const NeighbourList& list, const CubicSpline& kernel, int threads) {
    const std::size_t real = s.real;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t i = 0; i < real; ++i) {
        if (!s.interacting[i]) {
            s.correction[i] = {1, 1, 1, 0, 0, 0};
            continue;
        }
        // B_i = sum_j w x_ij x_ij^T, symmetric: its upper triangle is read (the outer product's two
        // triangles differ only in the order of rounding). A full fixed-size outer product unrolls;
        // SelfAdjointView::rankUpdate, which writes one triangle, took 1.7 times the instructions
        // (callgrind, Sedov 35 x 35).
        Eigen::Matrix3d b = Eigen::Matrix3d::Zero();
        const Eigen::Vector3d xi(s.x[i], s.y[i], s.z[i]);
        const double hi = s.h[i];
        for (std::uint32_t k = list.offsets[i]; k < list.offsets[i + 1]; ++k) {
            const std::uint32_t j = list.neighbours[k];
            if (!s.interacting[j]) continue;
            const Eigen::Vector3d d = xi - Eigen::Vector3d(s.x[j], s.y[j], s.z[j]);
            const double r2 = d.squaredNorm(), h = 0.5 * (hi + s.h[j]);
            if (r2 >= 4 * h * h) continue;
            const double w = -s.m[j] / s.rho[j] * kernel.gradient_factor(std::sqrt(r2), h);
            b.noalias() += (w * d) * d.transpose();
        }
        s.correction[i] = inverse_correction(symmetric_entries(b), kernel.dimension);
    }
}

}  // namespace sphdeck::refsolver
