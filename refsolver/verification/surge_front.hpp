// The surge front of a dam break (verification.md §3): the largest x among the particles near the floor
// (y below `floor_band`) that have another particle within 2 spacings, so that a lone droplet thrown
// ahead does not count as the front. nullopt when no particle qualifies.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

namespace sphdeck::refsolver::verification {

std::optional<double> surge_front(std::span<const double> x, std::span<const double> y,
                                  std::span<const std::uint8_t> active, double spacing, double floor_band);

// Linear interpolation of samples (t ascending) at `t`; nullopt outside [t.front(), t.back()].
std::optional<double> interpolate(std::span<const double> t, std::span<const double> f, double at);

}  // namespace sphdeck::refsolver::verification
