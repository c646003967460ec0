// From the Model to what the solver runs (design.md: "setup from the Model"): the particles'
// initial state in model order (positions, h0 and masses as the preview computes them, density
// RO (or RO / V0), internal energy E0 / RO, *INITIAL_VELOCITY), the parts' EOS (or *MAT_ELASTIC
// moduli) and SPH time windows, the controls, symmetry planes and body loads, and the list of everything in the deck
// that the solver does not honour (unsupported.cpp).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "model/model.hpp"
#include "model/radioss_run_input.hpp"
#include "refsolver/body_load.hpp"
#include "refsolver/eos.hpp"
#include "refsolver/simulation.hpp"
#include "refsolver/smoothing_length.hpp"
#include "refsolver/stress.hpp"
#include "refsolver/symmetry_ghosts.hpp"

namespace sphdeck::refsolver {

struct PartSetup {
    long long id = 0;
    EquationOfState eos;    // *MAT_ELASTIC: C1 = K (p = K mu)
    ElasticModuli elastic;  // *MAT_ELASTIC; shear 0 for a fluid
    double wave_speed = 0;  // *MAT_ELASTIC: sqrt((K + 4 G / 3) / rho0), the particles' c
    bool solid() const { return elastic.shear > 0; }
    double start = 0, death = 1e20;  // *SECTION_SPH START, DEATH
};

struct SolverInput {
    int dimension = 3;
    bool renormalise = false;  // FORM 1: the corrected gradient, and the volume-weighted equations
    // The volume-weighted density and momentum (FORM 1's equations, continuity.hpp and momentum.hpp)
    // without the correction: OpenRadioss decks, whose engine runs them at every Order (spdens.F,
    // spforcp.F: d rho_i / dt = rho_i sum_j V_j v_ij . grad W, F_i = sum_j V_i V_j (sigma_i + sigma_j) grad W).
    bool volume_weighted = false;
    SmoothingLengthRule h_rule = SmoothingLengthRule::Divergence;
    double q1 = 1.5, q2 = 0.06, tssfac = 0.9;
    // OpenRadioss decks: the engine's particle step, or with /DT/NODA its nodal step (radioss_time_step.hpp).
    bool radioss_step = false, radioss_nodal_step = false;
    double end_time = 0;
    long long end_cycle = 0;  // *CONTROL_TERMINATION ENDCYC, 0: none
    long long ncbs = 1;
    double sph_start = 0, sph_death = 1e20;    // *CONTROL_SPH START, DT
    double maxv = 1e15;                        // <= 0: no velocity check
    std::optional<std::array<double, 6>> box;  // *CONTROL_SPH BOXID
    std::vector<SymmetryPlane> planes;
    unsigned planes_per_image = 3;  // corner images across up to 3 planes; OpenRadioss decks 1 (spsym.F)
    std::vector<BodyLoad> loads;
    std::vector<PartSetup> parts;
    // Per particle, model order.
    std::vector<double> x, y, z, vx, vy, vz, rho, e, h, m, h_low, h_high;
    std::vector<std::uint32_t> part;
    // OpenRadioss /SPHBCS kinematic conditions, model order (empty when none): the projector P
    // (row-major 3x3) applied to each particle's acceleration and initial velocity; 0 for a
    // TIED node, I - n n^T for a SLIDE one, their product for a node in several groups.
    std::vector<std::array<double, 9>> kinematic;
};

struct SetupResult {
    std::optional<SolverInput> input;  // empty when something fatal was found (and not ignored)
    std::vector<Unsupported> unsupported;
};

SetupResult build_setup(const model::Model& model, const RunOptions& options);

// OpenRadioss decks (setup_radioss.cpp): what the solver does not honour, one part's property,
// material and EOS (`e0`: the EOS's E0 per unit initial volume), and the controls, planes,
// kinematic conditions and /INIVEL.
std::vector<Unsupported> radioss_unsupported(const model::Model& model, const model::RadiossRunInput& run);
bool read_radioss_part(const model::Model& model, long long id, PartSetup& ps, double& e0,
                       std::vector<Unsupported>& out);
void setup_radioss_controls(const model::Model& model, const model::RadiossRunInput& run, const RunOptions& options,
                            SolverInput& in, std::vector<Unsupported>& out);

// The keywords and settings of the deck the solver does not honour (unsupported.cpp).
std::vector<Unsupported> unsupported_features(const model::Model& model);

// Reading fields of a keyword record (setup helpers).
double record_number(const model::KeywordRecord* r, std::string_view name, double fallback = 0.0);
// An integer field (an id, a count) as an integer: `fallback` when absent, invalid or beyond long long.
long long record_integer(const model::KeywordRecord* r, std::string_view name, long long fallback = 0);
const model::FieldRecord* record_field(const model::KeywordRecord* r, std::string_view name);
const model::KeywordRecord* model_record(const model::Model& m, std::optional<std::size_t> index);

// The steps of build_setup after the particles (setup.cpp): the controls, planes and loads
// (setup_controls.cpp), the initial velocities (setup_velocities.cpp).
void setup_controls(const model::Model& m, const RunOptions& options, SolverInput& in, std::vector<Unsupported>& out);
void setup_initial_velocities(const model::Model& m, SolverInput& in, std::vector<Unsupported>& out);

}  // namespace sphdeck::refsolver
