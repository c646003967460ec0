// FORM 0's grad-h factor Omega (refsolver/grad_h.hpp): where it applies, and the Sedov deck run as
// FORM 0, whose hot core collapsed the time step without it (docs/verification.md §5).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/check.hpp"
#include "refsolver/grad_h.hpp"
#include "refsolver/kernel.hpp"
#include "refsolver/neighbour_list.hpp"
#include "refsolver/symmetry_ghosts.hpp"
#include "refsolver/simulation.hpp"

namespace test_refsolver_grad_h_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

TEST_CASE("refsolver grad-h: dW/dh is the derivative of the kernel in h and integrates to 0") {
    const refsolver::CubicSpline kernel{2};
    const double h = 0.7, step = 1e-6;
    for (double r : {0.0, 0.3, 0.69, 0.9, 1.3}) {
        CAPTURE(r);
        const double numeric = (kernel.value(r, h + step) - kernel.value(r, h - step)) / (2 * step);
        CHECK(kernel.h_derivative(r, h) == doctest::Approx(numeric).epsilon(1e-6));
    }
    double integral = 0;  // over the plane, in rings
    const double dr = 1e-4;
    for (double r = dr / 2; r < 2 * h; r += dr) integral += 2 * std::acos(-1.0) * r * kernel.h_derivative(r, h) * dr;
    CHECK(std::abs(integral) < 1e-6);
}

TEST_CASE("refsolver grad-h: each particle's sum runs over all its neighbours, ghosts included") {
    // A cloud with h from 0.05 to 0.08, some particles inactive, some not thinning, two symmetry
    // planes: Omega from the full lists on 1 and 3 threads against a sum over every other point (real
    // and ghost) by brute force.
    using namespace refsolver;
    const CubicSpline kernel{3};
    const std::vector<SymmetryPlane> planes = {{{1, 0, 0}, 0.0}, {{0, 1, 0}, 0.0}};
    std::uint64_t state = 777;
    const auto next = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) / double(1ull << 53);
    };
    for (int threads : {1, 3}) {
        CAPTURE(threads);
        Particles s;
        const std::size_t n = 900;
        s.resize_real(n);
        for (std::size_t i = 0; i < n; ++i) {
            s.x[i] = 0.6 * next(), s.y[i] = 0.6 * next(), s.z[i] = 0.6 * next();
            s.h[i] = 0.05 + 0.03 * next(), s.m[i] = 1e-4, s.rho[i] = 0.4 + next();
            s.h_low[i] = 0.01, s.h_high[i] = i % 11 == 5 ? s.h[i] : 1.0;  // some clamped at HMAX: Omega 1
            s.drho[i] = next() - 0.3, s.model_index[i] = static_cast<std::uint32_t>(i);
            s.active[i] = i % 13 != 7;
        }
        const double radius = 2 * 0.08 + 0.01;
        build_ghosts(s, planes, radius, threads);
        NeighbourList list;
        list.build(s, radius, threads, true);  // the full lists grad-h walks
        s.resize_pair_arrays();
        update_ghosts(s, planes, threads);
        for (std::size_t j = 0; j < s.total(); ++j)
            s.interacting[j] = s.active[j < s.real ? j : s.ghost_source[j - s.real]];
        compute_grad_h(s, list, kernel, true, threads);
        std::size_t applied = 0;
        for (std::size_t i = 0; i < s.real; ++i) {
            const bool thinning = s.interacting[i] && s.h[i] < s.h_high[i] && s.drho[i] < 0;
            double sum = kernel.h_derivative(0.0, s.h[i]);
            for (std::size_t j = 0; j < s.total(); ++j) {
                if (j == i || !s.interacting[j]) continue;
                const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
                const double r2 = dx * dx + dy * dy + dz * dz, h = 0.5 * (s.h[i] + s.h[j]);
                if (r2 < 4 * h * h) sum += kernel.h_derivative(std::sqrt(r2), h);
            }
            const double expected =
                thinning ? applied_omega(grad_h_omega(s.h[i], s.rho[i], s.m[i], sum, 3), s.drho[i]) : 1.0;
            CHECK(s.omega[i] == doctest::Approx(expected).epsilon(1e-12));
            applied += s.omega[i] != 1.0;
        }
        CHECK(applied > 5);  // the cloud does exercise Omega (9 to 11 particles here)
        for (std::size_t k = 0; k < s.ghosts(); ++k) CHECK(s.omega[s.real + k] == s.omega[s.ghost_source[k]]);
    }
}

TEST_CASE("refsolver grad-h: Omega applies only above 1 on a thinning particle, at most 5") {
    // A particle alone (its own term only) would have Omega = 1 - m W(0, h) / rho < 1: not applied.
    const refsolver::CubicSpline kernel{2};
    const double h = 1.0, m = 1.0, rho = 2.0 * kernel.value(0, h);
    const double alone = refsolver::grad_h_omega(h, rho, m, kernel.h_derivative(0, h), 2);
    CHECK(alone == doctest::Approx(0.5));
    CHECK(refsolver::applied_omega(alone, -1.0) == 1.0);
    // Neighbours at the kernel's edge (dW/dh > 0 there): Omega > 1, applied while the density falls.
    const double edge =
        refsolver::grad_h_omega(h, rho, m, kernel.h_derivative(0, h) + 8 * kernel.h_derivative(1.4, h), 2);
    CHECK(edge > 1.0);
    CHECK(refsolver::applied_omega(edge, -1.0) == edge);
    CHECK(refsolver::applied_omega(edge, 0.0) == 1.0);  // not thinning: as before
    CHECK(refsolver::applied_omega(edge, 1.0) == 1.0);
    CHECK(refsolver::applied_omega(40.0, -1.0) == refsolver::omega_ceiling);
}

// The Sedov deck (decks/verification/sedov_2d_35.k: 8 particles 1,000 times hotter than their
// neighbours) with FORM 0: without Omega the hot particles' density went negative as their neighbours
// receded and the run stopped at t = 0.082 with a time step of 3e-17. Run to 0.15 (a few dozen steps).
TEST_CASE("refsolver grad-h: the Sedov deck as FORM 0 runs past the time its hot core collapsed") {
    const std::filesystem::path path =
        std::filesystem::path(SPHDECK_SOURCE_DIR) / "decks" / "verification" / "sedov_2d_35.k";
    std::ifstream in(path);
    REQUIRE(in);
    std::stringstream text;
    text << in.rdbuf();
    std::string deck = text.str();
    const std::string form1 = "       150         1       0.0", form0 = "       150         0       0.0";
    const std::size_t at = deck.find(form1);
    REQUIRE(at != std::string::npos);
    deck.replace(at, form1.size(), form0);
    const engine::CheckResult r = engine::check_buffer(deck, "sedov_form0.k");
    refsolver::RunOptions options;
    options.end_time = 0.15;
    auto setup = refsolver::Simulation::create(r.model, options);
    REQUIRE(setup.simulation);
    refsolver::Simulation& sim = *setup.simulation;
    const double start = sim.totals().total;
    sim.run();
    CHECK(sim.failure().empty());
    CHECK(sim.time() == doctest::Approx(0.15));
    CHECK(sim.steps() < 200);
    double lowest = 1e30;
    for (double rho : sim.state().rho) lowest = std::min(lowest, rho);
    CHECK(lowest > 0.0);
    CHECK(std::abs(sim.totals().total - start) < 1e-3 * start);  // energy kept
}
}  // namespace test_refsolver_grad_h_cpp
