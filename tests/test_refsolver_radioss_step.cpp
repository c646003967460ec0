// The OpenRadioss engine's nodal time step (refsolver/radioss_time_step.hpp, dtnoda.F with the pair
// stiffness of spforcp.F) and its viscosity switch, on two particles whose sums are known by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "refsolver/kernel.hpp"
#include "refsolver/neighbour_list.hpp"
#include "refsolver/particles.hpp"
#include "refsolver/radioss_time_step.hpp"
#include "refsolver/symmetry_ghosts.hpp"

namespace test_refsolver_radioss_step_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck::refsolver;

namespace {

// Two particles 0.8 apart on x (h 1, m 2, rho 4, c 3), the second moving at (vx, vy, 0).
Particles two_particles(double vx, double vy) {
    Particles s;
    s.resize_real(2);
    for (std::size_t i = 0; i < 2; ++i) {
        s.x[i] = 0.8 * double(i), s.y[i] = 0, s.z[i] = 0;
        s.vx[i] = i == 1 ? vx : 0.0, s.vy[i] = i == 1 ? vy : 0.0, s.vz[i] = 0;
        s.h[i] = 1, s.m[i] = 2, s.rho[i] = 4, s.c[i] = 3, s.p[i] = 0;
        s.model_index[i] = static_cast<std::uint32_t>(i);
        s.active[i] = 1, s.interacting[i] = 1;
    }
    return s;
}

}  // namespace

TEST_CASE("refsolver radioss step: at rest the nodal step is sqrt(2 m / K), K = 4 m c^2 V^2 |grad W|^2") {
    Particles s = two_particles(0, 0);
    build_ghosts(s, {}, 2.5);
    NeighbourList list;
    list.build(s, 2.5, 1);
    const RadiossGradient gradient = radioss_velocity_gradient(s, list, 0.0);
    CHECK(gradient.f[0] == 0.0);  // no divergence: the switch is off
    const double g = std::abs(CubicSpline{3}.gradient_factor(0.8, 1.0)) * 0.8, volume = 2.0 / 4.0;
    const double stiffness = 2 * (2 * 9 * volume * volume * g * g + 2 * 9 * volume * volume * g * g);
    CHECK(radioss_nodal_time_step(s, list, gradient.f, 2, 1, 1) == doctest::Approx(std::sqrt(2 * 2 / stiffness)));
}

TEST_CASE("refsolver radioss step: an approaching pair's viscosity shortens the step; shear turns the switch down") {
    Particles s = two_particles(-0.5, 0);  // approaching along the line: pure divergence
    build_ghosts(s, {}, 2.5);
    NeighbourList list;
    list.build(s, 2.5, 1);
    const RadiossGradient gradient = radioss_velocity_gradient(s, list, 0.0);
    CHECK(gradient.f[0] == doctest::Approx(1.0));
    CHECK(gradient.second_order[0] == 0.0);  // dt1 = 0: no second-order term
    const double at_rest = [] {
        Particles r = two_particles(0, 0);
        build_ghosts(r, {}, 2.5);
        NeighbourList l;
        l.build(r, 2.5, 1);
        return radioss_nodal_time_step(r, l, radioss_velocity_gradient(r, l, 0.0).f, 2, 1, 1);
    }();
    CHECK(radioss_nodal_time_step(s, list, gradient.f, 2, 1, 1) < 0.9 * at_rest);
    // The same pair sliding past at right angles: rot v only, no divergence, f = 0.
    Particles shear = two_particles(0, 0.5);
    build_ghosts(shear, {}, 2.5);
    NeighbourList shear_list;
    shear_list.build(shear, 2.5, 1);
    const RadiossGradient sheared = radioss_velocity_gradient(shear, shear_list, 0.1);
    CHECK(sheared.f[0] < 0.05);
    CHECK(sheared.second_order[0] < 0);  // -dt1/2 V^2 |v|^2 |g|^2
    CHECK(radioss_nodal_time_step(shear, shear_list, sheared.f, 2, 1, 1) == doctest::Approx(at_rest));
}
}  // namespace test_refsolver_radioss_step_cpp
