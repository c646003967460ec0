// Reference solver runs against exact facts: a lattice at rest in a box of symmetry planes stays
// at rest; two particles conserve momentum and energy; a free particle falls as g t^2 / 2; a
// particle bounces off a symmetry plane; MAXV and BOXID deactivate; FORM 2 is refused; without
// viscosity every particle keeps its entropy.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "test_refsolver_decks.hpp"

namespace test_refsolver_runs_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using namespace sphdeck::test;

namespace {

#ifdef SPHDECK_SANITIZED
constexpr int lattice_side = 6;
#else
constexpr int lattice_side = 12;
#endif

// A square (2D) or cubic (3D) lattice of spacing dx at cell centres in [0, side dx]^d, walled by
// symmetry planes on every side: mirror images complete the lattice exactly.
TestDeck walled_lattice(int dimension, int side, double dx) {
    TestDeck deck;
    deck.idim = dimension;
    deck.rho0 = 1.0;
    // Ideal gas at p0 = 0.4 * E0 = 1 (e0 = 2.5): pressure everywhere, no gradient.
    deck.eos = "*EOS_LINEAR_POLYNOMIAL\n1,0,0,0,0,0.4,0.4,0\n2.5,1\n";
    const double mass = dimension == 2 ? dx * dx : dx * dx * dx;
    const int nz = dimension == 2 ? 1 : side;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i)
                deck.particles.push_back({(i + 0.5) * dx, (j + 0.5) * dx, dimension == 2 ? 0.0 : (k + 0.5) * dx, mass});
    const double L = side * dx;
    std::vector<std::string> planes = {fmt::format("0,0,0,1,0,0"), fmt::format("{},0,0,{},0,0", L, L - 1),
                                       fmt::format("0,0,0,0,1,0"), fmt::format("0,{},0,0,{},0", L, L - 1)};
    if (dimension == 3) planes.push_back("0,0,0,0,0,1"), planes.push_back(fmt::format("0,0,{},0,0,{}", L, L - 1));
    for (const std::string& p : planes) deck.extra += "*BOUNDARY_SPH_SYMMETRY_PLANE\n" + p + "\n";
    deck.endtim = 0.05;
    return deck;
}

}  // namespace

TEST_CASE("refsolver: a uniform lattice at rest in a box of symmetry planes stays at rest, density rho0") {
    for (int dimension : {2, 3})
        for (int form : {0, 1}) {
            CAPTURE(dimension);
            CAPTURE(form);
            TestDeck deck = walled_lattice(dimension, dimension == 2 ? 2 * lattice_side : lattice_side, 0.1);
            deck.form = form;
            auto setup = solver_for(deck);
            REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
            refsolver::Simulation& sim = *setup.simulation;
            for (int s = 0; s < 20; ++s) sim.step();
            const auto& st = sim.state();
            double vmax = 0, drho = 0;
            for (std::size_t i = 0; i < st.size(); ++i) {
                vmax = std::max(vmax, std::abs(st.vx[i]) + std::abs(st.vy[i]) + std::abs(st.vz[i]));
                drho = std::max(drho, std::abs(st.rho[i] - 1.0));
            }
            // Sound speed sqrt(1.4 p / rho) = 1.18: round-off only.
            CHECK(vmax < 1e-12);
            CHECK(drho < 1e-12);
            CHECK(sim.totals().mass == doctest::Approx(deck.particles.size() * deck.particles[0].mass).epsilon(1e-12));
        }
}

// Two particles of ideal gas (e0 = 1) approaching each other, masses 1 and 2 (so their densities differ).
TestDeck two_approaching_particles(double tssfac) {
    TestDeck deck;
    deck.sphini = 1.0;
    deck.hmin = deck.hmax = 1.0;
    deck.eos = "*EOS_LINEAR_POLYNOMIAL\n1,0,0,0,0,0.4,0.4,0\n1.0,1\n";
    deck.particles = {{0, 0, 0, 1.0, 0.3, 0.05, 0}, {1.5, 0.2, 0, 2.0, -0.4, 0, 0.1}};
    deck.endtim = 6.0;
    deck.tssfac = tssfac;
    return deck;
}

