// Positions of the four Sod waves from a particle profile (verification.md §1), by the rules of
// wave_detection.hpp with the exact plateaus as levels:
// - shock: scanning from the right end, where u first crosses u*/2 (u jumps only at the shock);
// - contact: scanning left from the shock, where rho crosses (rho*_L + rho*_R)/2 (only rho jumps there);
// - rarefaction head and tail: a line fitted to u over the fan interior (0.2 u* <= u <= 0.8 u*, left of
//   the contact) meets u = 0 (head) and u = u* (tail); u is linear in x inside the exact fan.
#pragma once

#include <optional>
#include <span>

#include "verify/riemann.hpp"

namespace sphdeck::verify {

struct SodWaves {
    std::optional<double> rarefaction_head, rarefaction_tail, contact, shock;
};

// Particles are averaged in bins of `bin_width` over [lo, hi) first.
SodWaves detect_sod_waves(std::span<const double> x, std::span<const double> rho, std::span<const double> u,
                          const RiemannSolution& exact, double lo, double hi, double bin_width);

// Exact positions at time t for a diaphragm at x0.
SodWaves exact_sod_waves(const RiemannSolution& exact, double x0, double t);

}  // namespace sphdeck::verify
