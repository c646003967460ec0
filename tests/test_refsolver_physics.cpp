// Reference solver, the pieces against hand calculations: kernel normalisation and gradient,
// equations of state, the FORM 1 correction inverse, load curves.
#include <doctest/doctest.h>

#include <cmath>

#include "refsolver/body_load.hpp"
#include "refsolver/eos.hpp"
#include "refsolver/kernel.hpp"
#include "refsolver/renormalisation.hpp"

namespace test_refsolver_physics_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck::refsolver;

TEST_CASE("refsolver kernel: the cubic spline integrates to 1 in 2D and 3D") {
    const double h = 0.7;
    for (int d : {2, 3}) {
        const CubicSpline w{d};
        const int n = d == 2 ? 400 : 80;  // midpoint rule over [-2h, 2h]^d
        const double step = 4 * h / n;
        double sum = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double x = -2 * h + (i + 0.5) * step, y = -2 * h + (j + 0.5) * step;
                if (d == 2) {
                    sum += w.value(std::hypot(x, y), h) * step * step;
                    continue;
                }
                for (int k = 0; k < n; ++k) {
                    const double z = -2 * h + (k + 0.5) * step;
                    sum += w.value(std::sqrt(x * x + y * y + z * z), h) * step * step * step;
                }
            }
        CHECK(sum == doctest::Approx(1.0).epsilon(2e-4));
    }
}

TEST_CASE("refsolver kernel: the gradient factor matches a finite difference of W") {
    const double h = 1.3;
    for (int d : {2, 3}) {
        const CubicSpline w{d};
        for (double q : {0.1, 0.5, 0.99, 1.01, 1.5, 1.9}) {
            const double r = q * h, dr = 1e-6 * h;
            const double dw_dr = (w.value(r + dr, h) - w.value(r - dr, h)) / (2 * dr);
            CHECK(w.gradient_factor(r, h) * r == doctest::Approx(dw_dr).epsilon(1e-6));
        }
        CHECK(w.gradient_factor(2.0 * h, h) == 0.0);
        CHECK(w.value(2.0 * h, h) == 0.0);
    }
    // W(0) = C_d / h^d: 1 / (pi h^3) in 3D, 10 / (7 pi h^2) in 2D.
    CHECK(CubicSpline{3}.value(0, 2.0) == doctest::Approx(1 / (M_PI * 8)));
    CHECK(CubicSpline{2}.value(0, 2.0) == doctest::Approx(10 / (7 * M_PI * 4)));
}

TEST_CASE("refsolver eos: ideal gas through *EOS_LINEAR_POLYNOMIAL C4 = C5 = gamma - 1") {
    EquationOfState eos;
    eos.kind = EquationOfState::Kind::LinearPolynomial;
    eos.rho0 = 1.0;
    eos.c[4] = eos.c[5] = 0.4;
    // p = (gamma - 1) rho e = 0.4 * 2 * 3 = 2.4; c^2 = gamma p / rho = 1.4 * 2.4 / 2 = 1.68.
    double p = 0, c = 0;
    eos.evaluate(2.0, 3.0, p, c);
    CHECK(p == doctest::Approx(2.4));
    CHECK(c == doctest::Approx(std::sqrt(1.68)));
    // Same gas with rho0 = 4 (E per reference volume = rho0 e): p is still (gamma - 1) rho e.
    eos.rho0 = 4.0;
    CHECK(eos.pressure(2.0, 3.0) == doctest::Approx(2.4));
    CHECK(eos.sound_speed(2.0, 3.0) == doctest::Approx(std::sqrt(1.68)));
}

TEST_CASE("refsolver eos: linear polynomial drops C2 and C6 in expansion; the cut-off holds") {
    EquationOfState eos;
    eos.kind = EquationOfState::Kind::LinearPolynomial;
    eos.rho0 = 1000;
    eos.c[1] = 10, eos.c[2] = 5;
    CHECK(eos.pressure(900, 0) == doctest::Approx(-1.0));         // mu = -0.1: 10 * -0.1
    CHECK(eos.pressure(1100, 0) == doctest::Approx(1.0 + 0.05));  // mu = 0.1: 1 + 5 * 0.01
    CHECK(eos.sound_speed(1000, 0) == doctest::Approx(std::sqrt(10.0 / 1000)));
    eos.pressure_cutoff = 0;
    CHECK(eos.pressure(900, 0) == 0.0);
}

