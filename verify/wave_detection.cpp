#include "verify/wave_detection.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sphdeck::verify {

Profile binned_profile(std::span<const double> x, std::span<const double> f, double lo, double hi, double width) {
    if (x.size() != f.size()) throw std::invalid_argument("binned_profile: x and f differ in length");
    Profile p;
    if (!(width > 0) || !(hi > lo)) return p;
    const std::size_t bins = static_cast<std::size_t>(std::ceil((hi - lo) / width));
    std::vector<double> sum_x(bins, 0.0), sum_f(bins, 0.0);
    std::vector<std::size_t> count(bins, 0);
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!(x[i] >= lo && x[i] < hi)) continue;  // also drops NaN positions
        const std::size_t k = std::min(bins - 1, static_cast<std::size_t>((x[i] - lo) / width));
        sum_x[k] += x[i];
        sum_f[k] += f[i];
        ++count[k];
    }
    for (std::size_t k = 0; k < bins; ++k) {
        if (count[k] == 0) continue;
        p.x.push_back(sum_x[k] / static_cast<double>(count[k]));
        p.f.push_back(sum_f[k] / static_cast<double>(count[k]));
    }
    return p;
}

std::optional<double> level_crossing(const Profile& profile, double level, double from, double to) {
    const std::size_t n = profile.x.size();
    if (n < 2) return std::nullopt;
    const double lo = std::min(from, to), hi = std::max(from, to);
    const bool forward = to >= from;
    for (std::size_t step = 0; step + 1 < n; ++step) {
        // Segment between points a and b, visited in scanning order.
        const std::size_t a = forward ? step : n - 1 - step, b = forward ? a + 1 : a - 1;
        const double xa = profile.x[a], xb = profile.x[b];
        if (std::max(xa, xb) < lo || std::min(xa, xb) > hi) continue;
        const double da = profile.f[a] - level, db = profile.f[b] - level;
        if (da == 0) {
            if (xa >= lo && xa <= hi) return xa;
            continue;
        }
        if ((da < 0) == (db < 0) && db != 0) continue;
        const double x = xa + (xb - xa) * da / (da - db);
        if (x >= lo && x <= hi) return x;
    }
    return std::nullopt;
}

std::optional<LineFit> fit_line(const Profile& profile, double x_lo, double x_hi, double f_a, double f_b) {
    const double f_lo = std::min(f_a, f_b), f_hi = std::max(f_a, f_b);
    double n = 0, sx = 0, sf = 0, sxx = 0, sxf = 0;
    for (std::size_t k = 0; k < profile.x.size(); ++k) {
        const double x = profile.x[k], f = profile.f[k];
        if (x < x_lo || x > x_hi || f < f_lo || f > f_hi) continue;
        n += 1;
        sx += x, sf += f, sxx += x * x, sxf += x * f;
    }
    const double det = n * sxx - sx * sx;
    if (n < 2 || !(std::abs(det) > 0)) return std::nullopt;
    LineFit fit;
    fit.slope = (n * sxf - sx * sf) / det;
    fit.intercept = (sf - fit.slope * sx) / n;
    fit.points = static_cast<std::size_t>(n);
    if (!(std::abs(fit.slope) > 0) || !std::isfinite(fit.slope)) return std::nullopt;
    return fit;
}

}  // namespace sphdeck::verify