// FORM 1 too: the volume-weighted continuity with its momentum factor (continuity.hpp, momentum.hpp).
TEST_CASE("refsolver: two particles approaching conserve momentum and energy; mass is exact") {
    for (int form : {0, 1}) {
        CAPTURE(form);
        TestDeck deck = two_approaching_particles(0.1);
        deck.form = form;
        auto setup = solver_for(deck);
        REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
        refsolver::Simulation& sim = *setup.simulation;
        const refsolver::Totals start = sim.totals();
        // Momentum by hand: 1 (0.3, 0.05, 0) + 2 (-0.4, 0, 0.1) = (-0.5, 0.05, 0.2).
        CHECK(start.momentum[0] == doctest::Approx(-0.5));
        CHECK(start.internal == doctest::Approx(3.0));  // sum m e0 = 1 + 2
        double closest = 1e9;
        sim.run([&](const refsolver::Simulation& s) {
            const auto& st = s.state();
            closest = std::min(closest, std::hypot(st.x[0] - st.x[1], st.y[0] - st.y[1], st.z[0] - st.z[1]));
        });
        const refsolver::Totals end = sim.totals();
        CHECK(closest < 1.4);  // they did interact (support 2h = 2)
        for (int a = 0; a < 3; ++a) CHECK(std::abs(end.momentum[a] - start.momentum[a]) < 1e-14);
        CHECK(end.mass == start.mass);
        CHECK(end.total == doctest::Approx(start.total).epsilon(1e-4));
        CHECK(end.internal != doctest::Approx(start.internal).epsilon(1e-4));  // energy did change form
    }
}

// energy.hpp / momentum.hpp: each particle's internal energy follows its own compression, de = (p / rho^2)
// d rho, so without viscosity an ideal gas keeps p / rho^gamma (here e / rho^0.4) on every particle, even
// where neighbours have different densities. The former symmetric split, 1/2 m_j (p_i / rho_i^2 +
// p_j / rho_j^2) v_ij . g_ij, heated each particle by its neighbour's pressure: with masses 1 and 2 (so
// different densities as they approach) e / rho^0.4 drifted by 2.6e-3, now 3e-6 (time integration).
TEST_CASE("refsolver: without viscosity each particle stays on its adiabat, e / rho^(gamma - 1) constant") {
    const TestDeck deck = two_approaching_particles(0.05);
    auto setup = solver_for(deck);
    REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
    refsolver::Simulation& sim = *setup.simulation;
    double largest_drift = 0, largest_change = 0, density_gap = 0;
    sim.run([&](const refsolver::Simulation& s) {
        const auto& st = s.state();
        for (std::size_t i = 0; i < 2; ++i) {
            largest_drift = std::max(largest_drift, std::abs(st.e[i] / std::pow(st.rho[i], 0.4) - 1.0));
            largest_change = std::max(largest_change, std::abs(st.e[i] - 1.0));
        }
        density_gap = std::max(density_gap, std::abs(st.rho[0] - st.rho[1]));
    });
    CHECK(density_gap > 0.05);     // the two densities did differ
    CHECK(largest_change > 0.02);  // e changed with the compression
    CHECK(largest_drift < 1e-4);   // ... along each particle's adiabat (3e-6; the former form: 2.6e-3)
}

// continuity.hpp: under FORM 0 the density is the number density, d rho_i/dt = m_i sum_j v_ij . grad W_ij,
// so with h fixed each particle's density changes exactly as m_i sum_j W_ij does (up to the time
// integration): for two particles of masses 1 and 2, by m_i (W(r) - W(r0)). The volume-weighted form
// (FORM 1; FORM 0 before Nov 2026) does not: it changes particle 1 by rho_1 V_2 (...), twice as much
// here at the start, which left the Noh implosion too dense: 21.4 for 16 (docs/verification.md §5).
TEST_CASE("refsolver: under FORM 0 the density follows m_i sum_j W_ij of the positions") {
    TestDeck deck;
    deck.sphini = 1.0;
    deck.hmin = deck.hmax = 1.0;
    deck.eos = "*EOS_LINEAR_POLYNOMIAL\n1,0,0,0,0,0.4,0.4,0\n1.0,1\n";  // ideal gas, e0 = 1
    deck.particles = {{0, 0, 0, 1.0, 0.3, 0, 0}, {1.5, 0, 0, 2.0, -0.3, 0, 0}};
    deck.endtim = 1.5;
    deck.tssfac = 0.05;
    auto setup = solver_for(deck);
    REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
    const auto kernel = [](double r) {  // 3D cubic spline at h = 1 (kernel.hpp)
        const double q = r;
        const double theta = q < 1   ? 1 - 1.5 * q * q + 0.75 * q * q * q
                             : q < 2 ? 0.25 * (2 - q) * (2 - q) * (2 - q)
                                     : 0.0;
        return theta / std::acos(-1.0);
    };
    refsolver::Simulation& sim = *setup.simulation;
    const double w0 = kernel(1.5);
    sim.run();
    const auto& st = sim.state();
    const double w = kernel(std::hypot(st.x[1] - st.x[0], st.y[1] - st.y[0]));
    CHECK(w - w0 > 0.05);  // they came closer: the kernel value grew by far more than the tolerance
    CHECK(st.rho[0] - 1.0 == doctest::Approx(1.0 * (w - w0)).epsilon(1e-4));
    CHECK(st.rho[1] - 1.0 == doctest::Approx(2.0 * (w - w0)).epsilon(1e-4));
}

