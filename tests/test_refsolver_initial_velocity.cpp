// The velocities the solver starts with (refsolver/setup_velocities.cpp): *INITIAL_VELOCITY_GENERATION
// by part and by part set (translation plus a rotation about an axis, exact values),
// *INITIAL_VELOCITY_NODE over both, and the errors of undefined sets and axes.
#include <doctest/doctest.h>

#include <string>

#include "test_refsolver_decks.hpp"

namespace test_refsolver_initial_velocity_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using namespace sphdeck::test;

namespace {

refsolver::Simulation::Setup solver_for_file(const std::string& name) {
    const engine::CheckResult r = engine::check_file(std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/run/" + name, {});
    return refsolver::Simulation::create(r.model, {});
}

// A 2-particle 2D fluid deck with `extra` keywords.
TestDeck two_particles(std::string extra) {
    TestDeck deck;
    deck.idim = 2;
    deck.sphini = 0.6;
    deck.particles = {{1.0, 2.0, 0, 0.25}, {1.5, 2.0, 0, 0.25}};
    deck.extra = std::move(extra);
    return deck;
}

}  // namespace

TEST_CASE("refsolver initial velocity: *INITIAL_VELOCITY_GENERATION by part and part set, _NODE last") {
    const refsolver::Simulation::Setup setup = solver_for_file("initial_velocity_generation_3d.k");
    REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
    const refsolver::ParticleState& s = setup.simulation->state();
    REQUIRE(s.size() == 8);
    // Part 1: (0.5, 0, 0) + 3 x_hat x (x - (0, 1, 0)) = (0.5, -3 z, 3 (y - 1)), NX 2 normalised.
    for (std::size_t i = 0; i < 4; ++i) {
        INFO("particle " << i);
        CHECK(s.vx[i] == 0.5);
        CHECK(s.vy[i] == -3.0 * s.z[i]);
        CHECK(s.vz[i] == 3.0 * (s.y[i] - 1.0));
    }
    CHECK(s.vz[0] == -3.0);
    CHECK(s.vy[3] == -1.5);
    CHECK(s.vz[3] == -1.5);
    // Part 2 through part set 7: (0, -1.25, 0); node 8 by *INITIAL_VELOCITY_NODE, given first in the deck.
    for (std::size_t i = 4; i < 7; ++i) {
        CHECK(s.vx[i] == 0.0);
        CHECK(s.vy[i] == -1.25);
        CHECK(s.vz[i] == 0.0);
    }
    CHECK(s.vx[7] == 4.0);
    CHECK(s.vy[7] == 5.0);
    CHECK(s.vz[7] == 6.0);
    CHECK(unsupported_text(setup).find("not used by the solver") == std::string::npos);
}

TEST_CASE("refsolver initial velocity: rotation about z in 2D") {
    // OMEGA 2 about z through (1, 2): v = (0.25, 0) + 2 z_hat x (x - (1, 2, 0)).
    const TestDeck deck = two_particles("*INITIAL_VELOCITY_GENERATION\n1,2,2,0.25\n1,2,0,0,0,1\n");
    const refsolver::Simulation::Setup setup = solver_for(deck);
    REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
    const refsolver::ParticleState& s = setup.simulation->state();
    CHECK(s.vx[0] == 0.25);
    CHECK(s.vy[0] == 0.0);
    CHECK(s.vx[1] == 0.25);
    CHECK(s.vy[1] == 1.0);
    CHECK(s.vz[1] == 0.0);
}

TEST_CASE("refsolver initial velocity: rotation about an axis through two nodes (NX -999)") {
    // OMEGA 2 about the axis from node 1 (1, 2) to node 3 (1, 2, 1): v = 2 z_hat x (x - (1, 2, 0)).
    TestDeck deck = two_particles("*SET_NODE_LIST\n5\n1,2\n*INITIAL_VELOCITY_GENERATION\n5,3,2\n0,0,0,-999,1,3\n");
    deck.particles.push_back({1.0, 2.0, 1.0, 0.25});  // node 3: the axis' second node (also a particle)
    deck.idim = 3;
    const refsolver::Simulation::Setup setup = solver_for(deck);
    REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
    const refsolver::ParticleState& s = setup.simulation->state();
    CHECK(s.vx[0] == 0.0);
    CHECK(s.vy[0] == 0.0);
    CHECK(s.vx[1] == 0.0);
    CHECK(s.vy[1] == 1.0);  // 2 * 0.5
    CHECK(s.vz[1] == 0.0);
    CHECK(s.vy[2] == 0.0);  // node 3 is not in set 5
}

TEST_CASE("refsolver initial velocity: *INITIAL_VELOCITY_NODE lines, rotation noted, non-particles noted") {
    const TestDeck deck = two_particles("*INITIAL_VELOCITY_NODE\n2,-1,0.5,7,0,0,9\n99,1,1,1\n");
    const refsolver::Simulation::Setup setup = solver_for(deck);
    REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
    const refsolver::ParticleState& s = setup.simulation->state();
    CHECK(s.vx[0] == 0.0);
    CHECK(s.vx[1] == -1.0);
    CHECK(s.vy[1] == 0.5);
    CHECK(s.vz[1] == 0.0);  // 2D: the x-y plane
    const std::string text = unsupported_text(setup);
    CHECK(text.find("VZR 9: particles have no rotational degrees of freedom") != std::string::npos);
    CHECK(text.find("1 node(s) are not SPH particles") != std::string::npos);
}

TEST_CASE("refsolver initial velocity: undefined sets, parts and axes stop the run") {
    for (const char* extra : {"*INITIAL_VELOCITY\n42\n1,0,0\n", "*INITIAL_VELOCITY_GENERATION\n9,2,0,1\n0,0,0,0,0,1\n",
                              "*INITIAL_VELOCITY_GENERATION\n9,1,0,1\n0,0,0,0,0,1\n",
                              "*INITIAL_VELOCITY_GENERATION\n1,2,5,0\n0,0,0,0,0,0\n"}) {
        INFO(extra);
        refsolver::RunOptions options;
        options.ignore_unsupported = true;
        const refsolver::Simulation::Setup setup = solver_for(two_particles(extra), options);
        CHECK_FALSE(setup.simulation);
    }
}

TEST_CASE("refsolver initial velocity: axis nodes written beyond any integer (NX -999, NY 1e20; issue 32)") {
    // NY and NZ are real fields that hold node ids here: 1e20 names no node and is never converted to
    // an integer (undefined behaviour; the sanitizer build of this test catches it). The run stops.
    TestDeck deck = two_particles("*SET_NODE_LIST\n5\n1,2\n*INITIAL_VELOCITY_GENERATION\n5,3,2\n0,0,0,-999,1e20,3\n");
    refsolver::RunOptions options;
    options.ignore_unsupported = true;
    const refsolver::Simulation::Setup setup = solver_for(deck, options);
    CHECK_FALSE(setup.simulation);
    CHECK(unsupported_text(setup).find("the axis nodes 1e+20 and 3 (NX -999) are not both defined") !=
          std::string::npos);
}

TEST_CASE("refsolver initial velocity: one *SET_NODE_LIST + *INITIAL_VELOCITY per particle") {
    // The set-up cost case of issue 18 (bench/make_velocity_sets_deck.py at full size): each
    // particle gets its own set's velocity, also the ones whose sets come in another order.
    TestDeck deck;
    deck.idim = 2;
    deck.sphini = 0.15;
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 20; ++i)
            deck.particles.push_back({0.1 * i, 0.1 * j, 0, 0.01, 0.001 * (i + 1), -0.002 * (j + 1), 0});
    const refsolver::Simulation::Setup setup = solver_for(deck);
    REQUIRE_MESSAGE(setup.simulation, unsupported_text(setup));
    const refsolver::ParticleState& s = setup.simulation->state();
    for (std::size_t k = 0; k < s.size(); ++k) {
        CHECK(s.vx[k] == deck.particles[k].vx);
        CHECK(s.vy[k] == deck.particles[k].vy);
    }
}
}  // namespace test_refsolver_initial_velocity_cpp
