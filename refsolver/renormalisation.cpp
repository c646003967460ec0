#include "refsolver/renormalisation.hpp"

#include <cmath>

namespace sphdeck::refsolver {

std::array<double, 6> inverse_correction(const std::array<double, 6>& b, int dimension, double min_det) {
    const std::array<double, 6> identity{1, 1, 1, 0, 0, 0};
    if (dimension == 2) {
        const double det = b[0] * b[1] - b[3] * b[3];
        if (!(det >= min_det) || !std::isfinite(det)) return identity;
        return {b[1] / det, b[0] / det, 1.0, -b[3] / det, 0.0, 0.0};
    }
    const double xx = b[0], yy = b[1], zz = b[2], xy = b[3], xz = b[4], yz = b[5];
    // Cofactors of the symmetric matrix.
    const double c_xx = yy * zz - yz * yz, c_yy = xx * zz - xz * xz, c_zz = xx * yy - xy * xy;
    const double c_xy = xz * yz - xy * zz, c_xz = xy * yz - xz * yy, c_yz = xy * xz - xx * yz;
    const double det = xx * c_xx + xy * c_xy + xz * c_xz;
    if (!(det >= min_det) || !std::isfinite(det)) return identity;
    return {c_xx / det, c_yy / det, c_zz / det, c_xy / det, c_xz / det, c_yz / det};
}

void compute_corrections(Particles& s, const NeighbourList& list, const CubicSpline& kernel, int threads) {
    const std::size_t real = s.real;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t i = 0; i < real; ++i) {
        std::array<double, 6> b{0, 0, 0, 0, 0, 0};
        if (s.interacting[i]) {
            const double xi = s.x[i], yi = s.y[i], zi = s.z[i], hi = s.h[i];
            for (std::uint32_t k = list.offsets[i]; k < list.offsets[i + 1]; ++k) {
                const std::uint32_t j = list.neighbours[k];
                if (!s.interacting[j]) continue;
                const double dx = xi - s.x[j], dy = yi - s.y[j], dz = zi - s.z[j];
                const double r2 = dx * dx + dy * dy + dz * dz, h = 0.5 * (hi + s.h[j]);
                if (r2 >= 4 * h * h) continue;
                const double w = -s.m[j] / s.rho[j] * kernel.gradient_factor(std::sqrt(r2), h);
                b[0] += w * dx * dx, b[1] += w * dy * dy, b[2] += w * dz * dz;
                b[3] += w * dx * dy, b[4] += w * dx * dz, b[5] += w * dy * dz;
            }
        }
        s.correction[i] =
            s.interacting[i] ? inverse_correction(b, kernel.dimension) : std::array<double, 6>{1, 1, 1, 0, 0, 0};
    }
}

}  // namespace sphdeck::refsolver
