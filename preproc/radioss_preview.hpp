// The Radioss pieces of the preview (docs/radioss.md), called by compute_preview when
// Model::radioss is set. Pure functions of the Model and the preview computed so far.
#pragma once

#include <cstdint>
#include <span>

#include "preproc/preview.hpp"

namespace sphdeck::preproc {

// The deck-wide values: alpha_sort, the time-step scales of the engine deck, the /SPHBCS planes.
RadiossPreview radioss_preview_setup(const model::Model& model);

// One part, after its nearest-neighbour distances are known (pp.nn_distance of its located
// particles): h per particle (spinih.F), the symmetry mass split (inspcnd.F, spinit3.F), the
// sound speed and the particle and nodal time steps. Sets h0 (the median h), h_min/h_max, support,
// mass_total (after the split), sound speed, dt_estimate and dt_radioss of the part, pp.h, pp.mass
// and pp.planes of its particles, and counts particles on each plane into out.radioss.
// `members`: the part's particles (model indices, located or not).
void radioss_preview_part(const model::Model& model, std::span<const std::uint32_t> members, std::size_t part,
                          Preview& out);

// Ghosts each plane would create, per plane and per part, once every particle has its h.
void radioss_count_ghosts(Preview& out);

}  // namespace sphdeck::preproc
