#include "verify/sod_waves.hpp"

#include "verify/wave_detection.hpp"

namespace sphdeck::verify {

SodWaves detect_sod_waves(std::span<const double> x, std::span<const double> rho, std::span<const double> u,
                          const RiemannSolution& exact, double lo, double hi, double bin_width) {
    SodWaves w;
    const Profile u_profile = binned_profile(x, u, lo, hi, bin_width);
    const Profile rho_profile = binned_profile(x, rho, lo, hi, bin_width);
    w.shock = level_crossing(u_profile, 0.5 * exact.u_star, hi, lo);
    if (!w.shock) return w;
    w.contact = level_crossing(rho_profile, 0.5 * (exact.rho_star_left + exact.rho_star_right), *w.shock, lo);
    const double fan_end = w.contact.value_or(*w.shock);
    if (const auto fit = fit_line(u_profile, lo, fan_end, 0.2 * exact.u_star, 0.8 * exact.u_star)) {
        w.rarefaction_head = fit->x_at(0.0);
        w.rarefaction_tail = fit->x_at(exact.u_star);
    }
    return w;
}

SodWaves exact_sod_waves(const RiemannSolution& exact, double x0, double t) {
    return {x0 + exact.left_head * t, x0 + exact.left_tail * t, x0 + exact.u_star * t, x0 + exact.right_head * t};
}

}  // namespace sphdeck::verify
