// SPH010-SPH035 but SPH033: the particle approximation FORM of *CONTROL_SPH against the run type,
// the dimension, the sections and the materials (*CONTROL_SPH manual page, Remark 2).
#include <fmt/format.h>

#include <cmath>
#include <set>

#include "lint/rules_control_sph.hpp"

namespace sphdeck::lint::control_sph {
namespace {

using diag::Severity;
using model::Form;

bool differs(double a, double b) { return std::abs(a - b) > 1e-12 * std::max(1.0, std::abs(b)); }

// SPH010: FORM 12 and 13 exist in MPP LS-DYNA only (Remark 2e; FORM 13 from newer editions).
// An error when the run is known to be SMP. When nothing tells, information: the solver is chosen
// on the command line, not in the deck, and a deck with FORM 12 or 13 is written for MPP (the only
// place it runs), so a warning would sit on every published MLS and ISPH deck without a defect.
void check_mpp_only(RuleContext& c, const RunKind& run) {
    const auto& form = c.model.controls.sph.form;
    if (!model::is_mpp_only(form.value) || run.solver == Solver::Mpp) return;
    const std::string what = fmt::format("{} runs only in MPP", form_label(form.value));
    if (run.solver == Solver::Smp)
        c.report("SPH010", Severity::Error, form.span, fmt::format("{}; the run is SMP ({})", what, run.why));
    else
        c.report("SPH010", Severity::Info, form.span,
                 fmt::format("{}; nothing shows this is an MPP run (no --solver, no *CONTROL_MPP_*, no memory2=)",
                             what));
}

// SPH011-SPH013: FORM 12 wants a constant h; ISTAB and QL serve FORM 12 only.
void check_mls(RuleContext& c) {
    const model::ControlSph& sph = c.model.controls.sph;
    const bool mls = sph.form.value == Form::MovingLeastSquares;
    if (mls) {
        for (const model::Section& s : c.model.sections) {
            if (!s.sph || (!differs(s.hmin.value, 1.0) && !differs(s.hmax.value, 1.0))) continue;
            const grammar::Span at = differs(s.hmin.value, 1.0) ? s.hmin.span : s.hmax.span;
            c.report("SPH011", at,
                     fmt::format("section {} has HMIN {} and HMAX {} with {}; expected 1.0 for both (constant h)", s.id,
                                 number(s.hmin.value), number(s.hmax.value), form_label(sph.form.value)))
                .notes.push_back({sph.form.span, "FORM 12 is set here"});
        }
        if (sph.ql.value < 0.001 || sph.ql.value > 0.1)
            c.report("SPH013", sph.ql.span,
                     fmt::format("QL {} is outside the manual's range; expected 0.001 to 0.1 (default 0.01)",
                                 number(sph.ql.value)));
        return;
    }
    const std::string form = fmt::format("FORM is {}", static_cast<int>(sph.form.value));
    if (sph.istab.explicit_value && sph.istab.value != 0)
        c.report("SPH012", sph.istab.span, fmt::format("ISTAB {} only acts with FORM 12; {}", sph.istab.value, form));
    if (sph.ql.explicit_value && differs(sph.ql.value, 0.01))
        c.report("SPH012", sph.ql.span, fmt::format("QL {} only acts with FORM 12; {}", number(sph.ql.value), form));
}

// SPH020-SPH023: adaptive SPH (FORM 9, 10) needs ellipse sections, 3D and SMP (Remark 2g).
void check_asph(RuleContext& c, const std::vector<const model::Part*>& parts, const RunKind& run) {
    const model::ControlSph& sph = c.model.controls.sph;
    const bool asph = model::is_asph(sph.form.value);
    for (const model::Section& s : c.model.sections) {
        if (!s.ellipse || asph) continue;
        auto& d = c.report("SPH023", s.span,
                           fmt::format("section {} is *SECTION_SPH_ELLIPSE but FORM is {}; expected FORM 9 or 10", s.id,
                                       static_cast<int>(sph.form.value)));
        if (sph.present) d.notes.push_back({sph.form.span, "FORM is set here"});
    }
    if (!asph) return;
    const std::string label = form_label(sph.form.value);
    std::set<model::Id> reported;
    for (const model::Part* p : parts) {
        const model::Section* s = c.definitions().section_of(*p);
        if (!s || !s->sph || s->ellipse || !reported.insert(s->id).second) continue;
        c.report("SPH020", sph.form.span,
                 fmt::format("{} needs *SECTION_SPH_ELLIPSE; part {} uses {} {}", label, p->id, s->keyword, s->id))
            .notes.push_back({s->span, fmt::format("section {} is not an ellipse section", s->id)});
    }
    if (model::is_two_dimensional(sph.idim.value))
        c.report("SPH021", sph.form.span,
                 fmt::format("{} is 3D only; IDIM is {}; expected IDIM 3", label, static_cast<int>(sph.idim.value)))
            .notes.push_back({sph.idim.span, "IDIM is set here"});
    if (run.solver == Solver::Mpp) {
        auto& d =
            c.report("SPH022", sph.form.span, fmt::format("{} runs only in SMP; the run is MPP ({})", label, run.why));
        if (run.evidence.valid()) d.notes.push_back({run.evidence, "this makes it an MPP run"});
    }
}

// SPH030, SPH031: what 2D and axisymmetric models support (IAVIS; Remark 2f).
void check_dimension(RuleContext& c) {
    const model::ControlSph& sph = c.model.controls.sph;
    const int idim = static_cast<int>(sph.idim.value);
    if (sph.iavis.value == model::ArtificialViscosity::SolidBulk && model::is_two_dimensional(sph.idim.value))
        c.report("SPH030", sph.iavis.span,
                 fmt::format("IAVIS 1 (solid-element viscosity) is not supported with IDIM {}; expected IAVIS 0", idim))
            .notes.push_back({sph.idim.span, "IDIM is set here"});
    const Form f = sph.form.value;
    if (sph.idim.value == model::Dimension::Axisymmetric && f != Form::Default && f != Form::Renormalized &&
        !model::is_enhanced_fluid(f))
        c.report("SPH031", sph.form.span,
                 fmt::format("{} is not implemented for IDIM -2; expected FORM 0, 1, 15 or 16", form_label(f)))
            .notes.push_back({sph.idim.span, "IDIM -2 (axisymmetric) is set here"});
}

// A part is a fluid when its material is *MAT_NULL with an EOS or a fluid material
// (*MAT_ELASTIC_FLUID, *MAT_SPH_INCOMPRESSIBLE_FLUID); nullopt when it cannot be told.
std::optional<bool> is_fluid(const RuleContext& c, const model::Part& p) {
    const model::Material* mat = c.definitions().material_of(p);
    if (!mat) return std::nullopt;
    if (mat->keyword == "*MAT_NULL") {
        if (p.eos.value.empty()) return std::nullopt;  // SPH116's business
        return true;
    }
    if (mat->keyword.find("FLUID") != std::string::npos) return true;
    const auto& records = c.model.records;
    if (mat->record && *mat->record < records.size() && records[*mat->record].has_option("FLUID")) return true;
    return false;
}

// SPH032, SPH034, SPH035: FORM advice (Remarks 2a-2d).
void check_advice(RuleContext& c, const std::vector<const model::Part*>& parts) {
    const auto& form = c.model.controls.sph.form;
    const std::string label = form_label(form.value);
    switch (form.value) {
        case Form::Symmetric:
        case Form::SymmetricRenormalized:
            c.report("SPH032", form.span,
                     fmt::format("{} is not recommended for any case; expected FORM 1 for solids, 15 or 16 for fluids",
                                 label));
            return;
        case Form::TotalLagrangian:
        case Form::TotalLagrangianRenormalized:
            c.report("SPH035", form.span,
                     fmt::format("{} is tensile-stable but cannot take very large deformation", label));
            return;
        case Form::Default: break;
        default: return;
    }
    std::vector<const model::Part*> fluids, solids;
    for (const model::Part* p : parts)
        if (auto fluid = is_fluid(c, *p)) (*fluid ? fluids : solids).push_back(p);
    auto advise = [&](const std::vector<const model::Part*>& group, std::string_view kind, std::string_view expected) {
        if (group.empty()) return;
        std::string ids;
        for (std::size_t i = 0; i < group.size() && i < 5; ++i) ids += (i ? ", " : "") + group[i]->id;
        if (group.size() > 5) ids += ", ...";
        c.report("SPH034", form.span,
                 fmt::format("FORM 0 with {} part{} {}; FORM {} is recommended", kind, group.size() > 1 ? "s" : "", ids,
                             expected))
            .notes.push_back({group.front()->span, fmt::format("part {} is a {} part", group.front()->id, kind)});
    };
    advise(fluids, "fluid", "15 or 16");
    advise(solids, "solid", "1");
}

}  // namespace

void check_forms(RuleContext& c, const std::vector<const model::Part*>& parts) {
    const RunKind run = run_kind(c);
    check_asph(c, parts, run);  // SPH023 looks at sections even without *CONTROL_SPH
    if (!c.model.controls.sph.present) return;
    check_mpp_only(c, run);
    check_mls(c);
    check_dimension(c);
    check_advice(c, parts);
}

}  // namespace sphdeck::lint::control_sph
