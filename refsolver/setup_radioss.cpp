// From an OpenRadioss deck to what the solver runs. The particles (positions, masses after the
// symmetry split, h0) come from the preview as for LS-DYNA decks (setup.cpp); here the parts
// (/PROP/TYPE34, the /MAT law and /EOS/POLYNOMIAL), the engine deck's /RUN and /DT, the /SPHBCS
// planes with their kinematic conditions, /INIVEL, and the list of what is not honoured.
// Sources (learnt from, not copied; OpenRadioss, AGPL-3.0): the starter's hm_read_prop34.F,
// hm_read_inivel.F, hm_read_spcnd.F; the engine's spforcp.F (pair forces and the Monaghan-type
// viscosity PIJ = (qa mu^2 - qb c mu) 2 / (rho_i + rho_j)), spdens.F, mdtsph.F and dtnoda.F
// (time steps), spsgsym.F (ghost velocities: SLIDE mirrored, TIED reversed).
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <set>

#include "refsolver/setup.hpp"

namespace sphdeck::refsolver {

namespace {

void add_radioss_unsupported(std::vector<Unsupported>& out, std::string what, grammar::Span span, bool fatal = true,
                             bool blocking = false) {
    Unsupported u{std::move(what), span, fatal};
    u.blocking = blocking;
    out.push_back(std::move(u));
}

struct OpaqueRule {
    std::string_view prefix, why;
    bool fatal;
};
// Blocks the reader keeps as they are that change an SPH run (the others, /TH, /ANIM, /FUNCT,
// /TITLE..., do not). /RUN and /INIVEL are read (model/radioss_run_input.cpp).
constexpr std::array<OpaqueRule, 11> opaque_rules = {{
    {"/GRAV", "gravity is not modelled for OpenRadioss decks", true},
    {"/BCS", "nodal boundary conditions are not modelled (only the /SPHBCS kinematic conditions)", true},
    {"/IMPVEL", "imposed velocities are not modelled", true},
    {"/IMPDISP", "imposed displacements are not modelled", true},
    {"/INTER", "contact interfaces are not modelled", true},
    {"/RWALL", "rigid walls are not modelled", true},
    {"/SENSOR", "sensors are not modelled", true},
    {"/ADYREL", "dynamic relaxation is not modelled", true},
    {"/KILL", "a kill file stop is not modelled", false},
    {"/DTIX", "the initial time step is not used: the solver starts with its own stable step", false},
    {"/STOP", "energy and mass stop criteria are not evaluated", false},
}};

bool radioss_starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

const model::IdSet* node_group(const model::Model& m, long long id) {
    for (const model::IdSet& s : m.node_sets)
        if (s.id == std::to_string(id)) return &s;
    return nullptr;
}

}  // namespace

std::vector<Unsupported> radioss_unsupported(const model::Model& m, const model::RadiossRunInput& run) {
    std::vector<Unsupported> out;
    const model::RadiossFacts& f = *m.radioss;
    for (const model::RadiossKeptBlock& b : run.blocks)
        for (const OpaqueRule& r : opaque_rules)
            if (radioss_starts_with(b.keyword, r.prefix) &&
                (b.keyword.size() == r.prefix.size() || b.keyword[r.prefix.size()] == '/'))
                add_radioss_unsupported(out, fmt::format("{}: {}", b.keyword, r.why), b.span, r.fatal);
    if (f.analysis != 0)
        add_radioss_unsupported(
            out,
            fmt::format("/ANALY N2D3D {} (2D) is not supported for OpenRadioss decks: the solver runs them in 3D",
                        f.analysis),
            f.analysis_span);
    for (const model::RadiossInout& io : f.inouts)
        add_radioss_unsupported(out, fmt::format("/SPH/INOUT {}: particle inlets and outlets are not modelled", io.id),
                                io.span);
    for (const model::RadiossReserve& r : f.reserves)
        add_radioss_unsupported(
            out,
            fmt::format("/SPH/RESERVE for part {}: reserve particles stay inactive (no inlet releases them)", r.part),
            r.span, false);
    for (const model::RadiossSolidProperty& p : f.solid_properties)
        if (p.sol2sph())
            add_radioss_unsupported(out,
                                    fmt::format("{} {}: SOL2SPH (solids turned into particles) is not modelled",
                                                p.keyword, p.id),
                                    p.span);
    if (f.bricks.size() + f.tetra4.size() + f.tetra10.size() + f.penta6.size() > 0)
        add_radioss_unsupported(out, "solid elements are not modelled: the solver runs the SPH particles only", {},
                                true);
    if (!f.initial_states.empty())
        add_radioss_unsupported(out,
                                fmt::format("/INISPHCEL: {} initial particle state(s) are not read",
                                            f.initial_states.size()),
                                f.initial_states.front().span);
    for (const model::RadiossSymmetry& s : f.symmetries) {
        if (!s.plane) {
            add_radioss_unsupported(out,
                                    fmt::format("/SPHBCS {}: its plane is not known (frame {} or direction '{}')", s.id,
                                                s.frame_id.value, s.dir.value),
                                    s.span, true, true);
            continue;
        }
        if (s.ilev.value == 0)
            add_radioss_unsupported(
                out,
                fmt::format("/SPHBCS {} Ilev 0: particles crossing the plane are put back with their normal "
                            "velocity reversed (Ilev 1), not dropped",
                            s.id),
                s.ilev.span, false);
    }
    // /DT/NODA/CST (and /DT/NODA/SET...) with a minimum step adds mass to keep the step (dtnoda.F).
    if (const model::RadiossDt* dt = f.time_step(model::DtKind::Nodal); dt && dt->dtmin.value > 0)
        add_radioss_unsupported(
            out,
            fmt::format("{}: the minimum step {} is not enforced (the engine adds nodal mass or stops there): "
                        "the solver runs the nodal step as computed",
                        dt->keyword, dt->dtmin.value),
            dt->span, false);
    return out;
}

namespace {

// The /EOS/POLYNOMIAL of a material (or the law's own C1 when no /EOS names it).
bool read_polynomial(const model::RadiossFacts& f, const model::RadiossMaterial& mat, long long part, PartSetup& ps,
                     double& e0, std::vector<Unsupported>& out) {
    EquationOfState& eos = ps.eos;
    eos.kind = EquationOfState::Kind::LinearPolynomial;
    eos.rho0 = mat.density;
    if (const model::RadiossEos* e = f.eos_of(mat.id)) {
        for (int k = 0; k < 6; ++k) eos.c[k] = e->c[k];
        if (e->rho0 > 0) eos.rho0 = e->rho0;
        e0 = e->e0;
        if (e->psh != 0)
            add_radioss_unsupported(out,
                                    fmt::format("/EOS/POLYNOMIAL {}: Psh {} (pressure shift) is not supported",
                                                e->material, e->psh),
                                    e->span);
        return true;
    }
    if (mat.bulk > 0) {
        eos.c[1] = mat.bulk;
        return true;
    }
    add_radioss_unsupported(out,
                            fmt::format("part {}: {} {} has no /EOS/POLYNOMIAL and no C1: no pressure", part,
                                        mat.keyword, mat.id),
                            mat.span, true, true);
    return false;
}

}  // namespace

// An elastic solid (LAW1, and LAW2 run without its plasticity): pressure from the bulk modulus, as *MAT_ELASTIC.
void run_elastic(const model::RadiossMaterial& mat, PartSetup& ps) {
    ps.elastic = ElasticModuli::from_young(mat.young, mat.poisson);
    ps.eos.kind = EquationOfState::Kind::LinearPolynomial;
    ps.eos.rho0 = mat.density;
    ps.eos.c[1] = ps.elastic.bulk;
    ps.wave_speed = ps.elastic.wave_speed(ps.eos.rho0);
}

bool read_radioss_part(const model::Model& m, long long id, PartSetup& ps, double& e0, std::vector<Unsupported>& out) {
    ps.id = id;
    e0 = 0;
    const model::RadiossFacts& f = *m.radioss;
    const model::Part* part = m.part(std::to_string(id));
    if (!part) {
        add_radioss_unsupported(out,
                                fmt::format("particles name part {}, which no /PART defines: no material for them", id),
                                {}, true, true);
        return false;
    }
    long long prop_id = 0, mat_id = 0;
    try {
        prop_id = std::stoll(part->section.value), mat_id = std::stoll(part->material.value);
    } catch (...) {
    }
    const model::RadiossSphProperty* prop = f.sph_property(prop_id);
    if (!prop) {
        add_radioss_unsupported(out,
                                fmt::format("part {}: property '{}' is not a /PROP/TYPE34 (SPH)", id,
                                            part->section.value),
                                part->section.span, true, true);
        return false;
    }
    if (prop->order.value == 0)
        add_radioss_unsupported(
            out,
            fmt::format("part {}: /PROP/TYPE34 {} Order 0 (zeroth-order correction) is not supported: the solver "
                        "runs Order -1 (none) and 1 (first order)",
                        id, prop->id),
            prop->order.span);
    if (prop->xi_stab.value != 0)
        add_radioss_unsupported(
            out,
            fmt::format("part {}: /PROP/TYPE34 {} Xi_Stab {} (tensile instability correction) is not modelled", id,
                        prop->id, prop->xi_stab.value),
            prop->xi_stab.span);
    if (prop->alpha_cs.value != 0)
        add_radioss_unsupported(
            out,
            fmt::format("part {}: /PROP/TYPE34 {} alpha_cs {} (conservative smoothing) is not modelled", id, prop->id,
                        prop->alpha_cs.value),
            prop->alpha_cs.span);
    if (prop->h_1d.value == 1)
        add_radioss_unsupported(
            out,
            fmt::format("part {}: /PROP/TYPE34 {} h_1D 1 is not supported: h follows the volume change", id, prop->id),
            prop->h_1d.span);
    const model::RadiossMaterial* mat = f.material(mat_id);
    if (!mat) {
        add_radioss_unsupported(out, fmt::format("part {}: material '{}' is not defined", id, part->material.value),
                                part->material.span, true, true);
        return false;
    }
    if (!(mat->density > 0)) {
        add_radioss_unsupported(out,
                                fmt::format("part {}: {} {} density {} is not positive", id, mat->keyword, mat->id,
                                            mat->density),
                                mat->span, true, true);
        return false;
    }
    switch (mat->law) {
        case 1: {  // LAW1 elastic: as *MAT_ELASTIC
            if (!(mat->young > 0) || !(mat->poisson > -1 && mat->poisson < 0.5)) {
                add_radioss_unsupported(out,
                                        fmt::format("part {}: {} {} needs E > 0 and -1 < nu < 0.5 (E {}, nu {})", id,
                                                    mat->keyword, mat->id, mat->young, mat->poisson),
                                        mat->span, true, true);
                return false;
            }
            run_elastic(*mat, ps);
            return true;
        }
        case 2:
            add_radioss_unsupported(
                out,
                fmt::format("part {}: {} {} (Johnson-Cook plasticity) is not supported: with --ignore-unsupported "
                            "it runs elastic (E, nu)",
                            id, mat->keyword, mat->id),
                mat->law_span);
            if (mat->young > 0 && mat->poisson > -1 && mat->poisson < 0.5) {
                run_elastic(*mat, ps);
                return true;
            }
            add_radioss_unsupported(out,
                                    fmt::format("part {}: {} {} has no E and nu the solver can run", id, mat->keyword,
                                                mat->id),
                                    mat->span, true, true);
            return false;
        case 3:  // HYDPLA: the polynomial EOS; with E = 0 no deviatoric stress (a fluid)
        case 6:  // HYD_VISC: the polynomial EOS and a physical viscosity
            if (mat->law == 3 && mat->young != 0)
                add_radioss_unsupported(
                    out,
                    fmt::format("part {}: {} {} E {}: the deviatoric stress and plastic flow (a, b, n) are not "
                                "modelled; the part runs as a fluid",
                                id, mat->keyword, mat->id, mat->young),
                    mat->span);
            if (mat->law == 6)
                add_radioss_unsupported(
                    out,
                    fmt::format("part {}: {} {}: the physical viscosity is not modelled (only qa/qb)", id, mat->keyword,
                                mat->id),
                    mat->span);
            return read_polynomial(f, *mat, id, ps, e0, out);
        case 0:
            add_radioss_unsupported(out,
                                    fmt::format("part {}: {} {} (void) gives particles no material", id, mat->keyword,
                                                mat->id),
                                    mat->law_span, true, true);
            return false;
        default:
            add_radioss_unsupported(
                out,
                fmt::format("part {}: {} {} is not supported: the solver runs LAW1 (elastic), LAW3 (HYDPLA) and LAW6 "
                            "(HYD_VISC) with /EOS/POLYNOMIAL",
                            id, mat->keyword, mat->id),
                mat->law_span, true, true);
            return false;
    }
}

namespace {

using Projector = std::array<double, 9>;
constexpr Projector identity_matrix{1, 0, 0, 0, 1, 0, 0, 0, 1};

Projector times(const Projector& a, const Projector& b) {
    Projector c{};
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) c[3 * r + k] += a[3 * r + j] * b[3 * j + k];
    return c;
}

// Planes (ghosts), and the kinematic condition of each /SPHBCS on its node group (seed page
// radioss_sph_symmetry_timestep.txt: SLIDE zeroes the normal velocity, TIED all of it).
void setup_symmetry(const model::Model& m, SolverInput& in, std::vector<Unsupported>& out) {
    const model::RadiossFacts& f = *m.radioss;
    std::map<long long, std::size_t> node_to_particle;
    for (std::size_t i = 0; i < m.particles.size(); ++i) node_to_particle.emplace(m.particles.node[i], i);
    for (const model::RadiossSymmetry& s : f.symmetries) {
        if (!s.plane || *s.plane >= m.symmetry_planes.size()) continue;
        const model::SymmetryPlane& q = m.symmetry_planes[*s.plane];
        std::array<double, 3> n{q.head[0] - q.tail[0], q.head[1] - q.tail[1], q.head[2] - q.tail[2]};
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(length > 0)) continue;
        for (double& v : n) v /= length;
        SymmetryPlane plane{n, n[0] * q.tail[0] + n[1] * q.tail[1] + n[2] * q.tail[2]};
        plane.tied = s.kind == model::SymmetryKind::Tied;
        in.planes.push_back(plane);
        if (s.grnod_id.value <= 0) continue;
        const model::IdSet* group = node_group(m, s.grnod_id.value);
        if (!group) {
            add_radioss_unsupported(out,
                                    fmt::format("/SPHBCS {}: node group {} is not defined: no kinematic condition",
                                                s.id, s.grnod_id.value),
                                    s.grnod_id.span, true, true);
            continue;
        }
        Projector p{};
        if (!plane.tied)
            for (int r = 0; r < 3; ++r)
                for (int k = 0; k < 3; ++k) p[3 * r + k] = (r == k ? 1.0 : 0.0) - n[r] * n[k];
        if (in.kinematic.empty()) in.kinematic.assign(m.particles.size(), identity_matrix);
        for (long long node : group->members)
            if (auto it = node_to_particle.find(node); it != node_to_particle.end())
                in.kinematic[it->second] = times(p, in.kinematic[it->second]);
    }
    if (in.planes.size() > 8)
        add_radioss_unsupported(out,
                                fmt::format("{} symmetry planes: the solver mirrors across the first 8 only",
                                            in.planes.size()),
                                f.symmetries[8].span);
}

