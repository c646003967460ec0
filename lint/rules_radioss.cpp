// RAD rules (OpenRadioss SPH options): the family's entry point, its shared helpers, and the
// /SPHBCS symmetry-plane rules RAD002-RAD008 (radioss-format.md §5.3, sph-algorithms.md §8).
#include "lint/rules_radioss.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <unordered_set>

#include "grammar/radioss/cards.hpp"
#include "lint/rules.hpp"
#include "model/id_index.hpp"
#include "model/radioss_card_decoder.hpp"

namespace sphdeck::lint {
namespace radioss {

std::string Group::ids(const model::Particles& p) const {
    std::string s;
    for (std::size_t k = 0; k < first.size(); ++k) s += (k ? ", " : "") + std::to_string(p.node[first[k]]);
    return count > first.size() ? s + ", ..." : s;
}

Positions particle_positions(const model::Model& m) {
    Positions out;
    const model::IdIndex nodes(m.nodes.id);
    out.at.resize(m.particles.size());
    out.located.assign(m.particles.size(), 0);
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        if (auto k = nodes.find(m.particles.node[i])) {
            out.at[i] = {m.nodes.x[*k], m.nodes.y[*k], m.nodes.z[*k]};
            out.located[i] = 1;
        }
    }
    return out;
}

const model::RadiossSphProperty* sph_property_of(const model::Model& m, long long part) {
    const model::Part* p = m.part(std::to_string(part));
    if (!p || p->section.value.empty()) return nullptr;
    for (const auto& prop : m.radioss->sph_properties)
        if (std::to_string(prop.id) == p->section.value) return &prop;
    return nullptr;
}

const model::RadiossMaterial* material_of(const model::Model& m, long long part) {
    const model::Part* p = m.part(std::to_string(part));
    if (!p || p->material.value.empty()) return nullptr;
    for (const auto& mat : m.radioss->materials)
        if (std::to_string(mat.id) == p->material.value) return &mat;
    return nullptr;
}

double reference_h(const model::Model& m, long long part) {
    const model::RadiossSphProperty* prop = sph_property_of(m, part);
    if (!prop) return 0;
    if (prop->h.value > 0) return prop->h.value;
    const model::RadiossMaterial* mat = material_of(m, part);
    if (!mat || !(mat->density > 0)) return 0;
    return std::cbrt(std::sqrt(2.0) * prop->mp.value / mat->density);
}

std::vector<const model::Part*> parts_using(const model::Model& m, long long property) {
    std::vector<const model::Part*> out;
    const std::string id = std::to_string(property);
    for (const model::Part& p : m.parts)
        if (p.section.value == id) out.push_back(&p);
    return out;
}

std::vector<double> element_sizes(const model::Model& m, const std::vector<long long>& parts) {
    const model::IdIndex nodes(m.nodes.id);
    const std::unordered_set<long long> wanted(parts.begin(), parts.end());
    std::vector<double> sizes;
    // Edges of a brick (corners 1-8: bottom 1-4, top 5-8) and of a tetra.
    static const int brick_edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                           {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    static const int tetra_edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
    auto measure = [&](const model::RadiossSolids& s, const int(*edges)[2], int count) {
        for (std::size_t e = 0; e < s.size(); ++e) {
            if (!wanted.count(s.part[e])) continue;
            double total = 0;
            int used = 0;
            for (int k = 0; k < count; ++k) {
                auto a = nodes.find(s.nodes[e * s.nodes_per_element + edges[k][0]]);
                auto b = nodes.find(s.nodes[e * s.nodes_per_element + edges[k][1]]);
                if (!a || !b) continue;
                const double d = std::hypot(m.nodes.x[*a] - m.nodes.x[*b], m.nodes.y[*a] - m.nodes.y[*b],
                                            m.nodes.z[*a] - m.nodes.z[*b]);
                if (d > 0) total += d, ++used;  // degenerate bricks repeat nodes: skip their zero edges
            }
            if (used > 0) sizes.push_back(total / used);
        }
    };
    measure(m.radioss->bricks, brick_edges, 12);
    measure(m.radioss->tetra4, tetra_edges, 6);
    return sizes;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + mid, v.end());
    return v[mid];
}

grammar::Span cell_field_span(const RuleContext& c, std::size_t particle, std::string_view field) {
    const grammar::radioss::KeywordSpec* spec = grammar::radioss::find_keyword("/SPHCEL");
    const grammar::Span whole = c.particle_span(particle);
    if (!spec) return whole;
    const grammar::radioss::CardSpec& card = spec->format_for(c.model.radioss->version).cards.front();
    return model::radioss_field_span(c.deck, c.model.particles.line[particle], card, c.model.radioss->version,
                                     card.index(field));
}

namespace {

using model::RadiossSymmetry;

const char* axis_name(int axis) { return axis == 0 ? "X" : axis == 1 ? "Y" : "Z"; }

// RAD002-RAD005: what the starter checks (398, 399, 400) and what it does not (Dir, moving frame).
void check_cards(RuleContext& c, const RadiossSymmetry& s) {
    const model::RadiossFacts& f = *c.model.radioss;
    if (s.kind == model::SymmetryKind::Invalid)
        c.report("RAD002", s.type_span,
                 fmt::format("/SPHBCS type '{}' is neither SLIDE nor TIED (starter error 398)", s.type_text));
    if (s.ilev.value != 0 && s.ilev.value != 1)
        c.report("RAD003", s.ilev.span,
                 fmt::format("Ilev {} is neither 0 nor 1 (starter error 399: bad formulation level)", s.ilev.value));
    if (s.frame_id.value != 0) {
        const model::RadiossFrame* frame = f.frame(s.frame_id.value);
        if (!frame) {
            auto& d = c.report("RAD004", diag::Severity::Error, s.frame_id.span,
                               fmt::format("frame_ID {} names no /FRAME (starter error 400)", s.frame_id.value));
            if (const model::RadiossFrame* skew = f.frame(s.frame_id.value, true))
                d.notes.push_back({skew->span, fmt::format("{} is a skew; /SPHBCS needs a /FRAME", skew->keyword)});
        } else if (frame->moving) {
            c.report("RAD004", diag::Severity::Warning, s.frame_id.span,
                     fmt::format("frame_ID {} is a moving frame ({}): the symmetry plane and its kinematic condition "
                                 "need a fixed frame (/FRAME/FIX)",
                                 s.frame_id.value, frame->keyword))
                .notes.push_back({frame->span, "the frame is defined here"});
        }
    }
    if (s.grnod_id.value != 0) {
        bool known = false;
        for (const auto& g : f.node_groups) known |= g.id == s.grnod_id.value;
        if (!known)
            c.report("REF008", s.grnod_id.span,
                     fmt::format("node group {} is not defined (/SPHBCS {} grnod_ID)", s.grnod_id.value, s.id));
    }
    if (s.axis < 0)
        c.report("RAD005", s.dir.span,
                 fmt::format("Dir '{}' is not X, Y or Z: the starter accepts it and leaves the plane's normal "
                             "undefined",
                             s.dir.value));
}

// Particles on each plane (|dd| < 1e-3 h_ref, as the starter counts them for the mass split) and
// behind it (dd < -1e-3 h_ref).
struct PlaneScan {
    std::vector<std::uint8_t> on;  // per particle
    radioss::Group behind, on_plane;
    double worst = 0;  // the most negative dd
};

PlaneScan scan(const model::Model& m, const model::SymmetryPlane& plane, const Positions& at,
               const std::vector<double>& tolerance) {
    PlaneScan out;
    out.on.assign(m.particles.size(), 0);
    const std::array<double, 3> n{plane.head[0] - plane.tail[0], plane.head[1] - plane.tail[1],
                                  plane.head[2] - plane.tail[2]};
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        if (!at.located[i]) continue;
        double dd = 0;
        for (int k = 0; k < 3; ++k) dd += (at.at[i][k] - plane.tail[k]) * n[k];
        if (std::abs(dd) < tolerance[i]) {
            out.on[i] = 1;
            out.on_plane.add(i);
        } else if (dd < 0) {
            out.behind.add(i);
            out.worst = std::min(out.worst, dd);
        }
    }
    return out;
}

std::string plane_text(const RadiossSymmetry& s) {
    if (s.frame_id.value == 0) return fmt::format("{} = 0", s.axis == 0 ? "x" : s.axis == 1 ? "y" : "z");
    return fmt::format("through frame {}, normal {}'", s.frame_id.value, axis_name(s.axis));
}

// RAD006 (Ilev 1 without the kinematic condition), RAD008 (wrong side), and the counts RAD007 needs.
void check_geometry(RuleContext& c, const Positions& at, const std::vector<double>& tolerance,
                    std::vector<std::uint8_t>& planes_of) {
    const model::RadiossFacts& f = *c.model.radioss;
    const model::Particles& p = c.model.particles;
    for (const RadiossSymmetry& s : f.symmetries) {
        if (!s.plane) continue;
        const PlaneScan r = scan(c.model, c.model.symmetry_planes[*s.plane], at, tolerance);
        for (std::size_t i = 0; i < p.size(); ++i) planes_of[i] = static_cast<std::uint8_t>(planes_of[i] + r.on[i]);
        if (r.behind.count) {
            const std::size_t i = r.behind.first.front();
            c.report("RAD008", c.particle_span(i),
                     fmt::format("{} particle{} start{} behind the /SPHBCS {} plane ({}): {}; the deepest is {:.4g} "
                                 "on the wrong side; expected every particle on the side the normal points to",
                                 r.behind.count, r.behind.count == 1 ? "" : "s", r.behind.count == 1 ? "s" : "", s.id,
                                 plane_text(s), r.behind.ids(p), -r.worst))
                .notes.push_back({s.span, "the symmetry plane is defined here"});
        }
        if (s.ilev.value != 1 || !r.on_plane.count) continue;
        const model::IdSet* group = nullptr;
        if (s.grnod_id.value != 0) {
            group = c.node_set(std::to_string(s.grnod_id.value));
            if (!group) continue;  // undefined (REF008), or a group kind sphdeck does not expand
        }
        std::unordered_set<long long> members;
        if (group) members.insert(group->members.begin(), group->members.end());
        radioss::Group missing;
        for (std::size_t i = 0; i < p.size(); ++i)
            if (r.on[i] && !members.count(p.node[i])) missing.add(i);
        if (!missing.count) continue;
        const grammar::Span where = s.grnod_id.value != 0 ? s.grnod_id.span : s.ilev.span;
        auto& d =
            c.report("RAD006", where,
                     fmt::format("Ilev 1 on /SPHBCS {}: {} particle{} on the plane at time 0 carr{} no kinematic "
                                 "condition ({}): {}",
                                 s.id, missing.count, missing.count == 1 ? "" : "s", missing.count == 1 ? "ies" : "y",
                                 s.grnod_id.value == 0 ? "grnod_ID is 0"
                                                       : fmt::format("not in node group {}", s.grnod_id.value),
                                 missing.ids(p)));
        if (s.grnod_id.value != 0) d.notes.push_back({s.ilev.span, "Ilev 1 here"});
    }
}

// RAD007: particles on more than two planes.
void check_corners(RuleContext& c, const std::vector<std::uint8_t>& planes_of) {
    const model::Particles& p = c.model.particles;
    radioss::Group many;
    std::uint8_t most = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (planes_of[i] > 2) many.add(i), most = std::max(most, planes_of[i]);
    if (!many.count) return;
    const std::size_t i = many.first.front();
    auto& d =
        c.report("RAD007", c.particle_span(i),
                 fmt::format("{} particle{} lie{} on {} symmetry planes at time 0: {}; the starter gives such a "
                             "particle m/(1 + n) of its mass, and mass and energy output will be off",
                             many.count, many.count == 1 ? "" : "s", many.count == 1 ? "s" : "", most, many.ids(p)));
    for (const RadiossSymmetry& s : c.model.radioss->symmetries)
        if (s.plane) d.notes.push_back({s.span, fmt::format("symmetry plane {}", s.id)});
}

}  // namespace