TEST_CASE("refsolver eos: Murnaghan and Gruneisen by hand") {
    EquationOfState m;
    m.kind = EquationOfState::Kind::Murnaghan;
    m.rho0 = 1000, m.gamma = 7, m.k0 = 100;
    CHECK(m.pressure(1010, 0) == doctest::Approx(100 * (std::pow(1.01, 7) - 1)));
    CHECK(m.sound_speed(1000, 0) == doctest::Approx(std::sqrt(7 * 100.0 / 1000)));
    CHECK(m.sound_speed(1010, 0) == doctest::Approx(std::sqrt(7 * 100.0 * std::pow(1.01, 6) / 1000)));

    EquationOfState g;
    g.kind = EquationOfState::Kind::Gruneisen;
    g.rho0 = 1000, g.C = 1500, g.S1 = 1.9, g.gamma0 = 0.5;
    CHECK(g.pressure(1000, 0) == 0.0);
    CHECK(g.sound_speed(1000, 0) == doctest::Approx(1500).epsilon(1e-6));  // c0 = C (§10.2)
    // Expansion: p = rho0 C^2 mu + gamma0 E, E = rho0 e.
    CHECK(g.pressure(990, 2.0) == doctest::Approx(1000 * 1500.0 * 1500 * -0.01 + 0.5 * 1000 * 2));
    // Compression, mu = 0.1: rho0 C^2 mu (1 + (1 - gamma0/2) mu) / (1 - (S1 - 1) mu)^2.
    const double mu = 0.1;
    CHECK(g.pressure(1100, 0) ==
          doctest::Approx(1000 * 1500.0 * 1500 * mu * (1 + 0.75 * mu) / std::pow(1 - 0.9 * mu, 2)));
}

TEST_CASE("refsolver renormalisation: the inverse of B, identity when singular") {
    const auto inv = inverse_correction({2, 4, 5, 0, 0, 0}, 3);
    CHECK(inv[0] == doctest::Approx(0.5));
    CHECK(inv[1] == doctest::Approx(0.25));
    CHECK(inv[2] == doctest::Approx(0.2));
    // A full symmetric matrix: B B^-1 = I.
    const std::array<double, 6> b{2, 3, 4, 0.5, 0.2, -0.3};
    const auto k = inverse_correction(b, 3);
    const double B[3][3] = {{b[0], b[3], b[4]}, {b[3], b[1], b[5]}, {b[4], b[5], b[2]}};
    const double K[3][3] = {{k[0], k[3], k[4]}, {k[3], k[1], k[5]}, {k[4], k[5], k[2]}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            double sum = 0;
            for (int j = 0; j < 3; ++j) sum += B[r][j] * K[j][c];
            CHECK(sum == doctest::Approx(r == c ? 1.0 : 0.0));
        }
    const auto singular = inverse_correction({1, 1e-4, 1, 0, 0, 0}, 3);
    CHECK(singular[1] == 1.0);
    // 2D: only the x-y block counts.
    const auto two = inverse_correction({2, 2, 0, 1, 0, 0}, 2);  // det 3
    CHECK(two[0] == doctest::Approx(2.0 / 3));
    CHECK(two[3] == doctest::Approx(-1.0 / 3));
}

TEST_CASE("refsolver body load: curve interpolation and the LS-DYNA sign") {
    LoadCurve c{{0, 1, 3}, {0, 2, 2}};
    CHECK(c.at(-1) == 0.0);
    CHECK(c.at(0.5) == doctest::Approx(1.0));
    CHECK(c.at(2) == doctest::Approx(2.0));
    CHECK(c.at(10) == 2.0);
    const auto a = body_acceleration({{1, 9.81, {{0, 10}, {1, 1}}}}, 0.3);
    CHECK(a[1] == doctest::Approx(-9.81));  // *LOAD_BODY_Y SF 9.81: gravity along -Y
    CHECK(a[0] == 0.0);
}
}  // namespace test_refsolver_physics_cpp
