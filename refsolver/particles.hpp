// The solver's internal particle arrays (structure of arrays). Real particles come first, in
// cell order (re-sorted at every neighbour rebuild for cache locality); symmetry-plane ghosts
// follow them (indices >= real) and carry copies of their source's state (symmetry_ghosts.hpp).
// `model_index` maps a real particle back to its place in the deck.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "refsolver/stress.hpp"

namespace sphdeck::refsolver {

struct Particles {
    std::size_t real = 0;  // real particles; the arrays of the pair loop also hold the ghosts
    bool solid = false;    // *MAT_ELASTIC parts present: the stress arrays below are sized, else empty

    // Read by the pair loop: real + ghost entries.
    std::vector<double> x, y, z, vx, vy, vz, rho, p, c, h, m;
    std::vector<std::uint8_t> interacting;          // 1: active and inside its SPH time window
    std::vector<std::array<double, 6>> correction;  // FORM 1: B^-1 as xx yy zz xy xz yz
    std::vector<SymmetricTensor> stress;            // solid: deviatoric stress S (stress.hpp), 0 for fluids
    std::vector<double> omega;                      // FORM 0: the grad-h factor Omega (grad_h.hpp), else 1

    // Real particles only.
    std::vector<double> e;                   // specific internal energy
    std::vector<double> h_low, h_high;       // HMIN h0, HMAX h0
    std::vector<std::uint32_t> part;         // index into the solver's parts
    std::vector<std::uint32_t> model_index;  // position in the deck's particle order
    std::vector<std::uint8_t> active;        // 0 once deactivated (BOXID, MAXV)
    // Rates of the last evaluation, and the half-step state of the leapfrog.
    std::vector<double> ax, ay, az, drho, de, dh;
    std::vector<double> vx_half, vy_half, vz_half, rho_half, e_half, h_half;
    std::vector<SymmetricTensor> dstress, stress_half;  // solid only
    // Positions at the last neighbour rebuild (the Verlet skin test).
    std::vector<double> x_built, y_built, z_built;

    // Ghosts: source real particle and the planes mirrored (bit k: plane k).
    std::vector<std::uint32_t> ghost_source;
    std::vector<std::uint8_t> ghost_planes;

    // Spare arrays for permute(), swapped with the live ones so that a rebuild allocates nothing.
    struct Spares {
        std::vector<std::vector<double>> doubles;
        std::vector<std::uint8_t> interacting, active;
        std::vector<std::array<double, 6>> correction, stress, stress_half;
        std::vector<std::uint32_t> part, model_index, renumber;
    } spares;

    std::size_t ghosts() const { return ghost_source.size(); }
    std::size_t total() const { return real + ghosts(); }

    // Sizes the real-only arrays and the pair-loop arrays for `n` real particles, no ghosts (set
    // `solid` first).
    void resize_real(std::size_t n);
    // Sizes the pair-loop arrays for the current ghosts (after ghost_source is filled).
    void resize_pair_arrays();
    // Reorders the real particles: new position k holds old particle order[k]. Ghosts stay
    // (same entries), their sources renumbered. The rates (ax .. dh) and the positions at the
    // last build are not carried over (a rebuild recomputes both right after), but for drho, which
    // FORM 0's Omega reads from the last evaluation (grad_h.hpp).
    void permute(const std::vector<std::uint32_t>& order, int threads = 1);
};

}  // namespace sphdeck::refsolver
