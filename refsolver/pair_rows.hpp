// The SIMD fast path of the fluid pair loop (rates.cpp): the same pair terms, computed for several
// partners of a particle at once (one vector lane per partner). Compiled once per instruction set
// in its own unit (pair_rows_avx2.cpp: -mavx2 -mfma, 4 lanes; pair_rows_avx512.cpp: -mavx512f,
// 8 lanes; both include pair_rows_kernel.hpp) and chosen at run time by what the CPU reports
// (pair_rows_dispatch.cpp), so the x86-64 baseline build never runs an instruction its CPU lacks.
// Per-ISA units rather than target_clones: clang 14 does not take target_clones on templates.
// The units see only this plain view of raw pointers: no inline function of a shared header
// (std containers) is instantiated with AVX code, where the linker could pick it for everyone.
// Results: each pair's terms as the scalar loop computes them up to fused multiply-adds, summed in
// another order (lanes, then lane sums): equal to the scalar loop to round-off
// (tests/test_refsolver_simd.cpp). Solid decks (*MAT_ELASTIC) keep the scalar loop.
#pragma once

#include <cstddef>
#include <cstdint>

#include "refsolver/packed_particle.hpp"

namespace sphdeck::refsolver {

struct PairRows {
    const PairRecord* records = nullptr;  // real then ghost particles
    const double* positions = nullptr;    // x y z h of the same particles, 4 per particle
    // The same in single precision, for the support filter, and the margin its test adds to 2 h_ij
    // for the rounding (a few pairs just outside the support pass it; the pair terms drop them).
    const float* positions_f = nullptr;
    float margin = 0;
    const double* correction = nullptr;  // FORM 1: 6 per particle (xx yy zz xy xz yz), real then ghost
    const std::uint8_t* interacting = nullptr;
    const std::uint32_t *forward_offsets = nullptr, *forward = nullptr;  // neighbour_list.hpp
    const std::uint32_t *ghost_offsets = nullptr, *ghost = nullptr;
    double norm = 0, q1 = 0, q2 = 0;  // kernel C_d, viscosity Q1 Q2
    double body[3] = {0, 0, 0};
    int dimension = 3;
    bool renormalise = false;
    double *ax = nullptr, *ay = nullptr, *az = nullptr, *drho = nullptr, *de = nullptr;  // own sums, set
    double* received = nullptr;  // this thread's: ax ay az drho de per real particle, added to
    // Scratch of this thread: `inside` holds `stride` entries, the most listed partners of a
    // particle (forward and ghosts) plus 16.
    std::uint32_t* inside = nullptr;
    std::size_t stride = 0;
};

// Fills ax .. de of the interacting real particles in [first, last) with the body load plus their
// rows' sums, and adds the shares of their forward partners to `received`; as rates.cpp's loop.
using PairRowsFunction = void (*)(const PairRows&, std::size_t first, std::size_t last);

struct PairRowsPath {
    PairRowsFunction run = nullptr;  // nullptr: the scalar loop
    const char* name = "scalar";
};

// The widest path compiled in and supported by this CPU (and its OS), chosen once; without
// `avx512`, AVX2 at most (to compare the two on one machine).
PairRowsPath best_pair_rows(bool avx512 = true);

// Per-ISA entry points: nullptr when the unit was built without its instruction set (not x86-64).
// Call only after checking the CPU (best_pair_rows does).
PairRowsFunction pair_rows_avx2();
PairRowsFunction pair_rows_avx512();

}  // namespace sphdeck::refsolver
