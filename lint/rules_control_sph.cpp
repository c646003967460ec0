// *CONTROL_SPH rules (SPH010-SPH094 but SPH081 and SPH090, which belong to the section and
// preview families): the entry point and the helpers the family's files share.
#include "lint/rules_control_sph.hpp"

#include <fmt/format.h>

#include <set>

#include "lint/rules.hpp"

namespace sphdeck::lint {
namespace control_sph {
namespace {

// A field the deck wrote with a valid number.
const model::FieldRecord* given(const model::KeywordRecord& r, std::string_view name) {
    const model::FieldRecord* f = r.field(name);
    return f && f->explicit_value && f->valid ? f : nullptr;
}

Criterion field_criterion(const model::FieldRecord& f, const model::Material& material) {
    return {f.span, fmt::format("{} {} on {} {}", f.name, number(f.number), material.keyword, material.id)};
}

}  // namespace

std::vector<const model::Part*> sph_parts(const RuleContext& c) {
    const model::Model& m = c.model;
    struct UsedParts {  // the parts the particles name: a fact of the particles alone (lint/bulk_facts.hpp)
        std::set<model::Id> ids;
    };
    const auto used = c.bulk_facts().get<UsedParts>([&] {
        UsedParts out;
        long long last = -1;  // particles come in long runs of the same part
        for (long long pid : m.particles.part) {
            if (pid == last) continue;
            out.ids.insert(std::to_string(pid));
            last = pid;
        }
        return out;
    });
    std::vector<const model::Part*> out;
    for (const model::Part& p : m.parts) {
        const model::Section* s = c.definitions().section_of(p);
        if (used->ids.count(p.id) || (s && s->sph)) out.push_back(&p);
    }
    return out;
}

std::optional<Criterion> material_failure(const model::Model& m, const model::Material& material) {
    for (const model::KeywordRecord& r : m.records) {
        if (r.schema->name != "*MAT_ADD_EROSION") continue;
        const model::FieldRecord* mid = r.field("MID");
        if (mid && mid->explicit_value && model::normalise_id(mid->text) == material.id)
            return Criterion{mid->span, fmt::format("*MAT_ADD_EROSION for material {}", material.id)};
    }
    if (!material.record || *material.record >= m.records.size()) return std::nullopt;
    const model::KeywordRecord& r = m.records[*material.record];
    const std::string_view name = r.schema->name;
    if (name == "*MAT_PLASTIC_KINEMATIC") {
        // FS defaults to 1e20 (no failure). An explicit 0 is read as "no failure" too: decks
        // written by pre-processors fill the field with 0 (lsdyna-sph-cards.md §17.3 lists no
        // meaning for it), and a criterion that fails every particle at once is not what they mean.
        const model::FieldRecord* fs = given(r, "FS");
        if (fs && fs->number > 0.0 && fs->number < 1.0e20) return field_criterion(*fs, material);
    } else if (name == "*MAT_JOHNSON_COOK") {
        for (std::string_view d : {"D1", "D2", "D3", "D4", "D5"})
            if (const model::FieldRecord* f = given(r, d); f && f->number != 0.0) return field_criterion(*f, material);
    } else if (name == "*MAT_NULL") {
        for (std::string_view e : {"TEROD", "CEROD"})
            if (const model::FieldRecord* f = given(r, e); f && f->number != 0.0) return field_criterion(*f, material);
    }
    return std::nullopt;
}

std::optional<Criterion> erosion_criterion(const RuleContext& c, const std::vector<const model::Part*>* parts) {
    const model::Model& m = c.model;
    if (parts) {
        std::set<model::Id> seen;
        for (const model::Part* p : *parts) {
            const model::Material* mat = c.definitions().material_of(*p);
            if (!mat || !seen.insert(mat->id).second) continue;
            if (auto failure = material_failure(m, *mat)) return failure;
        }
    } else {
        for (const model::Material& mat : m.materials)
            if (auto failure = material_failure(m, mat)) return failure;
        for (const model::KeywordRecord& r : m.records)  // even for a material nobody defines
            if (r.schema->name == "*MAT_ADD_EROSION") return Criterion{r.span, "*MAT_ADD_EROSION"};
    }
    const auto& erode = m.controls.erode;
    if (erode.value != 0) return Criterion{erode.span, fmt::format("ERODE {} on *CONTROL_TIMESTEP", erode.value)};
    return std::nullopt;
}

RunKind run_kind(const RuleContext& c) {
    RunKind k;
    if (c.options.solver != Solver::Unknown) {
        k.solver = c.options.solver;
        const char* word = k.solver == Solver::Mpp ? "mpp" : "smp";
        const std::string& source = c.options.solver_source;
        k.why = source.empty() || source == "--solver" ? fmt::format("--solver {}", word)
                                                       : fmt::format("solver = \"{}\" in {}", word, source);
        return k;
    }
    if (!c.model.controls.mpp_keywords.empty()) {
        k.solver = Solver::Mpp;
        k.evidence = c.model.controls.mpp_keywords.front();
        std::string keyword = "*CONTROL_MPP_";
        for (const grammar::Block& b : c.deck.blocks)
            if (b.span.file == k.evidence.file && b.span.line == k.evidence.line) keyword = b.keyword;
        k.why = fmt::format("{} in the deck", keyword);
    } else if (c.model.memory2_given) {
        k.solver = Solver::Mpp;
        k.evidence = c.deck.keyword_arguments.span;
        k.why = "memory2= on *KEYWORD";
    }
    return k;
}

std::string number(double v) {
    std::string s = fmt::format("{}", v);
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // n: inf, nan
    return s;
}

std::string form_label(model::Form f) {
    using model::Form;
    const int n = static_cast<int>(f);
    switch (f) {
        case Form::MovingLeastSquares: return fmt::format("FORM {} (MLS)", n);
        case Form::Incompressible: return fmt::format("FORM {} (ISPH)", n);
        case Form::Adaptive:
        case Form::AdaptiveRenormalized: return fmt::format("FORM {} (ASPH)", n);
        default: return fmt::format("FORM {} ({})", n, model::to_string(f));
    }
}

}  // namespace control_sph

void check_control_sph(RuleContext& c) {
    control_sph::check_symmetry_planes(c);
    if (!c.model.controls.sph.present) {
        // Without *CONTROL_SPH only the section-side rule can apply; the rest talk about its fields.
        control_sph::check_forms(c, {});
        return;
    }
    const std::vector<const model::Part*> parts = control_sph::sph_parts(c);
    control_sph::check_forms(c, parts);
    control_sph::check_erosion(c, parts);
    control_sph::check_limits(c);
    control_sph::check_misc(c, parts);
}

}  // namespace sphdeck::lint
