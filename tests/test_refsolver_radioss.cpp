// OpenRadioss decks in the reference solver (refsolver/setup_radioss.cpp): the engine deck's /RUN end
// time and /DT/NODA scale, /INIVEL on its node group, a TIED /SPHBCS whose group stays at rest, the
// symmetry mass split, /EOS/POLYNOMIAL pressure, the refusal list, and `sphdeck run` end to end.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "diag/diagnostic.hpp"
#include "engine/check.hpp"
#include "refsolver/simulation.hpp"
#include "run_sphdeck.hpp"
#include "verify/cases.hpp"

namespace test_refsolver_radioss_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using namespace sphdeck::test;

namespace {

std::string f20(double v) { return fmt::format("{:>20}", fmt::format("{:.10g}", v)); }

// A 3 x 3 x 3 cube of spacing 1 (rho 2, mp 2) on a TIED plane z = 0 (group 2: the bottom layer),
// the rest moving down at 0.1 (/INIVEL group 1); `extra` goes before /END.
std::string cube_starter(const std::string& extra = "", const std::string& law = "HYDPLA",
                         const std::string& plane = "TIED") {
    std::string s =
        "#RADIOSS STARTER\n/BEGIN\ncube\n      2019         0\n"
        "                  kg                  mm                  ms\n"
        "                  kg                  mm                  ms\n";
    s += "/MAT/" + law + "/1\nm\n" + f20(2.0) + "\n" + f20(law == "HYDPLA" ? 0.0 : 100.0) + f20(0.3) + "\n" + f20(0) +
         f20(0) + f20(0) + f20(0) + f20(0) + "\n" + f20(0) + "\n";
    s += "/EOS/POLYNOMIAL/1\neos\n" + f20(0) + f20(50.0) + f20(0) + f20(0) + "\n" + f20(0) + f20(0) + f20(0) + f20(0) +
         f20(0) + "\n";
    s += "/PART/1\np\n         1         1         0\n";
    s += "/PROP/TYPE34/1\nsph\n" + f20(2.0) + f20(2) + f20(1) + f20(0) + "         0         0\n        -1" + f20(0) +
         f20(0) + "\n";
    s += "/FRAME/FIX/1\nf\n" + f20(0) + f20(0) + f20(0) + "\n" + f20(0) + f20(1) + f20(0) + "\n" + f20(0) + f20(0) +
         f20(1) + "\n";
    s += "/NODE\n";
    std::string moving, bottom, cells;
    int id = 0;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                ++id;
                s += fmt::format("{:10d}{}{}{}\n", id, f20(i), f20(j), f20(k));
                (k == 0 ? bottom : moving) += fmt::format("{:10d}\n", id);
                cells += fmt::format("{:10d}\n", id);
            }
    s += "/GRNOD/NODE/1\nmoving\n" + moving + "/GRNOD/NODE/2\nbottom\n" + bottom + "/SPHCEL/1\n" + cells;
    s += "/INIVEL/TRA/1\nv\n" + f20(0) + f20(0) + f20(-0.1) + "         1         0\n";
    s += "/SPHBCS/" + plane + "/1\nbottom\n         Z         1         2                   1\n";
    return s + extra + "/END\n";
}

const std::string cube_engine = "/RUN/cube/1\n                 0.5\n/DT/NODA/CST/0\n0.67 0\n/END\n";

refsolver::Simulation::Setup solve(const TempDir& dir, const std::string& starter) {
    const std::string path = (dir.path() / "cube_0000.rad").string();
    std::ofstream(path) << starter;
    std::ofstream(dir.path() / "cube_0001.rad") << cube_engine;
    const engine::CheckResult r = engine::check_file(path);
    REQUIRE(r.model.radioss.has_value());
    refsolver::RunOptions options;
    options.deck = &r.deck;
    return refsolver::Simulation::create(r.model, options);
}

bool listed(const refsolver::Simulation::Setup& s, std::string_view text, bool fatal) {
    return std::any_of(s.unsupported.begin(), s.unsupported.end(), [&](const refsolver::Unsupported& u) {
        return u.what.find(text) != std::string::npos && u.fatal == fatal;
    });
}

}  // namespace

