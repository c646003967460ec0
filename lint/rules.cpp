#include "lint/rules.hpp"

namespace sphdeck::lint {

void run_rules(RuleContext& context) {
    const bool arrays = context.options.preview_arrays;
    // A kept preview keeps its counts, so that the editor's next re-check can follow an edit with it.
    const bool counts = context.options.keep_preview;
    run_rules(context,
              [arrays, counts](const model::Model& model) { return compute_rules_preview(model, arrays, counts); });
}

void run_rules(RuleContext& context, const PreviewSource& preview_source) { run_rules(context, preview_source, {}); }

void run_family(RuleContext& context, RuleFamily family) {
    switch (family) {
        case RuleFamily::References: return check_references(context);
        case RuleFamily::ControlSph: return check_control_sph(context);
        case RuleFamily::SectionSph: return check_section_sph(context);
        case RuleFamily::SphParticles: return check_sph_particles(context);
        case RuleFamily::SphMaterials: return check_sph_materials(context);
        case RuleFamily::Isph: return check_isph(context);
        case RuleFamily::Densities: return check_densities(context);
        case RuleFamily::SphDimension: return check_sph_dimension(context);
        case RuleFamily::Preview: return check_preview(context);
        case RuleFamily::Radioss: return check_radioss(context);
    }
}

void run_rules(RuleContext& context, const PreviewSource& preview_source, const FamilySteps& steps) {
    // The preview first: its grids then never sit beside the id indexes that the rules below
    // build and keep (the peak of memory). Its findings keep their place in the order.
    if (context.options.geometry) context.preview = preview_source(context.model);
    for (const RuleFamily family : all_rule_families) {
        // *ELEMENT_SPH masses; Radioss cells: RAD026.
        if (family == RuleFamily::SphParticles && context.model.radioss) continue;
        if (family == RuleFamily::Preview && !context.options.geometry) continue;
        if (family == RuleFamily::Radioss && !context.options.keep_preview) context.preview.reset();
        if (steps.run && !steps.run(family)) continue;
        run_family(context, family);
        if (steps.ran) steps.ran(family);
    }
}

}  // namespace sphdeck::lint
