// The editor's re-check keeps the geometry preview of the last check (neighbour grid, nearest
// neighbours, counts: the costliest rules on a big deck) when the data it is computed from did not
// change: an edit of a title, a comment or a control the preview does not read.
#pragma once

#include "model/bulk_reuse.hpp"
#include "model/model.hpp"

namespace sphdeck::engine {

// Whether preproc::compute_preview reads the same values from `now` as from `before`: the controls,
// the parts' section, material and EOS ids, the sections, materials, EOS and the keyword records
// they point at, the nodes and the particles (their lines aside). Positions (spans) are not compared:
// the preview holds model indices, never a place in the deck. Radioss decks: false (their preview
// reads properties, groups and cells as well). Keep this beside what compute_preview reads.
// `taken`: columns `now` took from `before` (model/bulk_reuse.hpp), the same when `now` holds them alone.
bool same_geometry_inputs(const model::Model& before, const model::Model& now, const model::BulkTaken& taken = {});

// The same but for the nodes and particles: whether only where particles stand and which particles
// there are changed, the edit a kept preview can follow (preproc/preview_follow.hpp).
bool same_geometry_settings(const model::Model& before, const model::Model& now);

// same_geometry_settings with the controls compared only where compute_preview reads them (*CONTROL_SPH
// and TSSFAC): the load cases of one run, which differ in their end time, share one preview
// (engine/shared_preview.hpp).
bool same_preview_settings(const model::Model& before, const model::Model& now);

// Whether the particles, their parts and the places of their nodes are the same (masses aside): what
// the nearest distances and the coincident pairs depend on (preproc::recompute_settings).
bool same_particle_places(const model::Model& before, const model::Model& now, const model::BulkTaken& taken = {});

}  // namespace sphdeck::engine
