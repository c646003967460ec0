// The lint rule families (design.md: one file per family), each a function of the context.
#pragma once

#include <functional>

#include "lint/rule_context.hpp"
#include "lint/rule_inputs.hpp"

namespace sphdeck::lint {

// An include that could not be read (DK010): definitions may be in it (rules_references.cpp).
bool include_missing(const RuleContext& c);
void check_references(RuleContext& c);     // rules_references.cpp: REF001-REF009
void check_control_sph(RuleContext& c);    // rules_control_sph*.cpp: SPH010-SPH080, SPH091-SPH094
void check_section_sph(RuleContext& c);    // rules_section_sph.cpp: SPH081, SPH100-SPH104
void check_sph_particles(RuleContext& c);  // rules_particles.cpp: SPH110-SPH112
void check_sph_materials(RuleContext& c);  // rules_materials.cpp: SPH116-SPH117
void check_isph(RuleContext& c);           // rules_isph.cpp: SPH014
void check_densities(RuleContext& c);      // rules_density.cpp: SPH119
void check_sph_dimension(RuleContext& c);  // rules_dimension.cpp: SPH120-SPH121
// The geometry rules' preview (null without particles), computed before the other rules run;
// check_preview reads it from RuleContext::preview. `neighbour_counts`: keep the per-particle counts
// too, for a kept preview that follows the next edit (preproc/preview_follow.hpp).
std::shared_ptr<const preproc::Preview> compute_rules_preview(const model::Model& model, bool particle_arrays = false,
                                                              bool neighbour_counts = false);
void check_preview(RuleContext& c);  // rules_preview.cpp: SPH090, SPH113-SPH115, SPH118
// run_rules with the geometry preview taken from `preview_source` instead of compute_rules_preview:
// the editor's re-check hands back the last check's preview when the geometry inputs are unchanged.
using PreviewSource = std::function<std::shared_ptr<const preproc::Preview>(const model::Model&)>;
void run_rules(RuleContext& context, const PreviewSource& preview_source);
// run_rules with a say before each family it reaches (in order, after the preview): `run` returns
// false to leave the family out (the caller put its last findings in its place, engine/rule_reuse.hpp);
// `ran` follows each family that ran. Either may be empty.
struct FamilySteps {
    std::function<bool(RuleFamily)> run;
    std::function<void(RuleFamily)> ran;
};
void run_rules(RuleContext& context, const PreviewSource& preview_source, const FamilySteps& steps);
// The one family, as run_rules runs it.
void run_family(RuleContext& context, RuleFamily family);
void check_radioss(RuleContext& c);  // rules_radioss*.cpp: RAD002-RAD029 (Radioss decks only)

}  // namespace sphdeck::lint
