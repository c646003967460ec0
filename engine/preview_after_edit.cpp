#include "engine/preview_after_edit.hpp"

#include "engine/preview_reuse.hpp"
#include "lint/rules.hpp"
#include "preproc/preview_follow.hpp"

namespace sphdeck::engine {

std::shared_ptr<const preproc::Preview> preview_after_edit(const CheckResult& previous, const model::Model& now,
                                                           bool particle_arrays, const model::BulkTaken& taken) {
    const preproc::Preview* old = previous.preview.get();
    if (!old || now.particles.size() == 0) return lint::compute_rules_preview(now, particle_arrays, true);
    // Columns another model took from `previous` cannot be compared with `now`'s.
    const model::BulkTaken& gone = previous.taken;
    if (gone.nodes != taken.nodes || gone.particles != taken.particles)
        return lint::compute_rules_preview(now, particle_arrays, true);
    if (same_geometry_inputs(previous.model, now, taken)) return previous.preview;
    // Only particles moved, came or went (an edit inside *NODE or *ELEMENT_SPH): followed locally, from
    // the last model's columns (none taken).
    if (!particle_arrays && !taken.any() && same_geometry_settings(previous.model, now))
        if (auto followed = preproc::follow_particle_edit(*old, previous.model, now))
            return std::make_shared<const preproc::Preview>(std::move(*followed));
    // Only settings changed (*CONTROL_SPH, *SECTION_SPH, a material): the places' values are kept.
    if (same_particle_places(previous.model, now, taken)) {
        preproc::PreviewOptions options;
        options.particle_arrays = particle_arrays;
        options.neighbour_counts = true;
        if (auto again = preproc::recompute_settings(now, *old, options))
            return std::make_shared<const preproc::Preview>(std::move(*again));
    }
    return lint::compute_rules_preview(now, particle_arrays, true);
}

}  // namespace sphdeck::engine
