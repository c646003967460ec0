#include "engine/preview_reuse.hpp"

#include <algorithm>

namespace sphdeck::engine {
namespace {
template <typename T>
bool same(const model::Setting<T>& a, const model::Setting<T>& b) {
    return a.value == b.value && a.explicit_value == b.explicit_value;
}

bool same(const model::ControlSph& a, const model::ControlSph& b) {
    return a.present == b.present && same(a.ncbs, b.ncbs) && same(a.boxid, b.boxid) && same(a.memory, b.memory) &&
           same(a.cont, b.cont) && same(a.deriv, b.deriv) && same(a.ishow, b.ishow) && same(a.icont, b.icont) &&
           same(a.isymp, b.isymp) && same(a.ithk, b.ithk) && same(a.istab, b.istab) && same(a.sphsort, b.sphsort) &&
           same(a.ishift, b.ishift) && same(a.dt, b.dt) && same(a.start, b.start) && same(a.maxv, b.maxv) &&
           same(a.ql, b.ql) && same(a.idim, b.idim) && same(a.form, b.form) && same(a.ini, b.ini) &&
           same(a.ierod, b.ierod) && same(a.iavis, b.iavis);
}

bool same(const model::Controls& a, const model::Controls& b) {
    return same(a.sph, b.sph) && same(a.endtim, b.endtim) && same(a.tssfac, b.tssfac) && same(a.erode, b.erode) &&
           same(a.q1, b.q1) && same(a.q2, b.q2) && a.bulk_viscosity_present == b.bulk_viscosity_present &&
           a.mpp_keywords.size() == b.mpp_keywords.size() && same(a.soln, b.soln);
}

bool same(const model::Section& a, const model::Section& b) {
    return a.id == b.id && a.keyword == b.keyword && a.sph == b.sph && a.ellipse == b.ellipse &&
           a.interaction == b.interaction && same(a.cslh, b.cslh) && same(a.hmin, b.hmin) && same(a.hmax, b.hmax) &&
           same(a.sphini, b.sphini) && same(a.death, b.death) && same(a.start, b.start) && same(a.kernel, b.kernel) &&
           a.shell_form == b.shell_form;
}

bool same(const model::Part& a, const model::Part& b) {  // the heading is not read
    return a.id == b.id && same(a.section, b.section) && same(a.material, b.material) && same(a.eos, b.eos) &&
           same(a.hourglass, b.hourglass) && same(a.thermal_material, b.thermal_material) && a.inertia == b.inertia;
}

bool same(const model::FieldRecord& a, const model::FieldRecord& b) {
    return a.name == b.name && a.type == b.type &&
           (a.number == b.number || (a.number != a.number && b.number != b.number)) && a.text == b.text &&
           a.explicit_value == b.explicit_value && a.valid == b.valid;
}

// The keyword records a material or an EOS points at (their moduli give the sound speed).
bool same_record(const model::Model& ma, std::optional<std::size_t> a, const model::Model& mb,
                 std::optional<std::size_t> b) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    const bool in_a = *a < ma.records.size(), in_b = *b < mb.records.size();
    if (in_a != in_b) return false;
    if (!in_a) return true;
    const model::KeywordRecord& ra = ma.records[*a];
    const model::KeywordRecord& rb = mb.records[*b];
    if (ra.schema != rb.schema || ra.keyword != rb.keyword || ra.options != rb.options ||
        ra.rows.size() != rb.rows.size())
        return false;
    for (std::size_t row = 0; row < ra.rows.size(); ++row)
        if (!std::equal(ra.rows[row].begin(), ra.rows[row].end(), rb.rows[row].begin(), rb.rows[row].end(),
                        [](const auto& x, const auto& y) { return same(x, y); }))
            return false;
    return true;
}

template <typename T, typename Same>
bool all_same(const std::vector<T>& a, const std::vector<T>& b, Same&& same_item) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), same_item);
}
}  // namespace

namespace {
// Columns `now` took whole from `before` are the same, unless more were appended to them since.
bool took_nodes(const model::Model& now, const model::BulkTaken& taken) {
    return taken.nodes && now.nodes.id.size() == taken.node_count;
}
bool took_particles(const model::Model& now, const model::BulkTaken& taken) {
    return taken.particles && now.particles.size() == taken.particle_count;
}
}  // namespace

bool same_geometry_inputs(const model::Model& before, const model::Model& now, const model::BulkTaken& taken) {
    const model::Particles& p = before.particles;
    const model::Particles& q = now.particles;
    return same_geometry_settings(before, now) && same_particle_places(before, now, taken) &&
           (took_particles(now, taken) || (p.mass == q.mass && p.volume == q.volume));
}

bool same_particle_places(const model::Model& before, const model::Model& now, const model::BulkTaken& taken) {
    const model::Particles& p = before.particles;
    const model::Particles& q = now.particles;
    const model::Nodes &a = before.nodes, &b = now.nodes;
    return !before.radioss && !now.radioss &&
           (took_nodes(now, taken) || (a.id == b.id && a.x == b.x && a.y == b.y && a.z == b.z)) &&
           (took_particles(now, taken) || (p.node == q.node && p.part == q.part));
}

namespace {
// same_geometry_settings but for the controls.
bool same_settings_but_controls(const model::Model& before, const model::Model& now) {
    if (before.radioss || now.radioss) return false;
    return all_same(before.sections, now.sections, [](const auto& a, const auto& b) { return same(a, b); }) &&
           all_same(before.parts, now.parts, [](const auto& a, const auto& b) { return same(a, b); }) &&
           all_same(before.materials, now.materials,
                    [&](const model::Material& a, const model::Material& b) {
                        return a.id == b.id && a.keyword == b.keyword && same(a.density, b.density) &&
                               a.has_density == b.has_density && same_record(before, a.record, now, b.record);
                    }) &&
           all_same(before.equations_of_state, now.equations_of_state,
                    [&](const model::Eos& a, const model::Eos& b) {
                        return a.id == b.id && a.keyword == b.keyword && same_record(before, a.record, now, b.record);
                    }) &&
           before.symmetry_planes.size() == now.symmetry_planes.size() &&
           all_same(before.symmetry_planes, now.symmetry_planes,
                    [](const auto& a, const auto& b) { return a.tail == b.tail && a.head == b.head; });
}
}  // namespace

bool same_geometry_settings(const model::Model& before, const model::Model& now) {
    return same(before.controls, now.controls) && same_settings_but_controls(before, now);
}

bool same_preview_settings(const model::Model& before, const model::Model& now) {
    return same(before.controls.sph, now.controls.sph) && same(before.controls.tssfac, now.controls.tssfac) &&
           same_settings_but_controls(before, now);
}

}  // namespace sphdeck::engine
