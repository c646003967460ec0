// Deactivation by *CONTROL_SPH (lsdyna-sph-cards.md §1, seed control_sph_manual_b.txt):
// - MAXV: a particle faster than MAXV is deactivated. The sources disagree on MAXV <= 0 (the seed
//   page: negative switches the check off; newer text: 0 = no check); here MAXV <= 0 means no check.
// - BOXID: a particle outside the *DEFINE_BOX is deactivated (bounds inclusive).
// A deactivated particle stops: no interactions, no motion, out of the totals. It stays in the
// output arrays with active = 0.
#pragma once

#include <array>
#include <optional>

#include "refsolver/particles.hpp"

namespace sphdeck::refsolver {

struct Deactivation {
    double maxv = 1e15;
    std::optional<std::array<double, 6>> box;  // xmin xmax ymin ymax zmin zmax
    int dimension = 3;                         // 2: the box's z bounds are not tested

    // Deactivates the particles that break a rule; returns how many were deactivated now.
    std::size_t apply(Particles& s) const;
};

}  // namespace sphdeck::refsolver
