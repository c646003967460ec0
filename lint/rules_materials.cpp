// SPH116-SPH117: materials and equations of state of SPH parts (lsdyna-sph-cards.md §17-§18,
// sph-algorithms.md §10).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_set>

#ifdef _OPENMP
#include <omp.h>
#else
static int omp_get_max_threads() { return 1; }
#endif

#include "lint/rules.hpp"
#include "model/id_index.hpp"

namespace sphdeck::lint {
namespace {

using model::Id;

// What the particles of one part tell SPH117: their largest initial speed and their extent.
struct PartStats {
    double speed = 0.0;  // largest initial speed from *INITIAL_VELOCITY
    const model::KeywordRecord* speed_record = nullptr;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
};

double material_number(const model::KeywordRecord& r, std::string_view field, double fallback = 0.0) {
    const model::FieldRecord* f = r.field(field);
    return f && f->valid ? f->number : fallback;
}

// Runs `f(particle, part stats)` over particles [from, to), looking a part up once per run of equal ids
// (particles come in blocks of one part).
template <typename F>
void for_each_particle(const model::Particles& p, std::size_t from, std::size_t to, std::map<Id, PartStats>& parts,
                       F f) {
    long long last = 0;
    PartStats* stats = nullptr;
    for (std::size_t i = from; i < to; ++i) {
        if (!stats || p.part[i] != last) last = p.part[i], stats = &parts[std::to_string(last)];
        f(i, *stats);
    }
}
template <typename F>
void for_each_particle(const model::Particles& p, std::map<Id, PartStats>& parts, F f) {
    for_each_particle(p, 0, p.size(), parts, f);
}

// The parts' extents, on every thread: each takes a run of particles, and the runs' boxes are
// merged (minima and maxima: the same in any order).
std::map<Id, PartStats> particle_parts(const model::Model& m, const ParticleNodes& node_of) {
    const std::size_t n = m.particles.size();
    const int threads = n > 65536 ? std::max(1, omp_get_max_threads()) : 1;
    std::vector<std::map<Id, PartStats>> runs(static_cast<std::size_t>(threads));
#pragma omp parallel for num_threads(threads) schedule(static, 1) if (threads > 1)
    for (int t = 0; t < threads; ++t) {
        const std::size_t from = n * static_cast<std::size_t>(t) / static_cast<std::size_t>(threads);
        const std::size_t to = n * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(threads);
        for_each_particle(m.particles, from, to, runs[static_cast<std::size_t>(t)], [&](std::size_t i, PartStats& s) {
            if (node_of[i] == RuleContext::no_node) return;
            const double x[3] = {m.nodes.x[node_of[i]], m.nodes.y[node_of[i]], m.nodes.z[node_of[i]]};
            for (int a = 0; a < 3; ++a) s.lo[a] = std::min(s.lo[a], x[a]), s.hi[a] = std::max(s.hi[a], x[a]);
        });
    }
    std::map<Id, PartStats> parts = std::move(runs[0]);
    for (std::size_t t = 1; t < runs.size(); ++t)
        for (const auto& [id, box] : runs[t]) {
            PartStats& s = parts[id];
            for (int a = 0; a < 3; ++a) s.lo[a] = std::min(s.lo[a], box.lo[a]), s.hi[a] = std::max(s.hi[a], box.hi[a]);
        }
    return parts;
}

const model::IdSet* material_node_set(const RuleContext& c, const model::FieldRecord* f) {
    if (!f || !f->valid || f->number == 0) return nullptr;
    return c.node_set(model::normalise_id(f->text));
}

// *INITIAL_VELOCITY: VX, VY, VZ on the nodes of NSID (0 = all) inside BOXID, VXE... on those of
// NSIDEX. Rotational velocities are left out (they need the rigid-body centre). With a set, only
// its members are visited: pre-processors write one set and one card per particle.
void add_initial_velocities(const RuleContext& c, const ParticleNodes& node_of, std::map<Id, PartStats>& parts) {
    const model::Model& m = c.model;
    for (const model::KeywordRecord& r : m.records) {
        if (r.schema->name != "*INITIAL_VELOCITY") continue;
        const double speed = std::hypot(material_number(r, "VX"), material_number(r, "VY"), material_number(r, "VZ"));
        const double exempt_speed =
            std::hypot(material_number(r, "VXE"), material_number(r, "VYE"), material_number(r, "VZE"));
        const model::IdSet* set = material_node_set(c, r.field("NSID"));
        if (material_number(r, "NSID") != 0 && !set) continue;  // REF008
        const model::IdSet* exempt = material_node_set(c, r.field("NSIDEX"));
        const model::Box* box =
            material_number(r, "BOXID") != 0 ? m.box(model::normalise_id(r.field("BOXID")->text)) : nullptr;
        if (speed == 0 && (!exempt || exempt_speed == 0)) continue;
        std::unordered_set<long long> exempted;
        if (exempt) exempted.insert(exempt->members.begin(), exempt->members.end());
        auto visit = [&](std::size_t i, PartStats& s) {
            if (box) {
                const std::uint32_t k = node_of[i];
                if (k == RuleContext::no_node) return;
                const auto& b = box->bounds;
                if (m.nodes.x[k] < b[0] || m.nodes.x[k] > b[1] || m.nodes.y[k] < b[2] || m.nodes.y[k] > b[3] ||
                    m.nodes.z[k] < b[4] || m.nodes.z[k] > b[5])
                    return;
            }
            const double v = exempted.count(m.particles.node[i]) ? exempt_speed : speed;
            if (v > s.speed) s.speed = v, s.speed_record = &r;
        };
        if (!set) {
            for_each_particle(m.particles, parts, visit);
            continue;
        }
        const model::IdIndex& particles = c.particle_index();
        for (long long node : set->members)
            if (const auto i = particles.find(node)) visit(*i, parts[std::to_string(m.particles.part[*i])]);
    }
}

// Gravity: a *LOAD_BODY_X/Y/Z whose *DEFINE_CURVE is constant gives g = |SF * SFO * (O + OFFO)|
// along its axis. Curves that vary, or a local system (CID), are left out.
struct Gravity {
    int axis = -1;
    double g = 0.0;
    const model::KeywordRecord* record = nullptr;
};

std::optional<double> constant_curve(const model::Model& m, double lcid) {
    for (const model::KeywordRecord& r : m.records) {
        if (r.schema->name != "*DEFINE_CURVE" || material_number(r, "LCID") != lcid) continue;
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        for (const auto& row : r.rows)
            for (const auto& f : row)
                if (f.name == "O1" && f.valid) lo = std::min(lo, f.number), hi = std::max(hi, f.number);
        if (lo > hi || lo != hi) return std::nullopt;
        return material_number(r, "SFO", 1.0) * (lo + material_number(r, "OFFO"));
    }
    return std::nullopt;
}

std::vector<Gravity> gravities(const model::Model& m) {
    std::vector<Gravity> out;
    for (const model::KeywordRecord& r : m.records) {
        const std::string_view k = r.schema->name;
        if (k.rfind("*LOAD_BODY_", 0) != 0 || k.size() != 12 || material_number(r, "CID") != 0) continue;
        const int axis = k.back() - 'X';
        if (axis < 0 || axis > 2) continue;
        std::optional<double> a = constant_curve(m, material_number(r, "LCID"));
        if (a && *a * material_number(r, "SF", 1.0) != 0)
            out.push_back({axis, std::abs(*a * material_number(r, "SF", 1.0)), &r});
    }
    return out;
}

// `x` rounded up to three significant digits, so a suggested minimum is never below the need.
double round_up(double x) {
    if (x <= 0) return x;
    const double unit = std::pow(10.0, std::floor(std::log10(x)) - 2);
    return std::ceil(x / unit * (1 - 1e-12)) * unit;
}

// SPH116: *MAT_NULL has no pressure of its own; an SPH part with it needs an EOS (§17.1).
void check_null_without_eos(RuleContext& c, const std::map<Id, PartStats>& particle_parts) {
    for (const model::Part& part : c.model.parts) {
        const model::Section* section = c.definitions().section_of(part);
        if (!particle_parts.count(part.id) && !(section && section->sph)) continue;
        const model::Material* mat = c.definitions().material_of(part);
        if (!mat || mat->keyword != "*MAT_NULL" || !part.eos.value.empty()) continue;
        c.report("SPH116", part.eos.span,
                 fmt::format("SPH part {} uses *MAT_NULL {} but EOSID is {}: the fluid has no pressure; "
                             "expected an *EOS_ id",
                             part.id, mat->id, part.eos.explicit_value ? "0" : "blank"))
            .notes.push_back({mat->span, fmt::format("*MAT_NULL {} is defined here", mat->id)});
    }
}

// SPH117: the manual asks for c0 = sqrt(GAMMA K0 / rho0) >= 10 v_max (lsdyna-sph-cards.md §18.3;
// sph-algorithms.md §10.3). Choices made here, since a deck does not state v_max:
//  - rho0 is RO of the part's material (the EOS has no density of its own; V0 = 1 is usual);
//  - v_max is the larger of the largest *INITIAL_VELOCITY speed on the part's particles and, when
//    a *LOAD_BODY_X/Y/Z with a constant curve gives g, the free-fall speed sqrt(2 g H), H being
//    the farthest the part's particles can fall along that axis within the particle cloud
//    (its far side to the cloud's opposite side; the part's own extent for a lone part). Both
//    are lower bounds of the speeds the run will reach, so the rule only fires when sure.
//  - one finding per EOS, for the part of the lowest c0 / v_max; at K0, the value to raise.
void check_murnaghan(RuleContext& c, const std::map<Id, PartStats>& parts) {
    double all_lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, all_hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (const auto& [id, s] : parts)
        for (int a = 0; a < 3; ++a) all_lo[a] = std::min(all_lo[a], s.lo[a]), all_hi[a] = std::max(all_hi[a], s.hi[a]);
    const std::vector<Gravity> gravity = gravities(c.model);
    for (const model::Eos& eos : c.model.equations_of_state) {
        if (eos.keyword != "*EOS_MURNAGHAN" || !eos.record) continue;
        const model::KeywordRecord& r = c.model.records[*eos.record];
        const double gamma = material_number(r, "GAMMA"), k0 = material_number(r, "K0");
        if (gamma <= 0 || k0 <= 0) continue;
        struct Worst {
            double ratio = HUGE_VAL, c0 = 0, v = 0, rho = 0;
            std::string why, note;
            grammar::Span source;
            const model::Part* part = nullptr;
            const model::Material* mat = nullptr;
        } worst;
        for (const model::Part& part : c.model.parts) {
            auto stats = parts.find(part.id);
            const model::Material* mat = c.definitions().material_of(part);
            if (part.eos.value != eos.id || stats == parts.end() || !mat || mat->density.value <= 0) continue;
            const PartStats& s = stats->second;
            const double c0 = std::sqrt(gamma * k0 / mat->density.value);
            double v = s.speed;
            std::string why = "the largest initial speed (*INITIAL_VELOCITY)";
            std::string note = "initial velocity given here";
            grammar::Span source = s.speed_record ? s.speed_record->span : grammar::Span{};
            for (const Gravity& g : gravity) {
                if (s.lo[g.axis] > s.hi[g.axis]) continue;  // no located particle
                const double h = std::max(s.hi[g.axis] - all_lo[g.axis], all_hi[g.axis] - s.lo[g.axis]);
                const double fall = std::sqrt(2 * g.g * h);
                if (fall <= v) continue;
                v = fall;
                why = fmt::format("the free-fall speed sqrt(2 g H) with g = {:.4g} ({}) and H = {:.4g}", g.g,
                                  g.record->keyword, h);
                note = "gravity given here";
                source = g.record->span;
            }
            if (v > 0 && c0 / v < worst.ratio)
                worst = {c0 / v, c0, v, mat->density.value, why, note, source, &part, mat};
        }
        if (!worst.part || worst.ratio >= 10.0) continue;
        const model::FieldRecord* k0_field = r.field("K0");
        auto& d = c.report(
            "SPH117", k0_field ? k0_field->span : eos.span,
            fmt::format("c0 = sqrt(GAMMA {:g} x K0 {:g} / RO {:g}) = {:.4g} for part {} is below 10 x {:.4g}, {}; "
                        "expected K0 >= {:.3g}",
                        gamma, k0, worst.rho, worst.c0, worst.part->id, worst.v, worst.why,
                        round_up(worst.rho * (10 * worst.v) * (10 * worst.v) / gamma)));
        d.notes.push_back({worst.mat->density.span, fmt::format("RO {:g} of material {}", worst.rho, worst.mat->id)});
        if (worst.source.valid()) d.notes.push_back({worst.source, worst.note});
    }
}

}  // namespace

void check_sph_materials(RuleContext& c) {
    const ParticleNodes& node_of = c.particle_nodes();
    struct PartExtents {  // the parts' extents, no speed yet: a fact of the particles alone (lint/bulk_facts.hpp)
        std::map<Id, PartStats> parts;
    };
    std::map<Id, PartStats> parts =
        c.bulk_facts().get<PartExtents>([&] { return PartExtents{particle_parts(c.model, node_of)}; })->parts;
    check_null_without_eos(c, parts);
    add_initial_velocities(c, node_of, parts);
    check_murnaghan(c, parts);
}

}  // namespace sphdeck::lint
