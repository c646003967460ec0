#include "refsolver/radioss_time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sphdeck::refsolver {

namespace {

// -d_ij v_ij.x_ij / (r^2 + 0.01 d_ij^2) of one pair within the support, else 0.
double approach(const Particles& s, std::size_t i, std::size_t j) {
    const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
    const double r2 = dx * dx + dy * dy + dz * dz, d = 0.5 * (s.h[i] + s.h[j]);
    if (r2 >= 4 * d * d) return 0;
    const double vr = (s.vx[i] - s.vx[j]) * dx + (s.vy[i] - s.vy[j]) * dy + (s.vz[i] - s.vz[j]) * dz;
    return -d * vr / (r2 + 0.01 * d * d);
}

}  // namespace

double radioss_particle_time_step(const Particles& s, const NeighbourList& list, double qa, double qb, int threads) {
    const std::size_t n = s.real;
    std::vector<double> mu(n, 0.0);
    // The half list names each real pair once: both particles take its approach (serial: two writes per pair).
    for (std::size_t i = 0; i < n; ++i) {
        if (!s.active[i]) continue;
        for (std::uint32_t k = list.forward_offsets[i]; k < list.forward_offsets[i + 1]; ++k) {
            const std::uint32_t j = list.forward[k];
            const double a = approach(s, i, j);
            mu[i] = std::max(mu[i], a), mu[j] = std::max(mu[j], a);
        }
        for (std::uint32_t k = list.ghost_offsets[i]; k < list.ghost_offsets[i + 1]; ++k)
            mu[i] = std::max(mu[i], approach(s, i, list.ghost[k]));
    }
    double smallest = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(min : smallest) num_threads(threads)
    for (std::size_t i = 0; i < n; ++i) {
        if (!s.active[i]) continue;
        const double q = qb * s.c[i] + qa * mu[i];
        const double speed = q + std::sqrt(q * q + s.c[i] * s.c[i]);
        if (speed > 0) smallest = std::min(smallest, s.h[i] / speed);
    }
    return smallest;
}

}  // namespace sphdeck::refsolver