TEST_CASE("refsolver: an isolated particle falls under *LOAD_BODY_Y as y0 - g t^2 / 2") {
    TestDeck deck;
    deck.sphini = 0.1;
    deck.eos = "*EOS_MURNAGHAN\n1,7,100,1\n";
    deck.particles = {{0, 10, 0, 1.0}};
    deck.extra = "*LOAD_BODY_Y\n1,9.81\n*DEFINE_CURVE\n1\n0,1\n100,1\n";
    deck.endtim = 0.5;
    auto setup = solver_for(deck);
    REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
    setup.simulation->run();
    const auto& st = setup.simulation->state();
    CHECK(setup.simulation->time() == doctest::Approx(0.5));
    CHECK(st.y[0] == doctest::Approx(10 - 0.5 * 9.81 * 0.25).epsilon(1e-12));
    CHECK(st.vy[0] == doctest::Approx(-9.81 * 0.5).epsilon(1e-12));
    CHECK(st.x[0] == 0.0);
    // Energy balance: the kinetic energy equals the work of gravity.
    const auto t = setup.simulation->totals();
    CHECK(t.kinetic == doctest::Approx(t.external_work).epsilon(1e-9));
}

TEST_CASE("refsolver: a particle thrown at a symmetry plane bounces back and never crosses it") {
    TestDeck deck;
    deck.sphini = 0.5;
    deck.hmin = deck.hmax = 1.0;
    deck.eos = "*EOS_LINEAR_POLYNOMIAL\n1,0,0,0,0,0.4,0.4,0\n1.0,1\n";  // ideal gas, c = 0.75
    deck.particles = {{0, 0.8, 0, 1.0, 0, -0.5, 0}};
    deck.extra = "*BOUNDARY_SPH_SYMMETRY_PLANE\n0,0,0,0,1,0\n";
    deck.endtim = 6.0;
    auto setup = solver_for(deck);
    REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
    double lowest = 1e9;
    setup.simulation->run([&](const refsolver::Simulation& s) { lowest = std::min(lowest, s.state().y[0]); });
    const auto& st = setup.simulation->state();
    CHECK(lowest > 0.0);
    CHECK(lowest < 0.8);
    CHECK(st.vy[0] > 0.0);  // on its way back
}

TEST_CASE("refsolver: MAXV deactivates a particle once it is too fast; it then stays where it was") {
    TestDeck deck;
    deck.sphini = 0.1;
    deck.eos = "*EOS_MURNAGHAN\n1,7,100,1\n";
    deck.maxv = 5.0;
    deck.particles = {{0, 10, 0, 1.0}};
    deck.extra = "*LOAD_BODY_Y\n1,9.81\n*DEFINE_CURVE\n1\n0,1\n100,1\n";
    deck.endtim = 1.0;
    auto setup = solver_for(deck);
    REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
    refsolver::Simulation& sim = *setup.simulation;
    double off_at = -1;
    sim.run([&](const refsolver::Simulation& s) {
        if (off_at < 0 && !s.state().active[0]) off_at = s.time();
    });
    const auto& st = sim.state();
    CHECK(st.active[0] == 0);
    // |v| = g t passes 5 at t = 0.5097: deactivated within a step of that, and frozen there.
    CHECK(off_at == doctest::Approx(5.0 / 9.81).epsilon(0.02));
    CHECK(std::abs(st.vy[0]) == doctest::Approx(5.0).epsilon(0.02));
    CHECK(st.y[0] == doctest::Approx(10 - 0.5 * 9.81 * off_at * off_at).epsilon(1e-3));
    CHECK(sim.totals().active == 0);
    CHECK(sim.totals().mass == 0.0);
}