void setup_inivel(const model::Model& m, const model::RadiossRunInput& run, SolverInput& in,
                  std::vector<Unsupported>& out) {
    std::map<long long, std::size_t> node_to_particle;
    for (std::size_t i = 0; i < m.particles.size(); ++i) node_to_particle.emplace(m.particles.node[i], i);
    for (const model::RadiossInitialVelocity& v : run.initial_velocities) {
        if (v.kind != "TRA") {
            add_radioss_unsupported(out,
                                    fmt::format("/INIVEL/{} is not supported: the solver reads /INIVEL/TRA", v.kind),
                                    v.span);
            continue;
        }
        if (!v.read) {
            add_radioss_unsupported(
                out, "/INIVEL/TRA: its card could not be read (Vx Vy Vz in 20 columns, then the group and skew)",
                v.span, true, true);
            continue;
        }
        if (v.skew != 0)
            add_radioss_unsupported(
                out, fmt::format("/INIVEL/TRA: skew {} is not supported: the velocity is taken in global axes", v.skew),
                v.span);
        const model::IdSet* group = node_group(m, v.group);
        if (!group) {
            add_radioss_unsupported(out, fmt::format("/INIVEL/TRA: node group {} is not defined", v.group), v.span,
                                    true, true);
            continue;
        }
        for (long long node : group->members)
            if (auto it = node_to_particle.find(node); it != node_to_particle.end())
                in.vx[it->second] = v.v[0], in.vy[it->second] = v.v[1], in.vz[it->second] = v.v[2];
    }
}

}  // namespace

