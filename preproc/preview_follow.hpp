// A preview that follows an edit of the particles (issue 45 item 3): when only where particles stand
// and which particles there are changed (a coordinate of *NODE edited, an *ELEMENT_SPH line added or
// removed), the kept preview is updated locally instead of recomputed: the changed particles get
// their nearest neighbour and neighbour count, the particles near their old and new places have their
// counts moved by one and their nearest neighbour searched again when it was a changed particle,
// and the parts' statistics are taken again from the per-particle values. No grid is built: the
// places near a changed particle are found by one pass over the positions per few changed particles,
// which costs milliseconds on a million particles where the whole preview takes a second.
//
// The update gives what compute_preview gives on the new model (tests/test_preview_follow.cpp
// compares them after random moves, additions and removals), or nothing where it does not apply:
// then the caller recomputes. It does not apply when a part's h0 moves (every support of the part
// would change), when its spacing moves on a deck of several parts or with particles at about one
// place (the tolerance of the coincident pairs moves with it), when a part appears or empties, when a
// changed particle has no node, when more than `max_changed` particles changed, when the preview kept
// only the first of its coincident pairs (more than coincident_pairs_kept: the others' would be unknown),
// on Radioss decks, and on a preview kept without per-particle counts (PreviewOptions::neighbour_counts)
// or with the other per-particle arrays (PreviewOptions::particle_arrays).
#pragma once

#include <cstddef>
#include <optional>

#include "model/model.hpp"
#include "preproc/preview.hpp"

namespace sphdeck::preproc {

struct FollowOptions {
    std::size_t max_changed = 64;  // more changed particles than this: recompute
    // A deliberately wrong update (the old places of moved and removed particles are not taken out of
    // their neighbours' counts): tests prove with it that their comparison catches a wrong update.
    bool forget_old_places = false;
    // Values kept on each side of a part's medians for the next followed edit (preview_follow_window.hpp).
    std::size_t window_width = 1024;
};

// `old` is compute_preview(before) (with neighbour_counts); `before` and `now` have the same
// controls, sections, parts, materials, EOS and symmetry planes (the caller checks it: engine/
// preview_reuse.hpp). The preview of `now`, or nullopt when the local update does not apply.
std::optional<Preview> follow_particle_edit(const Preview& old, const model::Model& before, const model::Model& now,
                                            const FollowOptions& options = {});

}  // namespace sphdeck::preproc