void check_symmetry(RuleContext& c) {
    const model::RadiossFacts& f = *c.model.radioss;
    for (const RadiossSymmetry& s : f.symmetries) check_cards(c, s);
    if (c.model.symmetry_planes.empty() || c.model.particles.size() == 0) return;
    const Positions at = particle_positions(c.model);
    // "On the plane" below 1e-3 h_ref (inspcnd.F); without h_ref, 1e-9 of the model's extent.
    double extent = 0;
    for (std::size_t i = 0; i < at.at.size(); ++i)
        if (at.located[i])
            for (double x : at.at[i]) extent = std::max(extent, std::abs(x));
    std::vector<double> tolerance(c.model.particles.size());
    long long last = 0;
    double h = 0;
    for (std::size_t i = 0; i < tolerance.size(); ++i) {
        if (i == 0 || c.model.particles.part[i] != last)
            last = c.model.particles.part[i], h = reference_h(c.model, last);
        tolerance[i] = h > 0 ? 1e-3 * h : std::max(1e-9 * extent, 1e-12);
    }
    std::vector<std::uint8_t> planes_of(c.model.particles.size(), 0);
    check_geometry(c, at, tolerance, planes_of);
    check_corners(c, planes_of);
}

}  // namespace radioss

void check_radioss(RuleContext& c) {
    if (!c.model.radioss) return;
    radioss::check_symmetry(c);
    radioss::check_sol2sph(c);
    radioss::check_properties(c);
    radioss::check_sph_references(c);
    radioss::check_generated_references(c);
    radioss::check_starter_values(c);
    radioss::check_time_history_selections(c);
}

}  // namespace sphdeck::lint
