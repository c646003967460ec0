// Evolution of h (*CONTROL_SPH DERIV, sph-algorithms.md §3.1):
//   DERIV 0: dh/dt = (1/d) h div v;  DERIV 1: dh/dt = (1/d) h (div v)^(1/3)  (real cube root),
// with div v_i = -(1/rho_i) d rho_i/dt (continuity, §3.1 "implementation notes"), d the dimension.
// After each update h is clamped to [HMIN h0, HMAX h0] (*SECTION_SPH, §2.1).
#pragma once

#include <algorithm>
#include <cmath>

namespace sphdeck::refsolver {

enum class SmoothingLengthRule { Divergence = 0, CubeRootDivergence = 1 };

inline double smoothing_length_rate(SmoothingLengthRule rule, int dimension, double h, double rho, double drho) {
    const double div_v = -drho / rho;
    const double rate = rule == SmoothingLengthRule::Divergence ? div_v : std::cbrt(div_v);
    return h * rate / dimension;
}

inline double clamp_smoothing_length(double h, double low, double high) { return std::clamp(h, low, high); }

}  // namespace sphdeck::refsolver
