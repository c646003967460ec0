#include "verify/surge_front.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sphdeck::verify {

std::optional<double> surge_front(std::span<const double> x, std::span<const double> y,
                                  std::span<const std::uint8_t> active, double spacing, double floor_band) {
    std::vector<std::size_t> near_floor;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (active[i] && y[i] < floor_band) near_floor.push_back(i);
    std::sort(near_floor.begin(), near_floor.end(), [&](std::size_t a, std::size_t b) { return x[a] > x[b]; });
    const double reach2 = 4.0 * spacing * spacing;  // (2 spacings)^2
    for (std::size_t i : near_floor) {              // furthest first; usually the first one has a neighbour
        for (std::size_t j = 0; j < x.size(); ++j) {
            if (j == i || !active[j]) continue;
            const double dx = x[j] - x[i], dy = y[j] - y[i];
            if (dx * dx + dy * dy <= reach2) return x[i];
        }
    }
    return std::nullopt;
}

std::optional<double> interpolate(std::span<const double> t, std::span<const double> f, double at) {
    if (t.empty() || at < t.front() || at > t.back()) return std::nullopt;
    const auto it = std::lower_bound(t.begin(), t.end(), at);
    const std::size_t k = static_cast<std::size_t>(it - t.begin());
    if (k == 0 || t[k] == at) return f[k];
    const double w = (at - t[k - 1]) / (t[k] - t[k - 1]);
    return f[k - 1] + w * (f[k] - f[k - 1]);
}

std::optional<FrontDelay> best_front_delay(std::span<const double> T, std::span<const double> z,
                                           std::span<const double> reference_T, std::span<const double> reference_z,
                                           double max_delay, double step) {
    std::optional<FrontDelay> best;
    if (!(step > 0) || reference_T.size() != reference_z.size()) return best;
    const int steps = static_cast<int>(std::floor(max_delay / step + 1e-9));
    for (int k = 0; k <= steps; ++k) {
        const double delay = k * step;
        double worst = 0;
        bool all = !reference_T.empty();
        for (std::size_t i = 0; i < reference_T.size() && all; ++i) {
            const std::optional<double> simulated = interpolate(T, z, reference_T[i] - delay);
            all = simulated.has_value() && std::isfinite(*simulated);
            if (all) worst = std::max(worst, std::abs(*simulated - reference_z[i]) / std::abs(reference_z[i]));
        }
        if (all && (!best || worst < best->worst_error)) best = FrontDelay{delay, worst};
    }
    return best;
}

}  // namespace sphdeck::verify
