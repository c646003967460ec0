// RAD010-RAD016 and RAD021: SOL2SPH, solids turned into particles (radioss-format.md §5.8,
// seed radioss_sol2sph.txt, sph-algorithms.md §9).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <set>

#include "lint/rules_radioss.hpp"
#include "model/id_index.hpp"
#include "preproc/nearest_neighbours.hpp"
#include "preproc/sound_speed.hpp"

namespace sphdeck::lint::radioss {
namespace {

using model::RadiossSolidProperty;

std::vector<const RadiossSolidProperty*> sol2sph_properties(const model::RadiossFacts& f) {
    std::vector<const RadiossSolidProperty*> out;
    for (const auto& p : f.solid_properties)
        if (p.sol2sph()) out.push_back(&p);
    return out;
}

std::vector<long long> part_ids(const std::vector<const model::Part*>& parts) {
    std::vector<long long> ids;
    for (const model::Part* p : parts) ids.push_back(std::stoll(p->id));
    return ids;
}

// RAD010: SOL2SPH together with /SPHBCS or /SPH/INOUT.
void check_incompatible(RuleContext& c, const RadiossSolidProperty& p) {
    const model::RadiossFacts& f = *c.model.radioss;
    const std::string sol2sph = fmt::format("SOL2SPH (property {}, Ndir {})", p.id, p.ndir.value);
    for (const auto& s : f.symmetries)
        c.report("RAD010", s.span,
                 fmt::format("/SPHBCS {} in a deck with {}: SOL2SPH is not compatible with SPH symmetry conditions",
                             s.id, sol2sph))
            .notes.push_back({p.ndir.span, "SOL2SPH is switched on here"});
    for (const auto& io : f.inouts)
        c.report("RAD010", io.span,
                 fmt::format("/SPH/INOUT {} in a deck with {}: SOL2SPH is not compatible with inlets and outlets",
                             io.id, sol2sph))
            .notes.push_back({p.ndir.span, "SOL2SPH is switched on here"});
}

// RAD011 (Ndir outside 1-9 with an SPH part), and the SPH part itself (DK008, REF002).
void check_ndir(RuleContext& c, const RadiossSolidProperty& p) {
    if (p.sph_part.value != 0 && (p.ndir.value < 1 || p.ndir.value > 9))
        c.report("RAD011", p.ndir.span,
                 fmt::format("Ndir {} with sphpartID {}: expected 1 to 9 particles per direction{}", p.ndir.value,
                             p.sph_part.value, p.ndir.value == 0 ? " (0 creates no particle)" : ""));
    if (p.ndir.value != 0 && p.sph_part.value == 0)
        c.report("DK008", diag::Severity::Error, p.sph_part.span,
                 fmt::format("sphpartID is required with Ndir {}: the particles would belong to no part",
                             p.ndir.value));
    if (p.sph_part.value != 0 && !c.model.part(std::to_string(p.sph_part.value)))
        c.report("REF002", p.sph_part.span,
                 fmt::format("sphpartID {} names no /PART (starter error 1037)", p.sph_part.value));
}

// RAD012: SOL2SPH on 10-node tetras or 6-node pentas.
void check_elements(RuleContext& c, const RadiossSolidProperty& p, const std::vector<const model::Part*>& parts) {
    const model::RadiossFacts& f = *c.model.radioss;
    for (const model::Part* part : parts) {
        const long long id = std::stoll(part->id);
        using Kind = std::pair<const char*, const model::RadiossSolids*>;
        for (const auto& [kind, solids] : {Kind{"/TETRA10", &f.tetra10}, Kind{"/PENTA6", &f.penta6}}) {
            std::size_t count = 0, first = 0;
            for (std::size_t e = 0; e < solids->size(); ++e)
                if (solids->part[e] == id && count++ == 0) first = e;
            if (!count) continue;
            const grammar::CardLine& line = c.deck.lines[solids->line[first]];
            c.report("RAD012", grammar::Span{line.file, line.line, 1, c.deck.length(line) + 1},
                     fmt::format("part {} has {} {} element{} with SOL2SPH property {}: SOL2SPH supports 8-node "
                                 "bricks and 4-node tetras only",
                                 id, count, kind, count == 1 ? "" : "s", p.id))
                .notes.push_back({p.ndir.span, "SOL2SPH is switched on here"});
        }
    }
}

// RAD013: Isolid 1, 2 or 24 and Iframe 1 or 2; 0 takes /DEF_SOLID, else 1.
void check_formulation(RuleContext& c, const RadiossSolidProperty& p) {
    const model::RadiossFacts& f = *c.model.radioss;
    const long long isolid = p.isolid.value != 0 ? p.isolid.value : f.def_isolid != 0 ? f.def_isolid : 1;
    const long long iframe = p.iframe.value != 0 ? p.iframe.value : f.def_iframe != 0 ? f.def_iframe : 1;
    const std::string from_default = "(0 takes /DEF_SOLID)";
    if (isolid != 1 && isolid != 2 && isolid != 24)
        c.report("RAD013", p.isolid.span,
                 fmt::format("Isolid {}{} with SOL2SPH: expected 1, 2 or 24", isolid,
                             p.isolid.value == 0 ? " " + from_default : ""));
    if (iframe != 1 && iframe != 2)
        c.report("RAD013", p.iframe.span,
                 fmt::format("Iframe {}{} with SOL2SPH: expected 1 or 2", iframe,
                             p.iframe.value == 0 ? " " + from_default : ""));
}

// RAD014: laws 2, 3, 4, 6, 21, 24, 36, 81, the same for the solid and its particles.
void check_materials(RuleContext& c, const RadiossSolidProperty& p, const std::vector<const model::Part*>& parts) {
    static const std::set<int> supported{2, 3, 4, 6, 21, 24, 36, 81};
    const model::Part* sph = c.model.part(std::to_string(p.sph_part.value));
    const model::RadiossMaterial* sph_mat = sph ? material_of(c.model, p.sph_part.value) : nullptr;
    if (sph_mat && sph_mat->law >= 0 && !supported.count(sph_mat->law))
        c.report("RAD014", sph->material.span,
                 fmt::format("SOL2SPH particle part {} uses material law {}: expected 2, 3, 4, 6, 21, 24, 36 or 81",
                             p.sph_part.value, sph_mat->law))
            .notes.push_back({sph_mat->law_span, fmt::format("{} here", sph_mat->keyword)});
    for (const model::Part* part : parts) {
        const model::RadiossMaterial* mat = material_of(c.model, std::stoll(part->id));
        if (!mat || mat->law < 0) continue;
        if (!supported.count(mat->law)) {
            c.report("RAD014", part->material.span,
                     fmt::format("SOL2SPH solid part {} uses material law {}: expected 2, 3, 4, 6, 21, 24, 36 or 81",
                                 part->id, mat->law));
        } else if (sph_mat && supported.count(sph_mat->law) && sph_mat->law != mat->law) {
            c.report("RAD014", sph->material.span,
                     fmt::format("SOL2SPH particle part {} uses law {} but its solid part {} uses law {}: both must "
                                 "be the same law (starter error 1911)",
                                 p.sph_part.value, sph_mat->law, part->id, mat->law))
                .notes.push_back({part->material.span, fmt::format("part {} material here", part->id)});
        }
    }
}

// Median nearest-neighbour distance of a part's particles: its pitch.
double particle_pitch(const model::Model& m, const Positions& at, long long part) {
    std::vector<double> x, y, z;
    for (std::size_t i = 0; i < m.particles.size(); ++i)
        if (m.particles.part[i] == part && at.located[i])
            x.push_back(at.at[i][0]), y.push_back(at.at[i][1]), z.push_back(at.at[i][2]);
    if (x.size() < 2) return 0;
    return median(preproc::nearest_neighbours_grid(x, y, z).distance);
}

// RAD015 and RAD016: pitch of each SOL2SPH property (element size / Ndir) against the genuine
// SPH parts, and its SPH property's h against 1.25-1.5 times that pitch.
void check_pitch(RuleContext& c, const std::vector<const RadiossSolidProperty*>& props) {
    struct Pitch {
        const RadiossSolidProperty* prop;
        double size, pitch;
    };
    std::vector<Pitch> sol2sph;
    for (const RadiossSolidProperty* p : props) {
        if (p->ndir.value < 1 || p->ndir.value > 9) continue;
        const double size = median(element_sizes(c.model, part_ids(parts_using(c.model, p->id))));
        if (size > 0) sol2sph.push_back({p, size, size / static_cast<double>(p->ndir.value)});
    }
    if (sol2sph.empty()) return;
    const Positions at = particle_positions(c.model);
    std::vector<std::pair<long long, double>> genuine;  // SPH parts with /SPHCEL particles
    for (long long part : std::set<long long>(c.model.particles.part.begin(), c.model.particles.part.end()))
        if (double pitch = particle_pitch(c.model, at, part); pitch > 0) genuine.emplace_back(part, pitch);
    for (const Pitch& s : sol2sph) {
        const std::string own =
            fmt::format("SOL2SPH property {} gives a pitch of {:.4g} (element size {:.4g} / Ndir {})", s.prop->id,
                        s.pitch, s.size, s.prop->ndir.value);
        if (!genuine.empty()) {
            for (const auto& [part, pitch] : genuine) {
                if (std::max(pitch, s.pitch) / std::min(pitch, s.pitch) <= 1.2) continue;
                c.report("RAD015", s.prop->ndir.span,
                         fmt::format("{}, but SPH part {} has a pitch of {:.4g}: all SPH and SOL2SPH parts should "
                                     "share one pitch",
                                     own, part, pitch));
                break;
            }
        } else if (&s != &sol2sph.front()) {
            const Pitch& ref = sol2sph.front();
            if (std::max(ref.pitch, s.pitch) / std::min(ref.pitch, s.pitch) > 1.2)
                c.report("RAD015", s.prop->ndir.span,
                         fmt::format("{}, but SOL2SPH property {} gives {:.4g}: all SOL2SPH parts should share one "
                                     "pitch",
                                     own, ref.prop->id, ref.pitch));
        }
        // RAD016: the particles' smoothing length.
        const model::RadiossSphProperty* sph = sph_property_of(c.model, s.prop->sph_part.value);
        if (!sph || sph->h_1d.value == 3) continue;  // h_1D 3 derives h from the particle distance
        const double h = sph->h.value;
        if (h <= 0)
            c.report(
                "RAD016", sph->h.span,
                fmt::format("h 0 on the SPH property {} of SOL2SPH particles: give h (about {:.4g}-{:.4g}, 1.25-1.5 "
                            "times the pitch {:.4g}) or h_1D 3",
                            sph->id, 1.25 * s.pitch, 1.5 * s.pitch, s.pitch));
        else if (h < 1.0 * s.pitch || h > 2.0 * s.pitch)
            c.report("RAD016", sph->h.span,
                     fmt::format("h {:.4g} is {:.3g} times the SOL2SPH pitch {:.4g}; expected about 1.25-1.5 times "
                                 "({:.4g}-{:.4g})",
                                 h, h / s.pitch, s.pitch, 1.25 * s.pitch, 1.5 * s.pitch));
    }
}

// Sound speed of a solid's material: elastic laws from E and nu, hydrodynamic ones from C1.
double solid_sound_speed(const model::RadiossFacts& f, const model::RadiossMaterial& m) {
    if (!(m.density > 0)) return 0;
    double bulk = m.bulk;
    if (const model::RadiossEos* e = f.eos_of(m.id)) bulk = e->c[1];
    const double shear = m.young > 0 && m.poisson > -1 ? m.young / (2 * (1 + m.poisson)) : 0;
    if (bulk > 0) return std::sqrt((bulk + 4.0 * shear / 3.0) / m.density);
    return preproc::elastic_sound_speed(m.young, m.poisson, m.density);
}

// The stable step of one element: characteristic length V / A_max (bricks) or 3V / A_max
// (tetras), over the sound speed.
double element_length(const model::Model& m, const model::IdIndex& nodes, const model::RadiossSolids& s,
                      std::size_t e) {
    using V3 = std::array<double, 3>;
    auto point = [&](int k, V3& out) {
        auto n = nodes.find(s.nodes[e * s.nodes_per_element + k]);
        if (!n) return false;
        out = {m.nodes.x[*n], m.nodes.y[*n], m.nodes.z[*n]};
        return true;
    };
    auto sub = [](const V3& a, const V3& b) { return V3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    auto cross = [](const V3& a, const V3& b) {
        return V3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    auto dot = [](const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    auto length = [&](const V3& a) { return std::sqrt(dot(a, a)); };
    const int n = s.nodes_per_element == 8 ? 8 : 4;
    V3 p[8];
    for (int k = 0; k < n; ++k)
        if (!point(k, p[k])) return 0;
    if (n == 4) {
        const double volume = std::abs(dot(sub(p[1], p[0]), cross(sub(p[2], p[0]), sub(p[3], p[0])))) / 6;
        static const int faces[4][3] = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}};
        double area = 0;
        for (const auto& f : faces)
            area = std::max(area, length(cross(sub(p[f[1]], p[f[0]]), sub(p[f[2]], p[f[0]]))) / 2);
        return area > 0 ? 3 * volume / area : 0;
    }
    // Hexahedron: volume from six tetrahedra around the diagonal 1-7, faces by their diagonals.
    static const int tets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
    double volume = 0;
    for (const auto& t : tets)
        volume += std::abs(dot(sub(p[t[1]], p[t[0]]), cross(sub(p[t[2]], p[t[0]]), sub(p[t[3]], p[t[0]])))) / 6;
    static const int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    double area = 0;
    for (const auto& f : faces) area = std::max(area, length(cross(sub(p[f[2]], p[f[0]]), sub(p[f[3]], p[f[1]]))) / 2);
    return area > 0 ? volume / area : 0;
}

// RAD021: /DT/BRICK/DEL DTmin about 20-30 % below the natural step of the SOL2SPH solids.
void check_brick_deletion(RuleContext& c, const std::vector<const RadiossSolidProperty*>& props) {
    const model::RadiossFacts& f = *c.model.radioss;
    const model::RadiossDt* del = nullptr;
    for (const auto& d : f.time_steps)
        if (d.kind == model::DtKind::Brick && d.keyword3 == "DEL" && !d.in_starter) del = &d;
    if (!del || props.empty()) return;
    const model::IdIndex& nodes = c.node_index();
    double step = 0;
    for (const RadiossSolidProperty* p : props)
        for (const model::Part* part : parts_using(c.model, p->id)) {
            const long long id = std::stoll(part->id);
            const model::RadiossMaterial* mat = material_of(c.model, id);
            const double speed = mat ? solid_sound_speed(f, *mat) : 0;
            if (!(speed > 0)) continue;
            for (const model::RadiossSolids* s : {&f.bricks, &f.tetra4})
                for (std::size_t e = 0; e < s->size(); ++e) {
                    if (s->part[e] != id) continue;
                    const double l = element_length(c.model, nodes, *s, e);
                    if (l > 0 && (step == 0 || l / speed < step)) step = l / speed;
                }
        }
    if (!(step > 0)) return;
    const double scale = del->dtsca.value > 0 ? del->dtsca.value : 0.9;
    const double natural = scale * step;
    const double ratio = del->dtmin.value / natural;
    if (ratio >= 0.65 && ratio <= 0.85) return;
    c.report("RAD021", del->dtmin.explicit_value ? del->dtmin.span : del->span,
             fmt::format("/DT/BRICK/DEL DTmin {:.4g} is {:.0f} % of the natural SOL2SPH brick step {:.4g} (DTsca {:g} "
                         "x l/c); expected about 20-30 % below it ({:.4g}-{:.4g})",
                         del->dtmin.value, 100 * ratio, natural, scale, 0.7 * natural, 0.8 * natural));
}

}  // namespace

void check_sol2sph(RuleContext& c) {
    const auto props = sol2sph_properties(*c.model.radioss);
    for (const auto& p : c.model.radioss->solid_properties) check_ndir(c, p);
    if (!props.empty()) check_incompatible(c, *props.front());
    for (const RadiossSolidProperty* p : props) {
        const auto parts = parts_using(c.model, p->id);
        check_elements(c, *p, parts);
        check_formulation(c, *p);
        check_materials(c, *p, parts);
    }
    check_pitch(c, props);
    check_brick_deletion(c, props);
}

}  // namespace sphdeck::lint::radioss
