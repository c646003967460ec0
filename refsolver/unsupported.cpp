// What in the deck changes the physics and is not honoured by the solver (the list `sphdeck run`
// prints; fatal items stop the run unless --ignore-unsupported). Settings of *CONTROL_SPH and
// *CONTROL_TIMESTEP here; per-part items (material, EOS, section) in setup.cpp.
#include <array>
#include <fmt/format.h>
#include <set>

#include "grammar/number_cast.hpp"
#include "refsolver/setup.hpp"

namespace sphdeck::refsolver {

namespace {

// Keywords the solver reads, or that do not change the physics of an SPH-only run.
constexpr std::array<std::string_view, 29> understood = {
    "*KEYWORD",
    "*TITLE",
    "*COMMENT",
    "*END",
    "*PARAMETER",
    "*PARAMETER_EXPRESSION",
    "*PARAMETER_DUPLICATION",
    "*INCLUDE",
    "*INCLUDE_PATH",
    "*INCLUDE_PATH_RELATIVE",
    "*INCLUDE_TRANSFORM",
    "*CONTROL_SPH",
    "*CONTROL_BULK_VISCOSITY",
    "*CONTROL_TIMESTEP",
    "*CONTROL_TERMINATION",
    "*CONTROL_MPP_DECOMPOSITION_SCALE_FACTOR_SPH",
    "*CONTROL_MPP_DECOMPOSITION_DISTRIBUTE_SPH_ELEMENTS",
    "*DEFINE_BOX",
    "*DEFINE_CURVE",
    "*SET_NODE_LIST",
    "*SET_PART_LIST",
    "*PART",
    "*SECTION_SPH",
    "*BOUNDARY_SPH_SYMMETRY_PLANE",
    "*INITIAL_VELOCITY",
    "*INITIAL_VELOCITY_NODE",
    "*INITIAL_VELOCITY_GENERATION",
    "*HOURGLASS",
    "*DEFINE_BOX_SPH",
};

// Keywords that change the physics and that the solver does not model.
struct Refused {
    std::string_view keyword, why;
};
constexpr std::array<Refused, 4> refused = {{
    {"*BOUNDARY_SPH_FLOW", "particle inflow is not modelled"},
    {"*BOUNDARY_SPH_NON_REFLECTING", "non-reflecting boundaries are not modelled"},
    {"*DEFINE_SPH_TO_SPH_COUPLING", "part-to-part penalty coupling is not modelled"},
    {"*DEFINE_ADAPTIVE_SOLID_TO_SPH", "solid-to-particle conversion is not modelled"},
}};

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

void add_unsupported(std::vector<Unsupported>& out, std::string what, grammar::Span span, bool fatal = true) {
    out.push_back({std::move(what), span, fatal});
}

void control_sph_items(const model::Model& m, std::vector<Unsupported>& out) {
    const model::ControlSph& sph = m.controls.sph;
    const model::Form form = sph.form.value;
    if (form != model::Form::Default && form != model::Form::Renormalized)
        add_unsupported(
            out,
            fmt::format("*CONTROL_SPH FORM {} ({}) is not supported: the solver runs FORM 0 (default) and FORM 1 "
                        "(renormalization); with --ignore-unsupported it runs FORM 0",
                        static_cast<int>(form), model::to_string(form)),
            sph.form.span);
    if (sph.idim.value == model::Dimension::Axisymmetric)
        add_unsupported(
            out,
            "*CONTROL_SPH IDIM -2 (2D axisymmetric) is not supported: the solver runs IDIM 3 (3D) and 2 (plane "
            "strain); with --ignore-unsupported it runs plane strain",
            sph.idim.span);
    if (sph.idim.value == model::Dimension::Unset)
        add_unsupported(out, "*CONTROL_SPH IDIM not given: 3D assumed",
                        sph.idim.span.valid() ? sph.idim.span : sph.keyword, false);
    if (sph.iavis.value != model::ArtificialViscosity::Monaghan)
        add_unsupported(
            out,
            fmt::format("*CONTROL_SPH IAVIS {} (solid-element bulk viscosity) is not supported: the solver runs "
                        "IAVIS 0 (Monaghan); with --ignore-unsupported it runs IAVIS 0",
                        static_cast<int>(sph.iavis.value)),
            sph.iavis.span);
    if (sph.deriv.value != 0 && sph.deriv.value != 1)
        add_unsupported(out,
                        fmt::format("*CONTROL_SPH DERIV {} is not supported: 0 or 1 expected; DERIV 0 is run",
                                    sph.deriv.value),
                        sph.deriv.span);
    if (sph.ishift.value != 0)
        add_unsupported(out,
                        fmt::format("*CONTROL_SPH ISHIFT {} (particle shifting) is not supported", sph.ishift.value),
                        sph.ishift.span);
    if (sph.ierod.value != model::ErosionMode::StayActive)
        add_unsupported(out,
                        fmt::format("*CONTROL_SPH IEROD {} has no effect: the solver evaluates no erosion criteria",
                                    static_cast<int>(sph.ierod.value)),
                        sph.ierod.span, false);
    std::set<long long> parts(m.particles.part.begin(), m.particles.part.end());
    if (sph.cont.value == 1 && parts.size() > 1)
        add_unsupported(out, "*CONTROL_SPH CONT 1 (no interaction between parts) is not supported: all parts interact",
                        sph.cont.span);
    if (sph.ncbs.value < 1)
        add_unsupported(out, fmt::format("*CONTROL_SPH NCBS {} taken as 1", sph.ncbs.value), sph.ncbs.span, false);
}

void timestep_items(const model::Model& m, std::vector<Unsupported>& out) {
    for (const model::KeywordRecord& r : m.records) {
        if (!r.schema || r.schema->name != "*CONTROL_TIMESTEP") continue;
        if (record_number(&r, "DT2MS") != 0)
            add_unsupported(out,
                            fmt::format("*CONTROL_TIMESTEP DT2MS {} (mass scaling) is not supported",
                                        record_number(&r, "DT2MS")),
                            record_field(&r, "DT2MS")->span);
        if (record_number(&r, "LCTM") != 0)
            add_unsupported(out,
                            fmt::format("*CONTROL_TIMESTEP LCTM {} (time-step limit curve) is not used",
                                        record_number(&r, "LCTM")),
                            record_field(&r, "LCTM")->span, false);
        if (record_number(&r, "ERODE") != 0)
            add_unsupported(out,
                            fmt::format("*CONTROL_TIMESTEP ERODE {} has no effect: particles are never eroded",
                                        record_number(&r, "ERODE")),
                            record_field(&r, "ERODE")->span, false);
    }
}

// A part's *HOURGLASS Q1/Q2 would replace the global ones (sph-algorithms.md §6.1).
void hourglass_items(const model::Model& m, std::vector<Unsupported>& out) {
    for (const model::Part& part : m.parts) {
        if (part.hourglass.value.empty() || part.hourglass.value == "0") continue;
        for (const model::KeywordRecord& r : m.records) {
            if (!r.schema || r.schema->name != "*HOURGLASS") continue;
            const model::FieldRecord* id = record_field(&r, "HGID");
            if (!id || model::normalise_id(fmt::format("{}", grammar::saturating_integer<long long>(id->number))) !=
                           part.hourglass.value)
                continue;
            const double q1 = record_number(&r, "Q1", m.controls.q1.value),
                         q2 = record_number(&r, "Q2", m.controls.q2.value);
            if (q1 != m.controls.q1.value || q2 != m.controls.q2.value)
                add_unsupported(
                    out,
                    fmt::format("part {}: *HOURGLASS {} Q1 {} / Q2 {} per part are not supported: the solver uses "
                                "*CONTROL_BULK_VISCOSITY's Q1 {} / Q2 {} for every pair",
                                part.id, part.hourglass.value, q1, q2, m.controls.q1.value, m.controls.q2.value),
                    r.span);
        }
    }
}

}  // namespace

std::vector<Unsupported> unsupported_features(const model::Model& m) {
    std::vector<Unsupported> out;
    control_sph_items(m, out);
    timestep_items(m, out);
    hourglass_items(m, out);
    for (const model::KeywordRecord& r : m.records) {
        const std::string_view name = r.schema ? r.schema->name : std::string_view(r.keyword);
        bool known = false;
        for (std::string_view k : understood) known = known || name == k;
        if (known || (starts_with(name, "*MAT_") && name != "*MAT_ADD_EROSION") || starts_with(name, "*EOS_") ||
            starts_with(name, "*LOAD_BODY_") || starts_with(name, "*DATABASE_"))
            continue;  // materials and EOS are checked per part that uses them
        bool listed = false;
        for (const Refused& f : refused)
            if (name == f.keyword) add_unsupported(out, fmt::format("{}: {}", r.keyword, f.why), r.span), listed = true;
        if (name == "*MAT_ADD_EROSION")
            add_unsupported(out, "*MAT_ADD_EROSION: erosion criteria are not evaluated", r.span), listed = true;
        if (!listed) add_unsupported(out, fmt::format("{} is not used by the solver", r.keyword), r.span, false);
    }
    return out;
}

}  // namespace sphdeck::refsolver
