// SPH081, SPH100-SPH104: *SECTION_SPH values (lsdyna-sph-cards.md §2) and the section of the
// parts that hold particles. Blank and 0 are already the defaults here for CSLH, HMIN, HMAX,
// SPHINI and DEATH (zero_is_default in the schema): a Setting's value is what LS-DYNA uses.
#include <fmt/format.h>
#include <map>

#include "grammar/value.hpp"
#include "lint/rules.hpp"

namespace sphdeck::lint {
namespace {

using model::Section;

// The text written in a setting's columns, as a number; nullopt for blank or &parameter.
std::optional<double> written_number(const RuleContext& c, const model::Setting<double>& s) {
    if (!s.explicit_value || !s.span.valid() || s.span.end_column <= s.span.column) return std::nullopt;
    std::string_view line = c.deck.sources.line_text(s.span.file, s.span.line);
    if (s.span.column - 1 >= line.size()) return std::nullopt;
    grammar::RealValue v = grammar::parse_real(line.substr(s.span.column - 1, s.span.end_column - s.span.column));
    if (v.status != grammar::NumberStatus::Ok) return std::nullopt;
    return v.value;
}

// SPH081: the section is computed from START until DEATH.
void check_death(RuleContext& c, const Section& s) {
    if (s.death.value > s.start.value) return;
    c.report("SPH081", s.death.span,
             fmt::format("section {} DEATH {:g} is not after START {:g}: its particles are never computed; "
                         "expected DEATH > START",
                         s.id, s.death.value, s.start.value))
        .notes.push_back({s.start.span, fmt::format("START {:g} given here", s.start.value)});
}

// SPH100: 1.05-1.3 acceptable, below 1 inadmissible (§2, CSLH). Not checked when SPHINI > 0:
// CSLH is then ignored, which SPH102 says.
void check_cslh(RuleContext& c, const Section& s) {
    const double cslh = s.cslh.value;
    if (s.sphini.value > 0) return;
    if (cslh < 1.0) {
        c.report("SPH100", diag::Severity::Error, s.cslh.span,
                 fmt::format("CSLH {:g} is below 1 (inadmissible); expected 1.05-1.3", cslh));
    } else if (cslh < 1.05 || cslh > 1.3) {
        c.report("SPH100", diag::Severity::Warning, s.cslh.span,
                 fmt::format("CSLH {:g} is outside the acceptable range 1.05-1.3", cslh));
    }
}

// SPH101: the bounds HMIN h0 <= h <= HMAX h0 must bracket h0, so HMIN <= 1 <= HMAX (which also
// gives HMIN <= HMAX).
void check_bounds(RuleContext& c, const Section& s) {
    const double hmin = s.hmin.value, hmax = s.hmax.value;
    const bool low_bad = hmin > 1.0, high_bad = hmax < 1.0;
    if (!low_bad && !high_bad) return;
    const auto& primary = low_bad ? s.hmin : s.hmax;
    const auto& other = low_bad ? s.hmax : s.hmin;
    std::string what = low_bad && hmin > hmax ? fmt::format("HMIN {:g} is above 1 and above HMAX {:g}", hmin, hmax)
                       : low_bad              ? fmt::format("HMIN {:g} is above 1", hmin)
                                              : fmt::format("HMAX {:g} is below 1", hmax);
    auto& d = c.report("SPH101", primary.span, what + "; expected HMIN <= 1 <= HMAX");
    if (hmin > hmax)
        d.notes.push_back({other.span, fmt::format("{} {:g} here", low_bad ? "HMAX" : "HMIN", other.value)});
}

// SPH102: SPHINI > 0 replaces the computed h0, so an explicit CSLH does nothing. A written 0
// means "default" (zero_is_default), not a value the user chose.
void check_sphini(RuleContext& c, const Section& s) {
    if (s.sphini.value <= 0 || !s.cslh.explicit_value) return;
    std::optional<double> written = written_number(c, s.cslh);
    if (written && *written == 0.0) return;
    c.report("SPH102", s.cslh.span,
             fmt::format("CSLH {:g} is ignored because SPHINI {:g} sets the initial smoothing length; "
                         "leave CSLH blank",
                         s.cslh.value, s.sphini.value))
        .notes.push_back({s.sphini.span, "SPHINI given here"});
}

// SPH103: the quintic spline wants HMAX >= 3 and FORM 0, 1, 9 or 10 (§2, SPHKERN).
void check_kernel(RuleContext& c, const Section& s) {
    if (s.kernel.value != model::Kernel::QuinticSpline) return;
    const auto& form = c.model.controls.sph.form;
    const auto f = form.value;
    const bool form_bad = !(f == model::Form::Default || f == model::Form::Renormalized || model::is_asph(f));
    const bool hmax_bad = s.hmax.value < 3.0;
    if (!form_bad && !hmax_bad) return;
    std::string what;
    if (hmax_bad) what = fmt::format("HMAX {:g} (expected >= 3)", s.hmax.value);
    if (form_bad)
        what += fmt::format("{}FORM {} (expected 0, 1, 9 or 10)", hmax_bad ? " and " : "", static_cast<int>(f));
    auto& d = c.report("SPH103", s.kernel.span, "quintic kernel (SPHKERN 1) with " + what);
    if (hmax_bad) d.notes.push_back({s.hmax.span, fmt::format("HMAX {:g} here", s.hmax.value)});
    if (form_bad && c.model.controls.sph.present)
        d.notes.push_back({form.span, fmt::format("FORM {} here", static_cast<int>(f))});
}

// SPH104: parts holding particles must have an SPH section. One finding per part.
void check_particle_sections(RuleContext& c) {
    struct PartCounts {  // part id → particles: a fact of the particles alone (lint/bulk_facts.hpp)
        std::map<long long, std::size_t> counts;
    };
    const auto counted = c.bulk_facts().get<PartCounts>([&] {
        PartCounts out;
        long long last = 0;
        std::size_t* count = nullptr;
        for (long long p : c.model.particles.part) {
            if (!count || p != last) count = &out.counts[p], last = p;  // particles come in runs of one part
            ++*count;
        }
        return out;
    });
    for (const auto& [id, n] : counted->counts) {
        const model::Part* part = c.model.part(std::to_string(id));
        if (!part) continue;  // REF002
        const Section* section = c.definitions().section_of(*part);
        if (!section || section->sph) continue;  // REF003, or fine
        c.report("SPH104", part->section.span,
                 fmt::format("part {} holds {} SPH particle{} but its section {} is {}; expected a {}", part->id, n,
                             n == 1 ? "" : "s", section->id, section->keyword,
                             c.model.radioss ? "/PROP/SPH" : "*SECTION_SPH"))
            .notes.push_back({section->span, fmt::format("section {} is defined here", section->id)});
    }
}

}  // namespace

void check_section_sph(RuleContext& c) {
    for (const Section& s : c.model.sections) {
        if (!s.sph) continue;
        check_death(c, s);
        check_cslh(c, s);
        check_bounds(c, s);
        check_sphini(c, s);
        check_kernel(c, s);
    }
    check_particle_sections(c);
}

}  // namespace sphdeck::lint
