// Error norms of a particle field against an exact field evaluated at the particle positions, with
// particle volumes V_i = m_i / rho_i as weights (verification.md §9.1), and the observed convergence
// order between two resolutions (§9.2).
#pragma once

#include <cstddef>
#include <span>

namespace sphdeck::verify {

// What the errors are divided by. Pointwise: the same norm of the exact field (§9.1 as written).
// MaxAbs: max |f_exact| times the same weights, for fields that cross zero (§9.1's "absolute scale").
enum class NormScale { Pointwise, MaxAbs };

struct ErrorNorms {
    double l1 = 0, l2 = 0, linf = 0;  // relative; NaN when there is nothing to compare or the scale is 0
    std::size_t count = 0;            // particles compared
};

// `values`, `exact` and `volumes` have the same length (a caller's bug otherwise: std::invalid_argument).
// Non-finite values make the norms NaN (a blown-up run must not pass).
ErrorNorms error_norms(std::span<const double> values, std::span<const double> exact, std::span<const double> volumes,
                       NormScale scale = NormScale::Pointwise);

// p = ln(e_coarse / e_fine) / ln(ratio), ratio = h_coarse / h_fine > 1 (§9.2); NaN when an error
// is not positive and finite.
double observed_order(double error_coarse, double error_fine, double ratio);

// |value - reference| / |reference|; NaN when the reference is 0.
double relative_error(double value, double reference);

}  // namespace sphdeck::verify
