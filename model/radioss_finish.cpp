// RadiossBuilder::finish: what needs the whole deck. Particle masses (the property mp applies to
// Type-0 cells without a mass), frame axes, symmetry planes, /GRNOD/PART members, part → EOS
// links and the time-step scale.
#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "model/id_index.hpp"
#include "model/radioss_builder.hpp"

namespace sphdeck::model {

namespace {

using Vec = std::array<double, 3>;

Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
bool normalise(Vec& a) {
    const double n = norm(a);
    if (!(n > 0)) return false;
    for (double& c : a) c /= n;
    return true;
}

// Moving systems: the Dir axis e_k along N1N2, e_k+2 = e_k x N1N3, e_k+1 = e_k+2 x e_k (indices
// mod 3; hm_read_frm.F and hm_read_skw.F, "calculation of z'" and "of y'" per IDIR).
bool from_nodes(RadiossFrame& f, const Vec& n1n2, const Vec& n1n3) {
    const int k = f.dir, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    Vec along = n1n2;
    if (!normalise(along)) return false;
    Vec third = cross(along, n1n3);
    if (!normalise(third)) return false;
    f.axes[k] = along;
    f.axes[k2] = third;
    f.axes[k1] = cross(third, along);
    return true;
}

// Fixed systems: the deck gives Y' and Z'; X' = Y' x Z', then Y' = Z' x X' (hm_read_frm.F and
// hm_read_skw.F, "calculation of x'" and "of y'"), each normalised; Z' keeps its direction.
bool from_y_and_z(RadiossFrame& f) {
    Vec z = f.axes[2];
    Vec x = cross(f.axes[1], z);
    if (!normalise(x) || !normalise(z)) return false;
    f.axes = {x, cross(z, x), z};
    return true;
}

}  // namespace

// The mass the starter gives each particle (radioss-format.md §5.2, sph-algorithms.md §4):
// Type 1 (or Type 0 with MASS > 0) its MASS, Type 2 its volume (flagged), else the property mp.
void RadiossBuilder::resolve_particles() {
    std::unordered_map<long long, const RadiossSphProperty*> property_of_part;
    for (const Part& part : model_.parts) {
        const long long pid = std::stoll(part.id);
        const RadiossSphProperty* prop = nullptr;
        if (!part.section.value.empty())
            for (const auto& p : facts_.sph_properties)
                if (std::to_string(p.id) == part.section.value) prop = &p;
        property_of_part[pid] = prop;
    }
    Particles& p = model_.particles;
    RadiossCells& cells = facts_.cells;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const int type = cells.type[i];
        const double written = cells.mass[i];
        if (type == 1) {
            p.mass[i] = std::max(written, 0.0);
        } else if (type == 2) {
            p.mass[i] = std::max(written, 0.0);
            p.volume[i] = 1;
        } else if (written > 0) {
            p.mass[i] = written;  // Type 0 with a mass: treated as Type 1
        } else {
            auto it = property_of_part.find(p.part[i]);
            p.mass[i] = it != property_of_part.end() && it->second ? it->second->mp.value : 1.0;
            cells.from_property[i] = 1;
        }
    }
}

void RadiossBuilder::resolve_frames() {
    const IdIndex nodes(model_.nodes.id);
    for (RadiossFrame& f : facts_.frames) {
        if (!f.moving) {
            f.geometry = from_y_and_z(f);
            continue;
        }
        if (f.nodes[0] == 0) continue;
        Vec at[3];
        bool found = true;
        for (int k = 0; k < 3; ++k) {
            auto n = nodes.find(f.nodes[k]);
            if (!n) {
                found = false;
                break;
            }
            at[k] = {model_.nodes.x[*n], model_.nodes.y[*n], model_.nodes.z[*n]};
        }
        if (!found) continue;
        f.origin = at[0];
        const Vec n1n2{at[1][0] - at[0][0], at[1][1] - at[0][1], at[1][2] - at[0][2]};
        const Vec n1n3{at[2][0] - at[0][0], at[2][1] - at[0][1], at[2][2] - at[0][2]};
        f.geometry = from_nodes(f, n1n2, n1n3);
    }
}

// A plane through the frame origin with the chosen local axis as normal (§5.3). Frame 0 is the
// global system; an unknown or unresolved frame leaves the plane unknown.
void RadiossBuilder::resolve_planes() {
    for (RadiossSymmetry& s : facts_.symmetries) {
        if (s.axis < 0) continue;
        Vec origin{0, 0, 0}, normal{0, 0, 0};
        normal[s.axis] = 1;
        if (s.frame_id.value != 0) {
            const RadiossFrame* f = facts_.frame(s.frame_id.value);
            if (!f || !f->geometry) continue;
            origin = f->origin;
            normal = f->axes[s.axis];
        }
        SymmetryPlane plane;
        plane.tail = origin;
        plane.head = {origin[0] + normal[0], origin[1] + normal[1], origin[2] + normal[2]};
        plane.span = s.span;
        s.plane = model_.symmetry_planes.size();
        model_.symmetry_planes.push_back(plane);
    }
}

// /GRNOD/PART: the nodes of the parts' particles and solid elements.
void RadiossBuilder::resolve_groups() {
    for (const auto& [id, parts] : part_groups_) {
        const std::unordered_set<long long> wanted(parts.begin(), parts.end());
        std::vector<long long> members;
        for (std::size_t i = 0; i < model_.particles.size(); ++i)
            if (wanted.count(model_.particles.part[i])) members.push_back(model_.particles.node[i]);
        for (const RadiossSolids* s : {&facts_.bricks, &facts_.tetra4, &facts_.tetra10, &facts_.penta6})
            for (std::size_t e = 0; e < s->size(); ++e)
                if (wanted.count(s->part[e]))
                    for (int k = 0; k < s->nodes_per_element; ++k)
                        if (long long n = s->nodes[e * s->nodes_per_element + k]) members.push_back(n);
        std::sort(members.begin(), members.end());
        members.erase(std::unique(members.begin(), members.end()), members.end());
        grammar::Span span;
        for (const auto& g : facts_.node_groups)
            if (g.id == id) span = g.span;
        model_.node_sets.push_back(IdSet{std::to_string(id), span, std::move(members)});
    }
}

// Parts use the EOS of their material; the SPH time-step scale comes from the engine deck.
void RadiossBuilder::resolve_links() {
    for (Part& part : model_.parts)
        for (const RadiossEos& e : facts_.eos)
            if (part.material.explicit_value && std::to_string(e.material) == part.material.value)
                part.eos = Setting<Id>{part.material.value, false, part.material.span};
    // /DT/NODA replaces the SPH factor when present; DTsca 0 takes the global /DT factor (0.9).
    const RadiossDt* global = facts_.time_step(DtKind::Global);
    const double global_scale = global && global->dtsca.value > 0 ? global->dtsca.value : 0.9;
    for (DtKind kind : {DtKind::SphCell, DtKind::Nodal}) {
        const RadiossDt* d = facts_.time_step(kind);
        if (!d) continue;
        const double scale = d->dtsca.value > 0 ? d->dtsca.value : global_scale;
        model_.controls.tssfac = Setting<double>{scale, d->dtsca.explicit_value, d->dtsca.span};
    }
}

Model RadiossBuilder::finish() {
    resolve_particles();
    resolve_frames();
    resolve_planes();
    resolve_groups();
    resolve_links();
    collect_surfaces();
    model_.radioss = std::move(facts_);
    compact_bulk_ids(model_);
    return std::move(model_);
}

}  // namespace sphdeck::model
