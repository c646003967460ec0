// build_setup: parts (section, *MAT_NULL and EOS, or *MAT_ELASTIC), particles (preview h0 and
// masses, density, energy), then the controls, planes, loads and velocities (setup_controls.cpp).
#include "refsolver/setup.hpp"

#include <cmath>
#include <limits>
#include <fmt/format.h>

#include "grammar/number_cast.hpp"
#include "preproc/preview.hpp"
#include "preproc/smoothing_length.hpp"

namespace sphdeck::refsolver {

const model::KeywordRecord* model_record(const model::Model& m, std::optional<std::size_t> index) {
    return index && *index < m.records.size() ? &m.records[*index] : nullptr;
}

const model::FieldRecord* record_field(const model::KeywordRecord* r, std::string_view name) {
    const model::FieldRecord* f = r ? r->field(name) : nullptr;
    return f && f->valid ? f : nullptr;
}

double record_number(const model::KeywordRecord* r, std::string_view name, double fallback) {
    const model::FieldRecord* f = record_field(r, name);
    return f ? f->number : fallback;
}

long long record_integer(const model::KeywordRecord* r, std::string_view name, long long fallback) {
    const model::FieldRecord* f = record_field(r, name);
    const std::optional<long long> n = f ? grammar::checked_integer<long long>(f->number) : std::nullopt;
    return n ? *n : fallback;
}

namespace {

struct PartProblem {
    std::vector<Unsupported>& out;
    bool fine = true;
    void fatal(std::string what, grammar::Span span, bool blocking = true) {
        Unsupported u{std::move(what), span, true};
        u.blocking = blocking;
        out.push_back(std::move(u));
        fine = fine && !blocking;
    }
};

// The EOS of a *MAT_NULL part; false (with the reason listed) when the solver cannot run it.
bool read_eos(const model::Model& m, const model::Part& part, const model::Material& mat, PartSetup& ps,
              PartProblem& problem) {
    const model::KeywordRecord* mr = model_record(m, mat.record);
    EquationOfState& eos = ps.eos;
    eos.rho0 = mat.density.value;
    eos.pressure_cutoff = record_number(mr, "PC", 0.0);
    if (record_number(mr, "MU") != 0)
        problem.fatal(fmt::format("part {}: *MAT_NULL {} viscosity MU {} is not supported: the solver has no physical "
                                  "viscosity (only the Monaghan artificial viscosity)",
                                  part.id, mat.id, record_number(mr, "MU")),
                      record_field(mr, "MU")->span, false);
    for (const char* name : {"TEROD", "CEROD"})
        if (record_number(mr, name) != 0)
            problem.fatal(fmt::format("part {}: *MAT_NULL {} erosion {} {} is not supported: particles do not erode",
                                      part.id, mat.id, name, record_number(mr, name)),
                          record_field(mr, name)->span, false);
    const model::Eos* e = part.eos.value.empty() || part.eos.value == "0" ? nullptr : m.eos(part.eos.value);
    if (!e) {
        problem.fatal(fmt::format("part {}: *MAT_NULL without an equation of state (EOSID '{}'): the solver needs "
                                  "*EOS_LINEAR_POLYNOMIAL, *EOS_GRUNEISEN or *EOS_MURNAGHAN for the pressure",
                                  part.id, part.eos.value),
                      part.eos.span.valid() ? part.eos.span : part.span);
        return false;
    }
    const model::KeywordRecord* r = model_record(m, e->record);
    if (e->keyword == "*EOS_LINEAR_POLYNOMIAL") {
        eos.kind = EquationOfState::Kind::LinearPolynomial;
        const char* names[7] = {"C0", "C1", "C2", "C3", "C4", "C5", "C6"};
        for (int k = 0; k < 7; ++k) eos.c[k] = record_number(r, names[k]);
    } else if (e->keyword == "*EOS_GRUNEISEN") {
        eos.kind = EquationOfState::Kind::Gruneisen;
        eos.C = record_number(r, "C"), eos.S1 = record_number(r, "S1"), eos.S2 = record_number(r, "S2");
        eos.S3 = record_number(r, "S3"), eos.gamma0 = record_number(r, "GAMMA0"), eos.a = record_number(r, "A");
        if (record_number(r, "LCID") != 0)
            problem.fatal(fmt::format("*EOS_GRUNEISEN {}: energy deposition curve LCID {} is not supported", e->id,
                                      record_number(r, "LCID")),
                          record_field(r, "LCID")->span, false);
    } else if (e->keyword == "*EOS_MURNAGHAN") {
        eos.kind = EquationOfState::Kind::Murnaghan;
        eos.gamma = record_number(r, "GAMMA"), eos.k0 = record_number(r, "K0");
    } else {
        problem.fatal(fmt::format("part {}: {} is not supported: the solver runs *EOS_LINEAR_POLYNOMIAL, "
                                  "*EOS_GRUNEISEN and *EOS_MURNAGHAN",
                                  part.id, e->keyword),
                      e->span);
        return false;
    }
    return true;
}

// A *MAT_ELASTIC part (stress.hpp): p = K (rho / rho0 - 1) as *EOS_LINEAR_POLYNOMIAL C1 = K with no
// cut-off, G for the deviatoric stress, the dilatational wave speed for the time step.
bool read_elastic(const model::Model& m, const model::Part& part, const model::Material& mat, PartSetup& ps,
                  PartProblem& problem) {
    const model::KeywordRecord* mr = model_record(m, mat.record);
    const double young = record_number(mr, "E"), poisson = record_number(mr, "PR");
    if (!(young > 0)) {
        const model::FieldRecord* f = record_field(mr, "E");
        problem.fatal(fmt::format("part {}: *MAT_ELASTIC {} E {} is not supported: the solver needs a positive "
                                  "Young's modulus (E < 0, the EFUNC card, is not modelled)",
                                  part.id, mat.id, young),
                      f ? f->span : mat.span);
        return false;
    }
    if (!(poisson > -1 && poisson < 0.5)) {
        const model::FieldRecord* f = record_field(mr, "PR");
        problem.fatal(fmt::format("part {}: *MAT_ELASTIC {} PR {} is outside (-1, 0.5): no positive bulk and shear "
                                  "moduli",
                                  part.id, mat.id, poisson),
                      f ? f->span : mat.span);
        return false;
    }
    for (const char* name : {"DA", "DB"})
        if (record_number(mr, name) != 0)
            problem.fatal(fmt::format("part {}: *MAT_ELASTIC {} {} {} (beam damping) has no effect on particles",
                                      part.id, mat.id, name, record_number(mr, name)),
                          record_field(mr, name)->span, false);
    if (!part.eos.value.empty() && part.eos.value != "0")
        problem.fatal(fmt::format("part {}: EOSID {} is ignored: *MAT_ELASTIC takes its pressure from E and PR",
                                  part.id, part.eos.value),
                      part.eos.span.valid() ? part.eos.span : part.span, false);
    ps.elastic = ElasticModuli::from_young(young, poisson);
    EquationOfState& eos = ps.eos;
    eos.kind = EquationOfState::Kind::LinearPolynomial;
    eos.rho0 = mat.density.value;
    eos.c[1] = ps.elastic.bulk;
    ps.wave_speed = ps.elastic.wave_speed(eos.rho0);
    return true;
}

// Section, material and EOS of one part.
bool read_part(const model::Model& m, long long id, PartSetup& ps, std::vector<Unsupported>& out) {
    PartProblem problem{out};
    ps.id = id;
    const model::Part* part = m.part(std::to_string(id));
    if (!part) {
        problem.fatal(fmt::format("particles name part {}, which no *PART defines: no material for them", id), {});
        return false;
    }
    const model::Section* section = m.section(part->section.value);
    if (!section || !section->sph) {
        problem.fatal(fmt::format("part {}: section '{}' is not a *SECTION_SPH", id, part->section.value),
                      part->section.span);
    } else {
        ps.start = section->start.value, ps.death = section->death.value > 0 ? section->death.value : 1e20;
        if (section->ellipse)
            problem.fatal(fmt::format("part {}: *SECTION_SPH_ELLIPSE (anisotropic kernel) is not supported: the solver "
                                      "runs the isotropic cubic spline",
                                      id),
                          section->span, false);
        if (section->kernel.value != model::Kernel::CubicSpline)
            problem.fatal(fmt::format("part {}: SPHKERN {} is not supported: the solver runs SPHKERN 0 (cubic spline)",
                                      id, static_cast<int>(section->kernel.value)),
                          section->kernel.span, false);
    }
    const model::Material* mat = m.material(part->material.value);
    if (!mat) {
        problem.fatal(fmt::format("part {}: material '{}' is not defined", id, part->material.value),
                      part->material.span);
        return false;
    }
    if (!(mat->density.value > 0)) {
        problem.fatal(fmt::format("part {}: material {} density RO {} is not positive", id, mat->id,
                                  mat->density.value),
                      mat->density.span.valid() ? mat->density.span : mat->span);
        return false;
    }
    if (mat->keyword == "*MAT_ELASTIC") return read_elastic(m, *part, *mat, ps, problem) && problem.fine;
    if (mat->keyword != "*MAT_NULL") {
        problem.fatal(fmt::format("part {}: material {} is not supported: the solver runs *MAT_NULL with an equation "
                                  "of state (a fluid) and *MAT_ELASTIC",
                                  id, mat->keyword),
                      mat->span);
        return false;
    }
    return read_eos(m, *part, *mat, ps, problem) && problem.fine;
}

// The EOS's initial relative volume V0 (1 when not given) and energy E0 per reference volume.
void initial_eos_state(const model::Model& m, const model::Part* part, double& v0, double& e0) {
    v0 = 1, e0 = 0;
    if (!part) return;
    const model::Eos* e = m.eos(part->eos.value);
    const model::KeywordRecord* r = e ? model_record(m, e->record) : nullptr;
    const double v = record_number(r, "V0", 1.0);
    v0 = v > 0 ? v : 1.0;
    e0 = record_number(r, "E0", 0.0);
}

}  // namespace

SetupResult build_setup(const model::Model& m, const RunOptions& options) {
    SetupResult result;
    std::vector<Unsupported>& out = result.unsupported;
    const bool radioss = m.radioss.has_value();
    const model::RadiossRunInput run =
        radioss && options.deck ? model::read_radioss_run_input(*options.deck) : model::RadiossRunInput{};
    out = radioss ? radioss_unsupported(m, run) : unsupported_features(m);
    SolverInput in;
    bool runnable = true;

    const preproc::Preview preview = preproc::compute_preview(m);
    in.dimension = preview.dimension;
    in.parts.resize(preview.parts.size());
    std::vector<double> radioss_e0(preview.parts.size(), 0.0);  // /EOS/POLYNOMIAL E0 per part
    for (std::size_t q = 0; q < preview.parts.size(); ++q) {
        runnable = (radioss ? read_radioss_part(m, preview.parts[q].part, in.parts[q], radioss_e0[q], out)
                            : read_part(m, preview.parts[q].part, in.parts[q], out)) &&
                   runnable;
        if (!(preview.parts[q].h0 > 0)) {
            out.push_back({fmt::format("part {}: no initial smoothing length ({}); give SPHINI on its *SECTION_SPH",
                                       preview.parts[q].part, preview.parts[q].notes),
                           {},
                           true,
                           true});
            runnable = false;
        }
    }

    const std::size_t n = m.particles.size();
    const preproc::ParticlePreview& pp = preview.particles;
    in.x = pp.x, in.y = pp.y, in.z = pp.z, in.h = pp.h, in.m = pp.mass, in.part = pp.part;
    if (in.dimension == 2) std::fill(in.z.begin(), in.z.end(), 0.0);  // plane strain: the x-y plane
    in.vx.assign(n, 0), in.vy.assign(n, 0), in.vz.assign(n, 0), in.rho.assign(n, 0), in.e.assign(n, 0);
    in.h_low.assign(n, 0), in.h_high.assign(n, 0);
    // The EOS's V0 and E0 per part, looked up once (not per particle).
    std::vector<std::array<double, 2>> v0_e0(preview.parts.size(), {1.0, 0.0});
    for (std::size_t q = 0; q < preview.parts.size(); ++q)
        if (radioss)
            v0_e0[q] = {1.0, radioss_e0[q]};
        else if (!in.parts[q].solid())
            initial_eos_state(m, m.part(std::to_string(preview.parts[q].part)), v0_e0[q][0], v0_e0[q][1]);
    std::size_t unlocated = 0, massless = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const preproc::PartPreview& pv = preview.parts[pp.part[i]];
        const double v0 = v0_e0[pp.part[i]][0], e0 = v0_e0[pp.part[i]][1];
        in.rho[i] = pv.density / v0;
        in.e[i] = pv.density > 0 ? e0 / pv.density : 0.0;  // E0 per reference volume: e = E0 / rho0
        in.h_low[i] = pv.h_min > 0 ? pv.h_min : pv.h0;
        in.h_high[i] = pv.h_max >= in.h_low[i] ? pv.h_max : pv.h0;
        if (radioss && pv.h_min == 0 && pv.h_max == 0)  // h_1D 0: h follows the volume, unbounded
            in.h_low[i] = 0, in.h_high[i] = std::numeric_limits<double>::infinity();
        unlocated += !pp.located[i];
        massless += !(in.m[i] > 0);
    }
    if (n == 0) {
        out.push_back({radioss ? "the deck has no SPH particles (/SPHCEL): nothing to run"
                               : "the deck has no SPH particles (*ELEMENT_SPH): nothing to run",
                       {},
                       true,
                       true});
        runnable = false;
    }
    if (unlocated)
        out.push_back({fmt::format("{} particle(s) have no *NODE: no position", unlocated), {}, true, true}),
            runnable = false;
    if (massless)
        out.push_back(
            {fmt::format("{} particle(s) have no positive mass (MASS 0, or a volume without a density)", massless),
             {},
             true,
             true}),
            runnable = false;

    if (radioss) {
        setup_radioss_controls(m, run, options, in, out);
    } else {
        setup_controls(m, options, in, out);
        setup_initial_velocities(m, in, out);
    }
    for (const Unsupported& u : out) {
        if (u.blocking) runnable = false;
        if (u.fatal && !options.ignore_unsupported) runnable = false;
    }
    if (runnable) result.input = std::move(in);
    return result;
}

}  // namespace sphdeck::refsolver