TEST_CASE("refsolver radioss: /RUN, /DT/NODA, /INIVEL and a TIED plane whose group stays at rest") {
    TempDir dir;
    auto setup = solve(dir, cube_starter());
    REQUIRE(setup.simulation);
    refsolver::Simulation& sim = *setup.simulation;
    CHECK(sim.end_time() == 0.5);  // /RUN of the engine deck
    CHECK(sim.dimension() == 3);
    // The bottom layer lies on the plane: mp / 2 each (the starter's split), 9 x 1 + 18 x 2 = 45.
    CHECK(sim.totals().mass == doctest::Approx(45.0));
    const refsolver::ParticleState& s0 = sim.state();
    for (std::size_t i = 0; i < s0.size(); ++i) CHECK(s0.vz[i] == (s0.z[i] == 0 ? 0.0 : -0.1));
    // /DT/NODA: the engine's nodal step 0.67 sqrt(2 m / K) (radioss_time_step.hpp), not the particle
    // step 0.67 h / (q + sqrt(q^2 + c^2)), c = sqrt(C1 / rho) = 5, h0 = (sqrt2 mp / rho)^(1/3) = 2^(1/6).
    CHECK(sim.dt() > 0.67 * std::pow(2.0, 1.0 / 6) / (5.0 * (1 + std::sqrt(2.0))));
    CHECK_FALSE(listed(setup, "/DT/NODA", false));  // computed, and its minimum step is 0
    const double e0 = sim.totals().total;
    sim.run();
    CHECK(sim.failure().empty());
    CHECK(sim.time() == doctest::Approx(0.5));
    const refsolver::ParticleState& s = sim.state();
    double pressure = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.z[i] == 0) {  // the TIED group
            CHECK(s.vx[i] == 0);
            CHECK(s.vy[i] == 0);
            CHECK(s.vz[i] == 0);
        }
        pressure = std::max(pressure, s.p[i]);
    }
    CHECK(pressure > 0);               // the cube is compressed against the plane: p = C1 mu > 0
    CHECK(sim.totals().internal > 0);  // kinetic turned into internal energy
    // The engine's central differences (simulation.cpp, radioss_cycle) keep the total only to their
    // time-step error: about 4 % in these 4 steps near the stability limit (the engine's own listing of
    // WavesCompression drifts 2 % in 44 cycles, and `verify radioss-waves` follows it to its digits).
    CHECK(std::abs(sim.totals().total - e0) < 0.1 * e0);
    auto slide = solve(dir, cube_starter("", "HYDPLA", "SLIDE"));
    REQUIRE(slide.simulation);
    const double slide_e0 = slide.simulation->totals().total;
    slide.simulation->run();
    CHECK(slide.simulation->failure().empty());
    CHECK(slide.simulation->totals().internal > 0);
    CHECK(std::abs(slide.simulation->totals().total - slide_e0) < 0.1 * slide_e0);
}

TEST_CASE("refsolver radioss: what the solver does not model is refused, the rest runs") {
    TempDir dir;
    auto gravity = solve(dir, cube_starter("/GRAV/1\ng\n         1         0Z\n" + f20(-9.81) + "\n"));
    CHECK(listed(gravity, "/GRAV/1: gravity is not modelled", true));
    auto plastic = solve(dir, cube_starter("", "PLAS_JOHNS"));
    CHECK(listed(plastic, "Johnson-Cook plasticity) is not supported", true));
    auto no_eos = solve(dir, [] {
        std::string s = cube_starter();
        const auto from = s.find("/EOS/POLYNOMIAL"), to = s.find("/PART/1");
        return s.erase(from, to - from);
    }());
    CHECK_FALSE(no_eos.simulation);
    CHECK(listed(no_eos, "has no /EOS/POLYNOMIAL and no C1", true));
}

TEST_CASE("refsolver radioss: sphdeck run writes history.csv, .vtp and .pvd for an OpenRadioss deck") {
    TempDir dir;
    std::ofstream(dir.path() / "cube_0000.rad") << cube_starter();
    std::ofstream(dir.path() / "cube_0001.rad") << cube_engine;
    const Run r = run_sphdeck(dir, "run cube_0000.rad --out out --every 2 --progress-every 0");
    CHECK_MESSAGE(r.exit_code == 0, r.err);
    CHECK(std::filesystem::exists(dir.path() / "out" / "history.csv"));
    CHECK(std::filesystem::exists(dir.path() / "out" / "particles.pvd"));
    CHECK(std::filesystem::exists(dir.path() / "out" / "particles_000002.vtp"));
    CHECK(r.err.find("run: step 1, t = ") != std::string::npos);  // the progress line
    CHECK(r.out.find("27 particles, 3D, end time 0.5") != std::string::npos);
}

TEST_CASE("refsolver radioss: the radioss-waves decks check clean and keep the starter's mass") {
    for (const char* name : {"radioss_waves_0000.rad", "radioss_waves_quick_0000.rad"}) {
        const engine::CheckResult r =
            engine::check_file(std::string(SPHDECK_SOURCE_DIR) + "/decks/verification/" + name);
        std::size_t errors = 0;
        for (const auto& d : r.diagnostics) errors += d.severity == diag::Severity::Error;
        INFO(name);
        CHECK(errors == 0);
        CHECK(r.model.particles.size() == 1296);
        CHECK(r.model.symmetry_planes.size() == 5);
    }
}

// The quick variant of `sphdeck verify radioss-waves` (docs/verification.md §6): the first 7 listed
// cycles of the engine. The solver follows the engine's time steps and energies to their printed
// digits, far inside the case's gates.
TEST_CASE("refsolver radioss: radioss-waves --quick, energies, time steps and mass against the engine's listing") {
    verify::CaseOptions options;
    options.decks = std::filesystem::path(SPHDECK_SOURCE_DIR) / "decks" / "verification";
    options.quick = true;
    options.threads = 1;
    const verify::CaseResult r = verify::run_radioss_waves(options);
    REQUIRE_MESSAGE(r.ran(), r.failure);
    REQUIRE(r.checks.size() == 5);
    CHECK(r.checks[0].quantity.starts_with("kinetic energy, worst of 7 listed cycles"));
    CHECK(r.checks[0].passed());
    CHECK(r.checks[1].passed());  // internal energy
    CHECK(r.checks[4].passed());  // mass
    CHECK(r.checks[4].value == doctest::Approx(597.9076).epsilon(1e-6));
    CHECK(r.checks[0].error < 0.001);  // kinetic energy, share of E_total(0)
    CHECK(r.checks[1].error < 0.001);  // internal energy
    CHECK(r.checks[2].quantity.starts_with("time step, worst of 6 cycles"));
    CHECK(r.checks[2].error < 0.001);  // dt at cycles 0..5, the first 0.8008
    CHECK(r.checks[3].error == 0);     // 6 cycles to the engine's time of cycle 6
    CHECK(r.passed());
}
}  // namespace test_refsolver_radioss_cpp
