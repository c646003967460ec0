// Wave positions from a particle profile (verification.md §1, "positions of shock and contact").
// Particles of a 2D strip are averaged into bins along x; a jump is located where the binned profile
// crosses the level midway between the exact plateaus on either side (linear interpolation between
// bin centres), and the ends of a rarefaction fan, which are kinks rather than jumps, where a
// straight line fitted to the fan's interior meets the plateau levels (the exact velocity is linear in x
// inside the fan, so the rule is exact for the exact solution).
#pragma once

#include <optional>
#include <span>
#include <vector>

namespace sphdeck::verify {

// Bin centres (mean x of the particles in the bin) and mean values, ascending in x; empty bins left out.
struct Profile {
    std::vector<double> x, f;
};

// Bins [lo + k width, lo + (k+1) width) over [lo, hi); particles outside are left out.
Profile binned_profile(std::span<const double> x, std::span<const double> f, double lo, double hi, double width);

// The first place where the profile crosses `level`, scanning from x = `from` towards x = `to`
// (either direction); nullopt when it never does in that range.
std::optional<double> level_crossing(const Profile& profile, double level, double from, double to);

struct LineFit {
    double slope = 0, intercept = 0;
    std::size_t points = 0;
    double x_at(double f) const { return (f - intercept) / slope; }
};

// Least-squares line f = slope x + intercept through the profile points with x in [x_lo, x_hi] and
// f between f_a and f_b (either order); nullopt with fewer than two points or a flat line.
std::optional<LineFit> fit_line(const Profile& profile, double x_lo, double x_hi, double f_a, double f_b);

}  // namespace sphdeck::verify
