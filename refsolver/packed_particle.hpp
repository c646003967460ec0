// What the pair loop reads of a particle, packed together: one or two cache lines per neighbour
// instead of one per array. Non-interacting particles get m = 0 and contribute nothing. Its own
// header (no containers) because the per-ISA units of the SIMD pair loop (pair_rows.hpp) read it.
#pragma once

namespace sphdeck::refsolver {

struct PackedParticle {
    double x, y, z, vx, vy, vz, h, m, rho, c, p_over_rho, volume;  // volume = m / rho
};

}  // namespace sphdeck::refsolver
