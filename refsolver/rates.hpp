// The right-hand side of one step: every physical term of one pair (continuity.hpp, momentum.hpp,
// viscosity.hpp, energy.hpp; smoothing_length.hpp per particle), in a single pass over the pairs.
// Per pair: x_ij, r, h_ij = (h_i + h_j)/2, g_ij = F(r, h_ij) x_ij (kernel.hpp), corrected under
// FORM 1 (renormalisation.hpp). Only pairs where both particles interact count (active and inside
// the SPH time window); ghosts act on real particles only.
// Symmetric evaluation (sph-algorithms.md §12.1 item 5): each real pair is listed once
// (neighbour_list.hpp) and its terms go to both particles. With g_ji = -g_ij exactly (h_ij and the
// mean FORM 1 correction are symmetric), the term particle j receives is bit for bit the one a
// loop over j's own neighbours would compute; only the order of the sums differs.
#pragma once

#include <array>
#include <vector>

#include "refsolver/kernel.hpp"
#include "refsolver/neighbour_list.hpp"
#include "refsolver/packed_particle.hpp"
#include "refsolver/particles.hpp"
#include "refsolver/smoothing_length.hpp"
#include "refsolver/stress.hpp"
#include "refsolver/viscosity.hpp"

namespace sphdeck::refsolver {

struct RateParameters {
    CubicSpline kernel;
    MonaghanViscosity viscosity;
    bool renormalise =
        false;  // the volume-weighted equations (FORM 1, OpenRadioss decks); s.correction is I unless FORM 1
    SmoothingLengthRule h_rule = SmoothingLengthRule::Divergence;
    std::array<double, 3> body{0, 0, 0};  // body acceleration (body_load.hpp)
    int threads = 1;
    // *MAT_ELASTIC parts present: the pair loop adds the stress terms and the velocity gradient
    // (stress.hpp) and fills dstress; fluid-only decks run the loop without them.
    bool solid = false;
    std::vector<double> shear;  // per part: G, 0 for a fluid
    // The SIMD pair loop (pair_rows.hpp) when the CPU runs one and the deck is fluid-only; false:
    // the scalar loop (the reference the tests compare it with).
    bool simd = true;
    // OpenRadioss decks: the viscosity switch f of each real particle (viscosity.hpp; ghosts take
    // their source's); null: f = 1. Runs the scalar loop.
    const std::vector<double>* viscosity_switch = nullptr;
    bool avx512 = true;  // with simd: false keeps the SIMD loop at AVX2 (to compare the two)
};

// Work arrays of compute_rates, kept between steps so that no step allocates.
struct RateScratch {
    std::vector<PackedParticle> packed;  // real + ghost particles (scalar loop)
    // SIMD loop (pair_rows.hpp), instead: x y z h and the rest of the same particles.
    std::vector<std::array<double, 4>> positions;
    std::vector<std::array<float, 4>> positions_f;  // in single precision, for the support filter
    float margin = 0;                               // PairRows::margin
    std::vector<PairRecord> records;
    // Per thread, per real particle: ax ay az drho de received from pairs listed under another
    // particle (no two threads write the same entry; the sums are added in thread order).
    std::vector<std::array<double, 5>> received;
    // Per block of the pair loop (one a thread): its real particles [block_begin[b], block_begin[b + 1]),
    // the highest particle its pairs reach and its longest row. Blocks are contiguous in cell order,
    // so a block's received sums stay within a narrow band: the merge reads only those, not team x
    // real entries. Derived from the lists: kept until they are rebuilt (`blocks_of`).
    std::vector<std::size_t> block_begin, reach;
    std::vector<std::uint32_t> longest;
    struct BlocksKey {
        const NeighbourList* list = nullptr;
        std::uint64_t builds = 0;
        std::size_t team = 0, real = 0, pairs = 0;
        bool operator==(const BlocksKey&) const = default;
    } blocks_of;
    std::vector<std::vector<std::uint32_t>> inside;  // per thread: one particle's pairs within the support
    // Solid decks only: S / rho^2 (real + ghost), and per real particle the P and Q sums of
    // stress.hpp, own and (per thread) received.
    std::vector<SymmetricTensor> stress_over_rho2;
    std::vector<std::array<double, 18>> gradient, received_gradient;
    // Wall-clock seconds, summed: compute_rates, and of it the adding of the received sums
    // (Simulation::timings: the benchmark's split of a step).
    double rates_seconds = 0, merge_seconds = 0;
};

// Fills ax, ay, az, drho, de, dh (and dstress when parameters.solid) of the real particles. Deterministic for a given
// thread count (static schedule); another thread count changes the order of the sums (last-digit round-off).
void compute_rates(Particles& s, const NeighbourList& list, const RateParameters& parameters, RateScratch& scratch);

}  // namespace sphdeck::refsolver
