#include "preproc/time_step.hpp"

#include <cmath>

namespace sphdeck::preproc {

double cfl_time_step(double h, double c, double scale, double speed) {
    const double signal = c + std::abs(speed);
    return signal > 0 && h > 0 ? scale * h / signal : 0.0;
}

double radioss_particle_time_step(double h, double c, double scale, double qa, double qb, double mu_bar) {
    if (!(c > 0) || !(h > 0)) return 0.0;
    const double qx = qb * c + qa * mu_bar;
    return scale * h / (qx + std::sqrt(qx * qx + c * c));
}

}  // namespace sphdeck::preproc
