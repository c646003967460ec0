#include "verify/norms.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sphdeck::verify {

ErrorNorms error_norms(std::span<const double> values, std::span<const double> exact, std::span<const double> volumes,
                       NormScale scale) {
    if (values.size() != exact.size() || values.size() != volumes.size())
        throw std::invalid_argument("error_norms: values, exact values and volumes differ in length");
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    ErrorNorms n;
    n.count = values.size();
    if (values.empty()) return {nan, nan, nan, 0};
    double max_exact = 0;
    for (double f : exact) max_exact = std::max(max_exact, std::abs(f));
    double e1 = 0, e2 = 0, einf = 0, s1 = 0, s2 = 0, volume = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double d = std::abs(values[i] - exact[i]), v = volumes[i];
        if (!std::isfinite(d) || !std::isfinite(v)) return {nan, nan, nan, n.count};
        e1 += v * d;
        e2 += v * d * d;
        einf = std::max(einf, d);
        s1 += v * std::abs(exact[i]);
        s2 += v * exact[i] * exact[i];
        volume += v;
    }
    if (scale == NormScale::MaxAbs) {
        s1 = volume * max_exact;
        s2 = volume * max_exact * max_exact;
    }
    n.l1 = s1 > 0 ? e1 / s1 : nan;
    n.l2 = s2 > 0 ? std::sqrt(e2 / s2) : nan;
    n.linf = max_exact > 0 ? einf / max_exact : nan;
    return n;
}

double observed_order(double error_coarse, double error_fine, double ratio) {
    const bool usable =
        error_coarse > 0 && error_fine > 0 && std::isfinite(error_coarse) && std::isfinite(error_fine) && ratio > 1;
    return usable ? std::log(error_coarse / error_fine) / std::log(ratio) : std::numeric_limits<double>::quiet_NaN();
}

double relative_error(double value, double reference) {
    return reference != 0 ? std::abs(value - reference) / std::abs(reference)
                          : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace sphdeck::verify
