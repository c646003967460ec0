#include "refsolver/time_step.hpp"

#include <algorithm>
#include <cmath>

namespace sphdeck::refsolver {

double stable_time_step(const Particles& s, double tssfac, int threads) {
    double smallest = std::numeric_limits<double>::infinity();
    const std::size_t n = s.real;
#pragma omp parallel for schedule(static) reduction(min : smallest) num_threads(threads)
    for (std::size_t i = 0; i < n; ++i) {
        if (!s.active[i]) continue;
        const double speed = std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i]);
        const double accel = std::sqrt(s.ax[i] * s.ax[i] + s.ay[i] * s.ay[i] + s.az[i] * s.az[i]);
        smallest = std::min(smallest, particle_time_step(s.h[i], s.c[i], speed, accel));
    }
    return tssfac * smallest;
}

}  // namespace sphdeck::refsolver
