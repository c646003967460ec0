// Shared pieces of the *CONTROL_SPH rule family (rules_control_sph*.cpp): which parts are SPH
// parts, where erosion and failure criteria come from, and what is known about the run type.
// Internal to the family; lint/rules.hpp declares only its entry point, check_control_sph.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lint/rule_context.hpp"

namespace sphdeck::lint::control_sph {

// Parts that particles use, and every part whose section is a *SECTION_SPH*, in deck order.
std::vector<const model::Part*> sph_parts(const RuleContext& c);

// A failure or erosion criterion: where it is written and a short description ("FS 0.3 on
// *MAT_PLASTIC_KINEMATIC 2").
struct Criterion {
    grammar::Span span;
    std::string what;
};

// The first failure or erosion criterion of a material: a *MAT_ADD_EROSION for its MID, FS < 1e20
// of *MAT_PLASTIC_KINEMATIC, D1-D5 of *MAT_JOHNSON_COOK, TEROD/CEROD of *MAT_NULL.
std::optional<Criterion> material_failure(const model::Model& m, const model::Material& material);

// The first criterion among the materials of `parts`, or, when `parts` is null, anywhere in the
// deck (any material, any *MAT_ADD_EROSION); then ERODE of *CONTROL_TIMESTEP.
std::optional<Criterion> erosion_criterion(const RuleContext& c, const std::vector<const model::Part*>* parts);

// MPP evidence: `--solver mpp` or the configuration; else a *CONTROL_MPP_* keyword or memory2=.
struct RunKind {
    Solver solver = Solver::Unknown;  // as decided, deck evidence included
    std::string why;                  // "--solver smp", "*CONTROL_MPP_PFILE in the deck", ...
    grammar::Span evidence;           // the deck line that decided, when it was the deck
};
RunKind run_kind(const RuleContext& c);

// A real value as a deck would write it: 2.0 rather than 2, 1e+20 as is.
std::string number(double v);

// "FORM 12 (MLS)": the value and a short name, for messages.
std::string form_label(model::Form f);

// SPH010-SPH035 (FORM and IDIM), in rules_control_sph_form.cpp.
void check_forms(RuleContext& c, const std::vector<const model::Part*>& parts);
// SPH033 and SPH040-SPH043 (failure, erosion, deactivation), in rules_control_sph_erosion.cpp.
void check_erosion(RuleContext& c, const std::vector<const model::Part*>& parts);
// SPH070-SPH073 and SPH080 (box, MAXV, times), in rules_control_sph_limits.cpp.
void check_limits(RuleContext& c);
// SPH050, SPH060, SPH091-SPH094, in rules_control_sph_misc.cpp.
void check_misc(RuleContext& c, const std::vector<const model::Part*>& parts);
// SPH122 (and DK034 for a blank line): a *BOUNDARY_SPH_SYMMETRY_PLANE line whose normal has no length.
void check_symmetry_planes(RuleContext& c);

}  // namespace sphdeck::lint::control_sph
