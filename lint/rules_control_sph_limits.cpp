// SPH070-SPH073 and SPH080: the limits of *CONTROL_SPH that deactivate particles or stop SPH:
// the BOXID box, the MAXV velocity limit, and the DT / START times against ENDTIM.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "grammar/fields.hpp"
#include "grammar/value.hpp"
#include "lint/rules_control_sph.hpp"
#include "model/id_index.hpp"

namespace sphdeck::lint::control_sph {
namespace {

using diag::Severity;

constexpr std::size_t max_listed = 5;  // ids named in one message

std::string list_ids(const std::vector<long long>& ids, std::size_t total) {
    std::string s;
    for (std::size_t i = 0; i < ids.size(); ++i) s += (i ? ", " : "") + std::to_string(ids[i]);
    if (total > ids.size()) s += ", ...";
    return s;
}

// SPH070, SPH071: the box must exist, and particles outside it at t = 0 are deactivated at once.
void check_box(RuleContext& c) {
    const model::ControlSph& sph = c.model.controls.sph;
    if (sph.boxid.value == 0) return;
    const model::Box* box = c.model.box(std::to_string(sph.boxid.value));
    if (!box) {
        c.report("SPH070", sph.boxid.span,
                 fmt::format("BOXID {} names no *DEFINE_BOX or *DEFINE_BOX_SPH; expected a defined box or 0",
                             sph.boxid.value));
        return;
    }
    const ParticleNodes& node_of = c.particle_nodes();
    const model::Nodes& n = c.model.nodes;
    const auto& b = box->bounds;
    // In 2D (IDIM 2, -2) particles live in the x-y plane: z does not decide.
    const bool planar = model::is_two_dimensional(sph.idim.value);
    std::size_t outside = 0;
    std::vector<long long> first;
    for (std::size_t i = 0; i < c.model.particles.size(); ++i) {
        const std::uint32_t k = node_of[i];
        if (k == RuleContext::no_node) continue;  // REF001
        const double x = n.x[k], y = n.y[k], z = n.z[k];
        if (x >= b[0] && x <= b[1] && y >= b[2] && y <= b[3] && (planar || (z >= b[4] && z <= b[5]))) continue;
        if (++outside <= max_listed) first.push_back(c.model.particles.node[i]);
    }
    if (outside == 0) return;
    c.report("SPH071", sph.boxid.span,
             fmt::format("{} particle{} start outside box {} and are deactivated at once ({}); expected every "
                         "particle inside",
                         outside, outside > 1 ? "s" : "", box->id, list_ids(first, outside)))
        .notes.push_back({box->span, fmt::format("box {} is defined here", box->id)});
}

struct Speed {
    double value = 0.0;
    grammar::Span span;
};

// The largest initial speed given to a particle by *INITIAL_VELOCITY (node set NSID, 0 = all
// nodes) or *INITIAL_VELOCITY_NODE (not in the schema: NID VX VY VZ per line, read raw).
Speed largest_initial_speed(const RuleContext& c) {
    Speed best;
    const model::Model& m = c.model;
    if (m.particles.size() == 0) return best;
    auto consider = [&](double vx, double vy, double vz, grammar::Span span) {
        const double v = std::sqrt(vx * vx + vy * vy + vz * vz);
        if (v > best.value) best = {v, span};
    };
    for (const model::KeywordRecord& r : m.records) {
        if (r.schema->name != "*INITIAL_VELOCITY") continue;
        const model::FieldRecord* nsid = r.field("NSID");
        if (nsid && nsid->explicit_value && nsid->valid && nsid->number != 0) {
            const model::IdSet* set = c.node_set(model::normalise_id(nsid->text));
            // The particle index only when a set asks: 4 bytes a particle, kept to the end of the rules.
            if (!set || std::none_of(set->members.begin(), set->members.end(),
                                     [&](long long node) { return c.particle_index().find(node).has_value(); }))
                continue;
        }
        auto value = [&](std::string_view name) {
            const model::FieldRecord* f = r.field(name);
            return f && f->valid ? f->number : 0.0;
        };
        const model::FieldRecord* vx = r.field("VX");
        consider(value("VX"), value("VY"), value("VZ"), vx ? vx->span : r.span);
    }
    std::vector<grammar::Field> fields;
    for (const grammar::Block& b : c.deck.blocks) {
        if (b.keyword != "*INITIAL_VELOCITY_NODE") continue;
        const std::uint32_t w = b.format == grammar::CardFormat::Long ? 20 : 10;
        const grammar::FixedField layout[] = {{0, w}, {w, w}, {2 * w, w}, {3 * w, w}};
        for (grammar::CardLinePtr l = c.deck.begin_lines(b); l != c.deck.end_lines(b); ++l) {
            grammar::cut_fields(c.deck.text(*l), *l, layout, 8 * w, fields);
            grammar::IntegerValue nid = grammar::parse_integer(fields[0].text);
            if (nid.status != grammar::NumberStatus::Ok || !c.particle_index().find(nid.value)) continue;
            double v[3] = {};
            for (int k = 0; k < 3; ++k) {
                grammar::RealValue r = grammar::parse_real(fields[k + 1].text);
                if (r.status == grammar::NumberStatus::Ok) v[k] = r.value;
            }
            consider(v[0], v[1], v[2], fields[1].span);
        }
    }
    return best;
}

// SPH072, SPH073: MAXV. The sources disagree on MAXV <= 0 (lsdyna-sph-cards.md §1 card 1 and §24):
// the seed manual page says a negative MAXV switches the check off; the newer text carried by
// pydyna reads 0 as "no check" and a negative value as a limit at |MAXV|; old LS-PrePost wrote 0
// meaning the default. So only MAXV > 0 is taken as a limit here, a negative value is reported
// (SPH073, naming both readings), and 0 is left alone: under both newer readings it is harmless.
void check_maxv(RuleContext& c) {
    const auto& maxv = c.model.controls.sph.maxv;
    if (maxv.explicit_value && maxv.value < 0.0) {
        c.report("SPH073", maxv.span,
                 fmt::format("MAXV {} switches the velocity check off (newer editions read it as a limit at {}); "
                             "expected a positive limit or blank",
                             number(maxv.value), number(-maxv.value)));
        return;
    }
    if (maxv.value <= 0.0) return;
    const Speed fastest = largest_initial_speed(c);
    if (fastest.value > maxv.value)
        c.report("SPH072", maxv.span,
                 fmt::format("initial speed {} exceeds MAXV {}: those particles are deactivated at once; expected "
                             "MAXV above every speed",
                             number(fastest.value), number(maxv.value)))
            .notes.push_back({fastest.span, "initial velocity given here"});
}

// SPH080: SPH is computed from START until DT; both against ENDTIM of *CONTROL_TERMINATION.
void check_times(RuleContext& c) {
    const model::ControlSph& sph = c.model.controls.sph;
    const auto& end = c.model.controls.endtim;
    if (sph.dt.value <= sph.start.value) {
        c.report("SPH080", Severity::Error, sph.dt.span,
                 fmt::format("DT {} is not after START {}: SPH is never computed; expected DT > START",
                             number(sph.dt.value), number(sph.start.value)))
            .notes.push_back({sph.start.span, "START is set here"});
    } else if (end.value > 0.0 && sph.start.value >= end.value) {
        c.report("SPH080", Severity::Warning, sph.start.span,
                 fmt::format("START {} is not before ENDTIM {}: SPH starts after the run ends; expected START < ENDTIM",
                             number(sph.start.value), number(end.value)))
            .notes.push_back({end.span, "ENDTIM is set here"});
    } else if (end.value > 0.0 && sph.dt.value < end.value) {
        c.report("SPH080", Severity::Info, sph.dt.span,
                 fmt::format("DT {} stops SPH before ENDTIM {}; expected DT >= ENDTIM unless SPH must stop early",
                             number(sph.dt.value), number(end.value)))
            .notes.push_back({end.span, "ENDTIM is set here"});
    }
}

}  // namespace

void check_limits(RuleContext& c) {
    check_box(c);
    check_maxv(c);
    check_times(c);
}

}  // namespace sphdeck::lint::control_sph
