// verify/noh_exact: the Noh implosion's exact solution against the published values (post-shock density
// 16 for gamma 5/3 cylindrical, 64 spherical, 4 planar; shock speed 1/3) and against independent physics:
// the Rankine-Hugoniot jump conditions across the moving shock and mass conservation of the inflow.
#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>

#include "verify/noh_exact.hpp"

namespace test_noh_exact_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck::verify;
using doctest::Approx;

TEST_CASE("noh exact: published values for gamma 5/3 (Noh 1987)") {
    NohSolution s;  // cylindrical
    CHECK(s.shock_speed() == Approx(1.0 / 3.0));
    CHECK(s.post_shock_density() == Approx(16.0));
    CHECK(s.shock_radius(0.6) == Approx(0.2));
    CHECK(s.pre_shock_density(0.2, 0.6) == Approx(4.0));
    const NohSolution::State behind = s.sample(0.1, 0.6);
    CHECK(behind.rho == Approx(16.0));
    CHECK(behind.u == 0.0);
    CHECK(behind.p == Approx(16.0 / 3.0));
    CHECK(behind.e == Approx(0.5));
    const NohSolution::State ahead = s.sample(0.3, 0.6);
    CHECK(ahead.rho == Approx(3.0));
    CHECK(ahead.u == -1.0);
    s.j = 3;
    CHECK(s.post_shock_density() == Approx(64.0));
    s.j = 1;
    CHECK(s.post_shock_density() == Approx(4.0));
    CHECK(s.pre_shock_density(0.3, 0.6) == Approx(1.0));
}

TEST_CASE("noh exact: mass, momentum and energy are conserved across the shock") {
    for (int j = 1; j <= 3; ++j) {
        for (double gamma : {5.0 / 3.0, 1.4}) {
            NohSolution s;
            s.j = j, s.gamma = gamma, s.rho0 = 1.3, s.u0 = 0.7;
            const double t = 0.9, d = s.shock_speed(), rs = s.shock_radius(t);
            const NohSolution::State a = s.sample(rs * (1 + 1e-12), t), b = s.sample(rs * (1 - 1e-12), t);
            INFO("j = " << j << ", gamma = " << gamma);
            // In the frame of the shock: w = u - D.
            const double wa = a.u - d, wb = b.u - d;
            CHECK(a.rho * wa == Approx(b.rho * wb).epsilon(1e-9));
            CHECK(a.p + a.rho * wa * wa == Approx(b.p + b.rho * wb * wb).epsilon(1e-9));
            CHECK(a.e + a.p / a.rho + 0.5 * wa * wa == Approx(b.e + b.p / b.rho + 0.5 * wb * wb).epsilon(1e-9));
            CHECK(b.p == Approx((gamma - 1) * b.rho * b.e));
        }
    }
}

TEST_CASE("noh exact: the inflow conserves mass (d rho/dt + r^(1-j) d(r^(j-1) rho u)/dr = 0)") {
    for (int j = 1; j <= 3; ++j) {
        const NohSolution s{j, 5.0 / 3.0, 1.0, 1.0};
        const double r = 0.7, t = 0.5, eps = 1e-5;
        const double drho_dt = (s.pre_shock_density(r, t + eps) - s.pre_shock_density(r, t - eps)) / (2 * eps);
        auto flux = [&](double x) { return std::pow(x, j - 1) * s.pre_shock_density(x, t) * -s.u0; };
        const double divergence = (flux(r + eps) - flux(r - eps)) / (2 * eps) / std::pow(r, j - 1);
        INFO("j = " << j);
        CHECK(drho_dt + divergence == Approx(0.0).scale(1.0).epsilon(1e-7));
    }
}
}  // namespace test_noh_exact_cpp
