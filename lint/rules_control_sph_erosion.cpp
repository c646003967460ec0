// SPH033 and SPH040-SPH043: failure and erosion criteria against FORM and IEROD, and the flags
// that act on deactivated particles (*CONTROL_SPH, Remarks 2b and 3).
#include <fmt/format.h>

#include <set>

#include "lint/rules_control_sph.hpp"

namespace sphdeck::lint::control_sph {
namespace {

// SPH033: the enhanced fluid forms smooth the pressure field, which does not suit materials
// that fail (Remark 2b).
void check_fluid_form(RuleContext& c, const std::vector<const model::Part*>& parts) {
    const auto& form = c.model.controls.sph.form;
    if (!model::is_enhanced_fluid(form.value)) return;
    std::set<model::Id> seen;
    for (const model::Part* p : parts) {
        const model::Material* mat = c.definitions().material_of(*p);
        if (!mat || !seen.insert(mat->id).second) continue;
        if (auto criterion = material_failure(c.model, *mat))
            c.report("SPH033", form.span,
                     fmt::format("{} smooths pressure but part {} has failure: {}; expected FORM 1",
                                 form_label(form.value), p->id, criterion->what))
                .notes.push_back({criterion->span, "failure criterion given here"});
    }
}

// SPH040, SPH041: IEROD against the erosion criteria (Remark 3, 3a).
void check_ierod(RuleContext& c, const std::vector<const model::Part*>& parts) {
    const auto& ierod = c.model.controls.sph.ierod;
    const int value = static_cast<int>(ierod.value);
    if (ierod.value == model::ErosionMode::StayActive) {
        if (auto criterion = erosion_criterion(c, &parts))
            c.report("SPH040", ierod.span,
                     fmt::format("IEROD 0 keeps particles active despite {}; expected IEROD 1, 2 or 3",
                                 criterion->what))
                .notes.push_back({criterion->span, "erosion criterion given here"});
    } else if (!erosion_criterion(c, nullptr)) {
        c.report("SPH041", ierod.span,
                 fmt::format("IEROD {} but no erosion criterion exists (material failure, *MAT_ADD_EROSION, ERODE); "
                             "expected IEROD 0",
                             value));
    }
}

// Whether any particle can be deactivated: erosion with IEROD, a BOXID box, a MAXV limit, or
// SPH death (DT, section DEATH) before the end of the run.
bool can_deactivate(const RuleContext& c) {
    const model::Model& m = c.model;
    const model::ControlSph& sph = m.controls.sph;
    if (sph.ierod.value != model::ErosionMode::StayActive && erosion_criterion(c, nullptr)) return true;
    if (sph.boxid.value != 0) return true;
    // A MAXV limit: written and positive (MAXV <= 0, see SPH073), and below the default 1e15, which
    // decks often write out and which no particle reaches.
    if (sph.maxv.explicit_value && sph.maxv.value > 0.0 && sph.maxv.value < 1.0e15) return true;
    const double end = m.controls.endtim.value;
    if (end <= 0.0) return false;
    if (sph.dt.value < end) return true;
    for (const model::Section& s : m.sections)
        if (s.sph && s.death.value < end) return true;
    return false;
}

// SPH042, SPH043: ICONT and ISHOW act on deactivated particles only (Remarks 3e, 3f).
void check_deactivation_flags(RuleContext& c) {
    const model::ControlSph& sph = c.model.controls.sph;
    if (sph.icont.value != 1 && sph.ishow.value != 1) return;
    if (can_deactivate(c)) return;
    constexpr std::string_view nothing =
        "nothing can deactivate particles (no erosion with IEROD, no BOXID, no MAXV limit, no DT or DEATH before "
        "ENDTIM)";
    if (sph.icont.value == 1)
        c.report("SPH042", sph.icont.span, fmt::format("ICONT 1 has no effect: {}; expected ICONT 0", nothing));
    if (sph.ishow.value == 1)
        c.report("SPH043", sph.ishow.span, fmt::format("ISHOW 1 has no effect: {}; expected ISHOW 0", nothing));
}

}  // namespace

void check_erosion(RuleContext& c, const std::vector<const model::Part*>& parts) {
    check_fluid_form(c, parts);
    check_ierod(c, parts);
    check_deactivation_flags(c);
}

}  // namespace sphdeck::lint::control_sph
