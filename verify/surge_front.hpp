// The surge front of a dam break (verification.md §3): the largest x among the particles near the floor
// (y below `floor_band`) that have another particle within 2 spacings, so that a lone droplet thrown
// ahead does not count as the front. nullopt when no particle qualifies.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

namespace sphdeck::verify {

std::optional<double> surge_front(std::span<const double> x, std::span<const double> y,
                                  std::span<const std::uint8_t> active, double spacing, double floor_band);

// Linear interpolation of samples (t ascending) at `t`; nullopt outside [t.front(), t.back()].
std::optional<double> interpolate(std::span<const double> t, std::span<const double> f, double at);

// A diagnostic, never a gate: the delay d (0 <= d <= max_delay, steps of `step`) for which the simulated
// front delayed by d, Z_sim(T - d), is closest to the reference points (smallest largest relative error),
// and that error. It tells a constant lag (a front that moves at the right speed but starts early, as when
// an experiment's gate takes time to open, verification.md §3) from a wrong speed. nullopt without points.
struct FrontDelay {
    double delay = 0, worst_error = 0;
};
std::optional<FrontDelay> best_front_delay(std::span<const double> T, std::span<const double> z,
                                           std::span<const double> reference_T, std::span<const double> reference_z,
                                           double max_delay, double step);

}  // namespace sphdeck::verify
