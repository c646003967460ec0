#include "lint/rules.hpp"

namespace sphdeck::lint {

void run_rules(RuleContext& context) {
    const bool arrays = context.options.preview_arrays;
    // A kept preview keeps its counts, so that the editor's next re-check can follow an edit with it.
    const bool counts = context.options.keep_preview;
    run_rules(context,
              [arrays, counts](const model::Model& model) { return compute_rules_preview(model, arrays, counts); });
}

void run_rules(RuleContext& context, const PreviewSource& preview_source) {
    // The preview first: its grids then never sit beside the id indexes that the rules below
    // build and keep (the peak of memory). Its findings keep their place in the order.
    if (context.options.geometry) context.preview = preview_source(context.model);
    check_references(context);
    check_control_sph(context);
    check_section_sph(context);
    if (!context.model.radioss) check_sph_particles(context);  // *ELEMENT_SPH masses; Radioss cells: RAD026
    check_sph_materials(context);
    check_isph(context);
    check_densities(context);
    check_sph_dimension(context);
    if (context.options.geometry) check_preview(context);
    if (!context.options.keep_preview) context.preview.reset();
    check_radioss(context);
}

}  // namespace sphdeck::lint
