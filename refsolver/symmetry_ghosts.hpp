// *BOUNDARY_SPH_SYMMETRY_PLANE through mirrored ghost particles (sph-algorithms.md §8,
// seed page radioss_sph_symmetry_timestep.txt, "Maximum Created Number of Ghost Particles").
// - A plane is its tail point O and unit normal n (tail to head, into the body,
//   lsdyna-sph-cards.md §6); dd = (x - O).n is a particle's signed distance.
// - At each neighbour rebuild, a real particle gets a ghost for a plane when dd <= the search
//   radius (support + skin): the seed's criterion with the security distance. As long as real
//   particles stay on the inner side, every ghost within the radius of a real particle exists
//   (its image is dd_i + dd_j away from a real j). A particle near several planes also gets the
//   images across each pair (and triple) of them (corner images, beyond Radioss, which builds
//   single images only: §8.1), so a box corner is fully symmetric for axis-aligned planes.
// - Ghost state (Slide, §8.2): position x - 2 dd n, velocity v - 2 (v.n) n, same mass, density,
//   pressure, sound speed, h; FORM 1 correction R B R with R = I - 2 n n, and the deviatoric stress
//   of *MAT_ELASTIC parts R S R (Slide flips the n-t shear stresses, §8.6). Ghosts only act on
//   real particles.
// - A real particle found behind a plane (dd < 0) is put back and its normal velocity reversed,
//   as OpenRadioss Ilev = 1 does (§8.6): SPH repulsion is finite, so crossing is possible.
#pragma once

#include <array>
#include <vector>

#include "refsolver/particles.hpp"

namespace sphdeck::refsolver {

struct SymmetryPlane {
    std::array<double, 3> normal{0, 0, 1};  // unit, into the body
    double offset = 0;                      // O . n
    // OpenRadioss /SPHBCS/TIED: the ghost's velocity is the source's reversed (no slip) instead of
    // mirrored (Slide); position, density and stress are mirrored alike.
    bool tied = false;
};

// Rebuilds the ghost list: sources, planes mirrored, and the pair-array sizes. `radius`: the
// neighbour search radius.
// `max_planes_per_image` 1: single images only, as the OpenRadioss engine builds them (spsym.F:
// one image per /SPHBCS and particle).
void build_ghosts(Particles& s, const std::vector<SymmetryPlane>& planes, double radius, int threads = 1,
                  unsigned max_planes_per_image = 3);
// Copies the sources' current state into their ghosts (every step, before the pair loops).
void update_ghosts(Particles& s, const std::vector<SymmetryPlane>& planes, int threads = 1);
// Puts real particles found behind a plane back into the body, reversing the normal velocity
// (both the current and the half-step one). Returns how many were put back.
std::size_t reflect_crossed(Particles& s, const std::vector<SymmetryPlane>& planes, int threads = 1);

}  // namespace sphdeck::refsolver
