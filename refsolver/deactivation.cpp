#include "refsolver/deactivation.hpp"

namespace sphdeck::refsolver {

std::size_t Deactivation::apply(Particles& s) const {
    std::size_t count = 0;
    const double maxv2 = maxv * maxv;
    for (std::size_t i = 0; i < s.real; ++i) {
        if (!s.active[i]) continue;
        bool off = false;
        if (maxv > 0) off = s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i] > maxv2;
        if (box) {
            const auto& b = *box;
            off = off || s.x[i] < b[0] || s.x[i] > b[1] || s.y[i] < b[2] || s.y[i] > b[3] ||
                  (dimension == 3 && (s.z[i] < b[4] || s.z[i] > b[5]));
        }
        if (off) s.active[i] = 0, s.interacting[i] = 0, ++count;
    }
    return count;
}

}  // namespace sphdeck::refsolver
