// The reference SPH solver's front door (design.md, refsolver/): a compact explicit SPH code that
// runs an LS-DYNA SPH deck as it is, from the same Model the linter and the preview read.
// `sphdeck run` and `sphdeck verify` both drive it through this interface:
//
//   auto setup = refsolver::Simulation::create(model, options);
//   if (!setup.simulation) { print setup.unsupported; exit 2; }
//   while (!sim.finished()) sim.step();            // or sim.run(observer)
//   sim.state().rho[i], sim.totals().kinetic, ...
//
// Units are the deck's own (consistent units, as in LS-DYNA). Arrays are in model order (the
// order of *ELEMENT_SPH), whatever order the solver keeps internally.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "grammar/raw_deck.hpp"
#include "text/source_map.hpp"
#include "model/model.hpp"

namespace sphdeck::refsolver {

// Something in the deck that changes the physics and that the solver cannot honour (an
// unsupported FORM, a material law it does not know, IDIM -2...), with where the deck says it.
// `fatal` ones stop the run unless RunOptions::ignore_unsupported; the others are only listed.
struct Unsupported {
    std::string what;  // a short lower-case sentence naming the value and what is supported
    grammar::Span span;
    bool fatal = true;
    // Added: the run is impossible even with RunOptions::ignore_unsupported (no EOS, no h0...).
    bool blocking = false;
};

struct RunOptions {
    std::optional<double> end_time;   // overrides *CONTROL_TERMINATION ENDTIM
    int threads = 0;                  // OpenMP threads; 0: the OpenMP default
    bool ignore_unsupported = false;  // run anyway, ignoring what cannot be honoured
    bool simd = true;                 // the SIMD pair loop where the CPU has one (false: scalar, for comparison)
    bool avx512 = true;               // with simd: false keeps it at AVX2 where AVX-512 runs (for comparison)
    bool rebuild_every_step =
        false;  // rebuild the neighbour lists at every step: the reference the skin test is checked against
    // The deck's text, which OpenRadioss decks need besides the Model: the engine deck's /RUN end
    // time and the /INIVEL cards (model/radioss_run_input.hpp). Ignored for LS-DYNA decks.
    const grammar::RawDeck* deck = nullptr;
};

// Particle state in model order (structure of arrays).
struct ParticleState {
    std::vector<double> x, y, z;       // position
    std::vector<double> vx, vy, vz;    // velocity
    std::vector<double> rho;           // density
    std::vector<double> e;             // specific internal energy (per unit mass)
    std::vector<double> p;             // pressure from the EOS
    std::vector<double> h;             // smoothing length
    std::vector<double> mass;          // constant during the run
    std::vector<std::uint32_t> part;   // index into Simulation::part_ids()
    std::vector<std::uint8_t> active;  // 0 once deactivated (BOXID, MAXV, DEATH)
    // Added: deviatoric stress S (xx yy zz xy xz yz) when the deck has *MAT_ELASTIC parts (0 for
    // its fluid particles); empty for fluid-only decks.
    std::vector<std::array<double, 6>> stress;
    std::size_t size() const { return x.size(); }
};

// Global sums over the active particles.
struct Totals {
    double time = 0, dt = 0;
    double mass = 0, kinetic = 0, internal = 0, total = 0;
    std::array<double, 3> momentum{};
    std::size_t active = 0;
    std::size_t steps = 0;
    // Added: work done on the active particles by the body loads since the start, so that
    // total - external_work is what stays constant (up to the time integration error).
    double external_work = 0;
};

// Where the wall-clock time of the steps went (seconds, summed since the start).
struct Timings {
    double total = 0;
    double neighbours = 0;  // rebuilding the neighbour grid and lists
    double skin_check = 0;  // deciding whether to rebuild them (the displacement bounds)
    double grad_h = 0;      // FORM 0's grad-h factors (grad_h.hpp)
    double rates = 0;       // the pair loop: packing, the pairs, adding the received sums
    double merge = 0;       // of `rates`: adding the sums each thread received
};

class Simulation {
public:
    struct Setup {
        std::unique_ptr<Simulation> simulation;  // null when a fatal item stops the run
        std::vector<Unsupported> unsupported;    // everything not honoured, fatal or not
    };
    // Builds the initial state: h0 as the preview computes it (INI modes, SPHINI), density RO,
    // internal energy from the EOS's E0, velocities from *INITIAL_VELOCITY...
    static Setup create(const model::Model& model, const RunOptions& options = {});

    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    void step();            // one explicit time step
    bool finished() const;  // time() >= end time
    // Steps until finished(); calls `observer` after every step (it may be empty).
    void run(const std::function<void(const Simulation&)>& observer = {});

    double time() const;
    double end_time() const;
    double dt() const;  // the step just taken (the next one before the first step)
    std::size_t steps() const;
    int dimension() const;               // 2 or 3
    const ParticleState& state() const;  // model order
    Totals totals() const;
    Timings timings() const;
    const std::vector<long long>& part_ids() const;
    // Added: why the run stopped early (a non-finite state or a collapsed time step); empty
    // while all is well. finished() is true once this is set.
    const std::string& failure() const;
    std::size_t neighbour_rebuilds() const;  // Added: how many times the lists were rebuilt
    int threads() const;  // OpenMP threads of the last step (chosen by refsolver/core_share.hpp when not given)

private:
    struct Impl;
    explicit Simulation(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace sphdeck::refsolver
