// verify/sedov_exact: the numerically solved Sedov similarity solution against published values: the
// energy constant alpha (0.984 for gamma 1.4 cylindrical as issue 18 quotes Kamm & Timmes 2007,
// LA-UR-07-2849; 0.851072 spherical, the energy lanl/ExactPack's spherical test uses for r_s = 1 at
// t = 1), the profiles of Kamm 2000 (LA-UR-00-6055, Tables 1 and 2, as tabulated in lanl/ExactPack's
// tests: an independent check of the same solution), the strong-shock jump and the r_s ~ t^(2/(j+2)) law.
#include <doctest/doctest.h>

#include <cmath>

#include "verify/sedov_exact.hpp"

namespace test_sedov_exact_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck::verify;
using doctest::Approx;

namespace {

// rho / rho2, u / u2, p / p2 at xi = r / r_s (unit energy, density and time).
SedovSolution::State scaled(const SedovSolution& s, double xi) {
    const double rs = s.shock_radius(1, 1, 1);
    const double speed = 2.0 / (s.j + 2) * rs;  // dr_s/dt at t = 1
    const double u2 = 2 / (s.gamma + 1) * speed, p2 = 2 / (s.gamma + 1) * speed * speed;
    const SedovSolution::State g = s.sample(xi * rs, 1, 1, 1);
    return {g.rho / s.density_ratio, g.u / u2, g.p / p2};
}

}  // namespace

TEST_CASE("sedov exact: the energy constant alpha for gamma = 1.4 (Kamm & Timmes 2007, ExactPack)") {
    const auto cylindrical = solve_sedov(2, 1.4);
    REQUIRE(cylindrical);
    CHECK(cylindrical->alpha == Approx(0.9840).epsilon(1e-4));
    const auto spherical = solve_sedov(3, 1.4);
    REQUIRE(spherical);
    CHECK(spherical->alpha == Approx(0.851072).epsilon(1e-5));
    CHECK(cylindrical->density_ratio == Approx(6.0));
}

TEST_CASE("sedov exact: cylindrical profiles match Kamm 2000, Table 2 (gamma = 1.4)") {
    const auto s = solve_sedov(2, 1.4);
    REQUIRE(s);
    // lambda, f = u / u2, g = rho / rho2, h = p / p2.
    const double table[][4] = {{0.9998, 0.9996, 0.9973, 0.9985}, {0.9802, 0.9645, 0.7653, 0.8659},
                               {0.9096, 0.8514, 0.3451, 0.5983}, {0.8094, 0.7226, 0.1414, 0.4545},
                               {0.7242, 0.6327, 0.0718, 0.4074}, {0.5180, 0.4448, 0.0123, 0.3760},
                               {0.3000, 0.2571, 0.0008, 0.3730}, {0.1000, 0.0857, 0.0000, 0.3729}};
    for (const auto& row : table) {
        INFO("xi = " << row[0]);
        const SedovSolution::State g = scaled(*s, row[0]);
        CHECK(std::abs(g.u - row[1]) <= 2e-4);
        CHECK(std::abs(g.rho - row[2]) <= 3e-4);
        CHECK(std::abs(g.p - row[3]) <= 2e-4);
    }
}

TEST_CASE("sedov exact: planar profiles match Kamm 2000, Table 1; the shock law and bad input") {
    const auto s = solve_sedov(1, 1.4);
    REQUIRE(s);
    const double table[][4] = {{0.9797, 0.9699, 0.8620, 0.9159},
                               {0.8050, 0.7390, 0.3020, 0.5458},
                               {0.4912, 0.4244, 0.0641, 0.4037},
                               {0.1040, 0.0891, 0.0013, 0.3900}};
    for (const auto& row : table) {
        INFO("xi = " << row[0]);
        const SedovSolution::State g = scaled(*s, row[0]);
        CHECK(std::abs(g.u - row[1]) <= 2e-4);
        CHECK(std::abs(g.rho - row[2]) <= 3e-4);
        CHECK(std::abs(g.p - row[3]) <= 3e-4);
    }
    const auto c = *solve_sedov(2, 1.4);
    // r_s ~ t^(1/2) in 2D, ~ E^(1/4); ambient gas beyond the shock; the jump at the shock.
    CHECK(c.shock_radius(1, 1, 4) == Approx(2 * c.shock_radius(1, 1, 1)));
    CHECK(c.shock_radius(16, 1, 1) == Approx(2 * c.shock_radius(1, 1, 1)));
    const double rs = c.shock_radius(1, 1, 0.5);
    CHECK(c.sample(1.01 * rs, 1, 1, 0.5).rho == 1.0);
    CHECK(c.sample(1.01 * rs, 1, 1, 0.5).p == 0.0);
    CHECK(c.sample(rs, 1, 1, 0.5).rho == Approx(6.0));
    CHECK_FALSE(solve_sedov(0, 1.4));
    CHECK_FALSE(solve_sedov(4, 1.4));
    CHECK_FALSE(solve_sedov(2, 1.0));
}
}  // namespace test_sedov_exact_cpp
