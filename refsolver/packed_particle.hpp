// What the pair loop reads of a particle, packed together: one or two cache lines per neighbour
// instead of one per array. Non-interacting particles get m = 0 and contribute nothing. Its own
// header (no containers) because the per-ISA units of the SIMD pair loop (pair_rows.hpp) read it.
#pragma once

namespace sphdeck::refsolver {

struct PackedParticle {
    // s6, s7: what the density, momentum and energy terms of the deck's formulation read (continuity.hpp):
    // FORM 0 p V^2 and 1 / m (0 when not interacting), FORM 1 p / rho and V = m / rho. volume = m / rho
    // (the solid stress's velocity gradient). f: the viscosity switch, 1 but for OpenRadioss decks
    // (viscosity.hpp).
    double x, y, z, vx, vy, vz, h, m, rho, c, s6, s7, volume, f;
};

// The SIMD pair loop's record of a particle (pair_rows.hpp): the same fields but x y z h, which it
// reads from a compact array of its own (the support filter reads them first), so that a partner
// costs one 64-byte cache line here instead of the two a 112-byte PackedParticle spans.
struct alignas(64) PairRecord {
    double vx, vy, vz, m, rho, c, s6, s7;
};

}  // namespace sphdeck::refsolver
