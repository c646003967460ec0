#include "refsolver/body_load.hpp"

#include <algorithm>

namespace sphdeck::refsolver {

double LoadCurve::at(double time) const {
    if (t.empty()) return 0;
    if (time <= t.front()) return f.front();
    if (time >= t.back()) return f.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), time) - t.begin());
    const double span = t[k] - t[k - 1];
    if (!(span > 0)) return f[k];
    const double w = (time - t[k - 1]) / span;
    return f[k - 1] + w * (f[k] - f[k - 1]);
}

std::array<double, 3> body_acceleration(const std::vector<BodyLoad>& loads, double time) {
    std::array<double, 3> a{0, 0, 0};
    for (const BodyLoad& load : loads) a[load.axis] -= load.scale * load.curve.at(time);
    return a;
}

}  // namespace sphdeck::refsolver
