// The SIMD pair loop (refsolver/pair_rows.hpp) against the scalar loop (rates.cpp) on the same
// decks: a jostled block of water-like fluid walled by symmetry planes (ghost rows), viscous, under
// gravity, FORM 0 and FORM 1, 2D and 3D. Each pair's terms are the scalar ones up to fused
// multiply-adds and the sums run in another order, so after a few steps every field agrees to a
// few hundred ulps; a wrong term (a factor, a lane, a padding lane counted) is far outside that.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "refsolver/pair_rows.hpp"
#include "test_refsolver_decks.hpp"

namespace test_refsolver_simd_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using namespace sphdeck::test;

namespace {

// A block of side^d particles at spacing 0.1 with a velocity field that varies from particle to
// particle (compression and shear, so the viscosity acts on some pairs and not on others).
TestDeck jostled_block(int dimension, int form) {
    TestDeck deck;
    deck.idim = dimension, deck.form = form;
    deck.q1 = 1.0, deck.q2 = 0.5;
    deck.rho0 = 1000;
    deck.eos = "*EOS_MURNAGHAN\n1,7,2e5,1\n";
    const int side = dimension == 2 ? 13 : 7, nz = dimension == 2 ? 1 : side;
    const double dx = 0.1, mass = dimension == 2 ? 1000 * dx * dx : 1000 * dx * dx * dx;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i) {
                const double x = (i + 0.5) * dx, y = (j + 0.5) * dx, z = dimension == 2 ? 0.0 : (k + 0.5) * dx;
                const double wobble = std::sin(12.9898 * i + 78.233 * j + 37.719 * k);
                deck.particles.push_back({x, y, z, mass * (1 + 0.05 * wobble), -3 * x + wobble, 2 * y - 0.5 * wobble,
                                          dimension == 2 ? 0.0 : 0.7 * wobble - z});
            }
    deck.extra = "*LOAD_BODY_Y\n1,9.81\n*DEFINE_CURVE\n1\n0,1\n100,1\n";
    deck.extra += "*BOUNDARY_SPH_SYMMETRY_PLANE\n0,0,0,1,0,0\n*BOUNDARY_SPH_SYMMETRY_PLANE\n0,0,0,0,1,0\n";
    if (dimension == 3) deck.extra += "*BOUNDARY_SPH_SYMMETRY_PLANE\n0,0,0,0,0,1\n";
    deck.endtim = 1.0;
    return deck;
}

// The largest difference of a field between two runs, relative to the field's largest magnitude.
double relative_gap(const std::vector<double>& a, const std::vector<double>& b) {
    double gap = 0, scale = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        gap = std::max(gap, std::abs(a[i] - b[i])), scale = std::max(scale, std::abs(a[i]));
    return scale > 0 ? gap / scale : gap;
}

}  // namespace

TEST_CASE("refsolver: the SIMD pair loop equals the scalar loop to round-off") {
    // Every SIMD path this CPU runs: the widest, and AVX2 too where the widest is AVX-512.
    for (bool avx512 : {true, false}) {
        const refsolver::PairRowsPath path = refsolver::best_pair_rows(avx512);
        if (!avx512 && path.run == refsolver::best_pair_rows(true).run) continue;
        const std::string path_name = path.name;
        CAPTURE(path_name);
        double largest = 0;  // the largest relative gap of any field
        for (int dimension : {2, 3})
            for (int form : {0, 1}) {
                CAPTURE(dimension);
                CAPTURE(form);
                const TestDeck deck = jostled_block(dimension, form);
                refsolver::RunOptions scalar_options, fast_options;
                scalar_options.simd = false;
                fast_options.avx512 = avx512;
                auto fast = solver_for(deck, fast_options), scalar = solver_for(deck, scalar_options);
                REQUIRE_MESSAGE(fast.simulation, unsupported_text(fast));
                REQUIRE(scalar.simulation);
                for (int s = 0; s < 8; ++s) fast.simulation->step(), scalar.simulation->step();
                const refsolver::ParticleState &a = fast.simulation->state(), &b = scalar.simulation->state();
                REQUIRE(a.size() == b.size());
                // The run did something: particles moved and the density changed by far more than the tolerance.
                CHECK(relative_gap(a.rho, std::vector<double>(a.size(), 1000.0)) > 1e-6);
                for (const auto& [member, label] : {std::pair{&refsolver::ParticleState::x, "x"},
                                                    {&refsolver::ParticleState::y, "y"},
                                                    {&refsolver::ParticleState::vx, "vx"},
                                                    {&refsolver::ParticleState::vy, "vy"},
                                                    {&refsolver::ParticleState::vz, "vz"},
                                                    {&refsolver::ParticleState::rho, "rho"},
                                                    {&refsolver::ParticleState::e, "e"},
                                                    {&refsolver::ParticleState::h, "h"}}) {
                    const std::string name = label;  // a copy: clang 14 lambdas (CAPTURE) cannot capture bindings
                    const auto field = member;
                    CAPTURE(name);
                    const double gap = relative_gap(a.*field, b.*field);
                    largest = std::max(largest, gap);
                    CHECK(gap < 1e-11);
                }
            }
        MESSAGE("pair loop " << path_name << ": largest relative gap to the scalar loop " << largest);
    }
}
}  // namespace test_refsolver_simd_cpp