TEST_CASE("refsolver: BOXID deactivates a particle that leaves the box") {
    TestDeck deck;
    deck.sphini = 0.1;
    deck.eos = "*EOS_MURNAGHAN\n1,7,100,1\n";
    deck.boxid = 7;
    deck.particles = {{0, 0, 0, 1.0, 2.0, 0, 0}, {-5, 0, 0, 1.0}};
    deck.extra = "*DEFINE_BOX\n7,-10,1,-1,1,-1,1\n";
    deck.endtim = 1.0;
    auto setup = solver_for(deck);
    REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
    setup.simulation->run();
    const auto& st = setup.simulation->state();
    CHECK(st.active[0] == 0);  // left through x = 1 at t = 0.5
    CHECK(st.x[0] == doctest::Approx(1.0).epsilon(0.05));
    CHECK(st.active[1] == 1);
    CHECK(setup.simulation->totals().active == 1);
}

// A particle that does not interact yet (its part's *SECTION_SPH START is later) stays in the neighbour
// lists but is no neighbour: under FORM 0 the number-density terms (continuity.hpp) must not count it
// either, though they carry no factor of its mass or volume.
TEST_CASE("refsolver: a particle whose part has not started changes no density, FORM 0 and 1") {
    for (int form : {0, 1}) {
        CAPTURE(form);
        const std::string deck = fmt::format(
            "*KEYWORD\n*CONTROL_TERMINATION\n0.3\n*CONTROL_TIMESTEP\n0,0.3\n"
            "*CONTROL_SPH\n1,0,1e20,3,150,{}\n*CONTROL_BULK_VISCOSITY\n1.5,0.06\n"
            "*SECTION_SPH\n1,1.2,0.2,2.0,0.1\n*SECTION_SPH\n2,1.2,0.2,2.0,0.1,1e20,10.0\n"
            "*PART\nmoving\n1,1,1,1\n*PART\nnot yet\n2,2,1,1\n*MAT_NULL\n1,1.0,-1e30\n"
            "*EOS_MURNAGHAN\n1,7,100,1\n*NODE\n1,0,0,0\n2,0.25,0,0\n*ELEMENT_SPH\n1,1,1.0\n2,2,1.0\n"
            "*SET_NODE_LIST\n100\n1\n*INITIAL_VELOCITY\n100\n0.5,0,0\n*END\n",
            form);
        const engine::CheckResult r = engine::check_buffer(deck, "test.k");
        auto setup = refsolver::Simulation::create(r.model);
        REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
        setup.simulation->run();
        const auto& st = setup.simulation->state();
        CHECK(st.active[1] == 1);
        CHECK(std::abs(st.x[0] - st.x[1]) < 0.15);  // well within the support (0.2) at the end
        CHECK(st.rho[0] == 1.0);
        CHECK(st.vx[0] == 0.5);
    }
}

TEST_CASE("refsolver: FORM 2 is refused with a message naming FORM and what is supported") {
    TestDeck deck;
    deck.form = 2;
    deck.sphini = 0.1;
    deck.particles = {{0, 0, 0, 1.0}};
    auto setup = solver_for(deck);
    CHECK_FALSE(setup.simulation);
    const std::string text = unsupported_text(setup);
    CHECK(text.find("FORM 2") != std::string::npos);
    CHECK(text.find("FORM 0") != std::string::npos);
    CHECK(text.find("FORM 1") != std::string::npos);
    refsolver::RunOptions ignore;
    ignore.ignore_unsupported = true;
    CHECK(solver_for(deck, ignore).simulation);  // runs as FORM 0 when told to
}

TEST_CASE("refsolver: a material without an EOS cannot run, even with --ignore-unsupported") {
    TestDeck deck;
    deck.eos = "";
    deck.sphini = 0.1;
    deck.particles = {{0, 0, 0, 1.0}};
    refsolver::RunOptions ignore;
    ignore.ignore_unsupported = true;
    auto setup = solver_for(deck, ignore);
    CHECK_FALSE(setup.simulation);
    CHECK(unsupported_text(setup).find("equation of state") != std::string::npos);
}
}  // namespace test_refsolver_runs_cpp