void setup_radioss_controls(const model::Model& m, const model::RadiossRunInput& run, const RunOptions& options,
                            SolverInput& in, std::vector<Unsupported>& out) {
    const model::RadiossFacts& f = *m.radioss;
    // qa quadratic, qb linear (spforcp.F): the solver's q1 (quadratic) and q2 (linear), as
    // *CONTROL_BULK_VISCOSITY Q1/Q2. One pair for the run: the first SPH property's.
    std::set<std::pair<double, double>> pairs;
    for (const model::RadiossSphProperty& p : f.sph_properties) pairs.insert({p.qa.value, p.qb.value});
    if (!f.sph_properties.empty())
        in.q1 = f.sph_properties.front().qa.value, in.q2 = f.sph_properties.front().qb.value;
    else
        in.q1 = 2.0, in.q2 = 1.0;  // hm_read_prop34.F defaults
    if (pairs.size() > 1)
        add_radioss_unsupported(
            out,
            fmt::format("{} different qa/qb pairs: the solver uses the first property's (qa {}, qb {}) for every "
                        "pair",
                        pairs.size(), in.q1, in.q2),
            f.sph_properties[1].span);
    bool order1 = false;
    for (const model::RadiossSphProperty& p : f.sph_properties) order1 = order1 || p.order.value == 1;
    in.renormalise = order1;
    in.volume_weighted = true;
    in.planes_per_image = 1;  // the engine's single images (spsym.F), no corner images  // the engine's equations at
                              // every Order (spdens.F, spforcp.F)
    in.h_rule = SmoothingLengthRule::Divergence;  // h follows the volume: dh/dt = h div v / 3, h ~ rho^(-1/3) (h_1D 0)
    in.tssfac = m.controls.tssfac.value > 0 ? m.controls.tssfac.value : 0.9;
    in.radioss_step = true;
    in.radioss_nodal_step = f.time_step(model::DtKind::Nodal) != nullptr;  // /DT/NODA: dtnoda.F
    in.end_time = options.end_time.value_or(run.end_time.value_or(0.0));
    in.ncbs = 1;
    in.maxv = 0;  // no velocity check in Radioss
    if (!(in.end_time > 0))
        add_radioss_unsupported(out,
                                run.end_time
                                    ? fmt::format("/RUN end time {} is not positive: give --end-time", *run.end_time)
                                    : std::string(
                                          "no engine deck with /RUN (<run>_0001.rad next to the starter deck): give "
                                          "--end-time"),
                                run.run_span, true, true);
    setup_symmetry(m, in, out);
    setup_inivel(m, run, in, out);
    if (!in.kinematic.empty())
        for (std::size_t i = 0; i < in.kinematic.size(); ++i) {
            const Projector& p = in.kinematic[i];
            const double vx = in.vx[i], vy = in.vy[i], vz = in.vz[i];
            in.vx[i] = p[0] * vx + p[1] * vy + p[2] * vz;
            in.vy[i] = p[3] * vx + p[4] * vy + p[5] * vz;
            in.vz[i] = p[6] * vx + p[7] * vy + p[8] * vz;
        }
}

}  // namespace sphdeck::refsolver
