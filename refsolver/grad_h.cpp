#include "refsolver/grad_h.hpp"

#include <cmath>

namespace sphdeck::refsolver {

void compute_grad_h(Particles& s, const NeighbourList& list, const CubicSpline& kernel, bool follows_density,
                    int threads) {
    const std::size_t real = s.real;
    // Dynamic: only thinning particles walk their lists, and in cell order they come in regions (a
    // static split left most threads waiting for the one holding a free surface).
#pragma omp parallel for schedule(dynamic, 512) num_threads(threads)
    for (std::size_t i = 0; i < real; ++i) {
        const double hi = s.h[i];
        // s.drho: the rate of the last evaluation (grad_h.hpp: thinning particles only).
        const bool follows = follows_density && s.interacting[i] && hi > s.h_low[i] && hi < s.h_high[i];
        if (!follows || !(s.drho[i] < 0)) {
            s.omega[i] = 1.0;
            continue;
        }
        double sum = kernel.h_derivative(0.0, hi);  // the particle's own term
        for (std::uint32_t k = list.offsets[i]; k < list.offsets[i + 1]; ++k) {
            const std::uint32_t j = list.neighbours[k];
            if (!s.interacting[j]) continue;
            const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
            const double r2 = dx * dx + dy * dy + dz * dz, h = 0.5 * (hi + s.h[j]);
            if (r2 >= 4 * h * h) continue;
            sum += kernel.h_derivative(std::sqrt(r2), h);
        }
        s.omega[i] = applied_omega(grad_h_omega(hi, s.rho[i], s.m[i], sum, kernel.dimension), s.drho[i]);
    }
    const std::size_t ghosts = s.ghosts();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t k = 0; k < ghosts; ++k) s.omega[real + k] = s.omega[s.ghost_source[k]];
}

}  // namespace sphdeck::refsolver
