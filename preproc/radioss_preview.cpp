// The Radioss preview: initial h (spinih.F), symmetry mass split (inspcnd.F, spinit3.F), ghosts
// per plane (seed page and spsym_alloc.F), particle and nodal time steps (mdtsph.F, spinit3.F).
// Formulas: preproc/radioss_formulas.hpp; choices and their reasons: docs/radioss.md.
#include "preproc/radioss_preview.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "preproc/neighbour_grid.hpp"
#include "preproc/radioss_formulas.hpp"
#include "preproc/time_step.hpp"

namespace sphdeck::preproc {
namespace {

// (x - O) . n of a plane with origin O and normal n (not normalised: the plane's tail-to-head vector).
double plane_signed_distance(const RadiossPlanePreview& plane, double x, double y, double z) {
    const Eigen::Vector3d origin(plane.origin[0], plane.origin[1], plane.origin[2]);
    const Eigen::Vector3d normal(plane.normal[0], plane.normal[1], plane.normal[2]);
    return (Eigen::Vector3d(x, y, z) - origin).dot(normal);
}

void add_radioss_note(std::string& notes, const std::string& note) {
    if (note.empty()) return;
    if (!notes.empty()) notes += "; ";
    notes += note;
}

long long id_number(const std::string& id) {
    char* end = nullptr;
    const long long v = std::strtoll(id.c_str(), &end, 10);
    return end && *end == '\0' && !id.empty() ? v : 0;
}

// The last engine card of a kind (a /DT written in the starter deck is ignored by the starter).
const model::RadiossDt* engine_dt(const model::RadiossFacts& f, model::DtKind kind) {
    const model::RadiossDt* found = nullptr;
    for (const model::RadiossDt& d : f.time_steps)
        if (d.kind == kind && !d.in_starter) found = &d;
    return found;
}

double median_of(std::vector<double> v) {
    if (v.empty()) return 0;
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + mid, v.end());
    double m = v[mid];
    if (v.size() % 2 == 0) m = 0.5 * (m + *std::max_element(v.begin(), v.begin() + mid));
    return m;
}

std::string radioss_h_evolution(long long h_1d) {
    switch (h_1d) {
        case 1: return "h_1D 1: h follows the volume change with coefficient 1 (1D), unbounded";
        case 2: return "h_1D 2: h stays constant during the run";
        case 3: return "h_1D 3: h follows the volume change (coefficient 1/3), kept within [hmin h0, hmax h0]";
        default: return "h_1D 0: h follows the volume change (coefficient 1/3), unbounded";
    }
}

}  // namespace

RadiossPreview radioss_preview_setup(const model::Model& m) {
    RadiossPreview r;
    const model::RadiossFacts& f = *m.radioss;
    r.alpha_sort = f.sph_global.alpha_sort.value > 0 ? f.sph_global.alpha_sort.value : 0.25;
    r.engine_deck = f.engine_deck;
    // DTsca 0 takes the global /DT factor, 0.9 in 3D by default (radioss-format.md §5.7).
    const model::RadiossDt* global = engine_dt(f, model::DtKind::Global);
    const double global_scale = global && global->dtsca.value > 0 ? global->dtsca.value : 0.9;
    const model::RadiossDt* sph = engine_dt(f, model::DtKind::SphCell);
    r.dt_scale_particle = sph && sph->dtsca.value > 0 ? sph->dtsca.value : global_scale;
    if (const model::RadiossDt* nodal = engine_dt(f, model::DtKind::Nodal)) {
        r.nodal = true;
        r.dt_scale_nodal = nodal->dtsca.value > 0 ? nodal->dtsca.value : global_scale;
    }
    for (const model::RadiossSymmetry& s : f.symmetries) {
        if (!s.plane || *s.plane >= m.symmetry_planes.size()) {
            r.unknown_planes.push_back(s.id);
            continue;
        }
        const model::SymmetryPlane& p = m.symmetry_planes[*s.plane];
        RadiossPlanePreview plane;
        plane.id = s.id;
        plane.type = s.type_text;
        plane.origin = p.tail;
        for (int k = 0; k < 3; ++k) plane.normal[k] = p.head[k] - p.tail[k];
        r.planes.push_back(plane);
    }
    return r;
}

void radioss_preview_part(const model::Model& m, std::span<const std::uint32_t> members, std::size_t q, Preview& out) {
    const model::RadiossFacts& f = *m.radioss;
    RadiossPreview& glob = *out.radioss;
    PartPreview& pv = out.parts[q];
    ParticlePreview& pp = out.particles;
    RadiossPartPreview r;
    r.ghosts.assign(glob.planes.size(), 0);
    r.ghosts_coded.assign(glob.planes.size(), 0);

    const model::Part* part = m.part(std::to_string(pv.part));
    const model::RadiossSphProperty* prop = part ? f.sph_property(id_number(part->section.value)) : nullptr;
    const long long material = part ? id_number(part->material.value) : 0;
    if (part && !prop)
        add_radioss_note(pv.notes, fmt::format("property {} is not a /PROP/SPH: mp 1, h automatic, qa 2, qb 1 assumed",
                                               part->section.value));
    if (prop) {
        r.property = prop->id;
        r.mp = prop->mp.value, r.property_h = prop->h.value, r.h_1d = prop->h_1d.value;
        r.hcst = prop->hcst.value, r.hmin = prop->hmin.value, r.hmax = prop->hmax.value;
        r.qa = prop->qa.value, r.qb = prop->qb.value;
    } else {
        r.mp = 1.0;
    }
    const double rho = pv.density;
    r.h_evolution = radioss_h_evolution(r.h_1d);

    // h0 per particle (spinih.F, sph-algorithms.md §4).
    double largest_nn = 0;
    for (std::uint32_t i : members)
        if (pp.located[i]) largest_nn = std::max(largest_nn, pp.nn_distance[i]);
    const bool from_distance = r.h_1d == 3;
    std::array<std::size_t, 5> by_source{};
    for (std::uint32_t i : members) {
        const bool from_property = f.cells.from_property[i] != 0;
        const RadiossCellH h = radioss_cell_h(f.cells.type[i], f.cells.mass[i], from_property, r.property_h, r.mp, rho);
        ++by_source[static_cast<std::size_t>(h.source)];
        if (from_property)
            ++r.cells_from_property;
        else if (f.cells.type[i] == 2)
            ++r.cells_with_volume;
        else
            ++r.cells_with_mass;
        pp.h[i] = from_distance ? r.hcst * largest_nn : h.h;
    }
    if (from_distance) {
        r.h_rule =
            fmt::format("hcst {:.4g} x the largest nearest same-part distance {:.4g} (h_1D 3)", r.hcst, largest_nn);
        if (!(largest_nn > 0))
            add_radioss_note(pv.notes,
                             "h_1D 3 with no nearest-neighbour distance (one particle, or all at one place): h 0");
    } else {
        std::vector<std::string> rules;
        const auto sources = std::count_if(by_source.begin(), by_source.end(), [](std::size_t n) { return n > 0; });
        const char* words[] = {"property h", "(sqrt2 mp / rho)^(1/3), mp of the property",
                               "(sqrt2 MASS / rho)^(1/3), the cell's mass", "(sqrt2 V)^(1/3), the cell's volume",
                               "unknown (no density)"};
        for (std::size_t k = 0; k < by_source.size(); ++k)
            if (by_source[k] > 0)
                rules.push_back(sources > 1 ? fmt::format("{} ({} cells)", words[k], by_source[k])
                                            : std::string(words[k]));
        for (std::size_t k = 0; k < rules.size(); ++k) r.h_rule += (k ? "; " : "") + rules[k];
        if (by_source[static_cast<std::size_t>(RadiossHSource::Unknown)] > 0)
            add_radioss_note(pv.notes, "the material density is not positive: h from the mass is unknown");
    }

    // Symmetry planes at t = 0: a particle on n planes keeps m / (1 + n) (§8.5).
    const double h_ref = radioss_symmetry_reference_h(r.property_h, r.mp, rho);
    if (pp.planes.size() != pp.x.size()) pp.planes.assign(pp.x.size(), 0);
    std::vector<double> h_located, mass_after;
    for (std::uint32_t i : members) {
        r.mass_before += pp.mass[i];
        int n = 0;
        if (pp.located[i]) {
            for (std::size_t k = 0; k < glob.planes.size(); ++k) {
                const RadiossPlanePreview& plane = glob.planes[k];
                const double dd = plane_signed_distance(plane, pp.x[i], pp.y[i], pp.z[i]);
                if (radioss_on_plane(dd, h_ref)) {
                    ++n;
                    ++glob.planes[k].on_plane;
                }
            }
            h_located.push_back(pp.h[i]);
        }
        pp.planes[i] = static_cast<std::uint8_t>(n);
        ++r.on_planes[std::min(n, 3)];
        pp.mass[i] = radioss_symmetry_mass(pp.mass[i], n);
        r.mass_after += pp.mass[i];
        if (pp.located[i]) mass_after.push_back(pp.mass[i]);
    }
    pv.mass_total = r.mass_after;
    pv.mass_median = median_of(mass_after);
    if (r.on_planes[3] > 0)
        add_radioss_note(pv.notes, fmt::format("{} particle(s) on three or more symmetry planes keep m / (1 + n), not "
                                               "the physical share m / 2^n",
                                               r.on_planes[3]));

    if (!h_located.empty()) {
        auto [lo, hi] = std::minmax_element(h_located.begin(), h_located.end());
        r.h_smallest = *lo, r.h_largest = *hi;
        r.h_median = median_of(h_located);
    }
    pv.h0 = r.h_median;
    pv.sphini_given = !from_distance && r.property_h > 0 && r.cells_from_property > 0;
    // The LS-DYNA mode that matches the rule: h_1D 3 is the max-of-min rule of INI 0, the others
    // take h from each particle's mass or volume (INI 2); a property h is SPHINI.
    pv.ini = from_distance ? model::IniMode::BucketSort : model::IniMode::FromMass;
    pv.support = 2.0 * pv.h0;  // the cubic spline, the only OpenRadioss kernel (§1.1)
    if (r.h_1d == 3)
        pv.h_min = r.hmin * pv.h0, pv.h_max = r.hmax * pv.h0;
    else if (r.h_1d == 2)
        pv.h_min = pv.h_max = pv.h0;
    else
        pv.h_min = pv.h_max = 0;  // unbounded: docs/radioss.md

    // Sound speed and time steps at rest (§7.2, §7.3, §10).
    const RadiossSoundSpeed c = radioss_sound_speed(f, material);
    pv.sound_speed = c.c;
    pv.sound_source = c.source;
    add_radioss_note(pv.notes, c.note);
    double dt_particle = 0, dt_nodal = 0;
    for (std::uint32_t i : members) {
        if (!pp.located[i] || !(pp.h[i] > 0) || !(c.c > 0)) continue;
        const double unscaled = radioss_particle_time_step(pp.h[i], c.c, 1.0, r.qa, r.qb);
        const double dt = glob.dt_scale_particle * unscaled;
        if (dt_particle == 0 || dt < dt_particle) dt_particle = dt;
        if (glob.nodal) {
            const double nodal = radioss_nodal_time_step(glob.dt_scale_nodal, pp.mass[i],
                                                         radioss_particle_stiffness(pp.mass[i], unscaled));
            if (dt_nodal == 0 || nodal < dt_nodal) dt_nodal = nodal;
        }
    }
    r.dt_particle = dt_particle;
    r.dt_nodal = dt_nodal;
    pv.dt_radioss = dt_particle;
    const double tssfac = m.controls.tssfac.value > 0 ? m.controls.tssfac.value : 0.9;
    pv.dt_estimate = cfl_time_step(pv.h0, c.c, tssfac);  // as for LS-DYNA decks: TSSFAC h0 / c
    pv.radioss = std::move(r);
}

void radioss_count_ghosts(Preview& out) {
    RadiossPreview& glob = *out.radioss;
    const ParticlePreview& pp = out.particles;
    std::vector<std::uint32_t> located;
    for (std::size_t i = 0; i < pp.located.size(); ++i)
        if (pp.located[i]) located.push_back(static_cast<std::uint32_t>(i));
    glob.h_max = 0;
    for (std::uint32_t i : located) glob.h_max = std::max(glob.h_max, pp.h[i]);
    if (glob.planes.empty() || located.empty() || !(glob.h_max > 0)) return;
    const double alpha = glob.alpha_sort, widen = std::sqrt(1.0 + alpha);

    auto distance = [&](std::uint32_t i, const RadiossPlanePreview& p) {
        return plane_signed_distance(p, pp.x[i], pp.y[i], pp.z[i]);
    };
    // Candidates pass the coded bound, which contains the documented one (max h_j <= h_max). The
    // neighbour search is needed only where the documented test depends on it: i itself (bound
    // 2 h_i) does not decide, and a larger neighbour h could (the bound h_i + h_max does).
    std::vector<std::uint8_t> candidate(pp.x.size(), 0), search(pp.x.size(), 0);
    for (std::uint32_t i : located)
        for (const RadiossPlanePreview& p : glob.planes) {
            const double dd = distance(i, p);
            if (std::abs(dd) <= widen * (pp.h[i] + glob.h_max) || dd < 0) candidate[i] = 1;
            if (std::abs(dd) > widen * 2 * pp.h[i] && std::abs(dd) <= widen * (pp.h[i] + glob.h_max)) search[i] = 1;
        }

    // The largest h among the sort neighbours of each candidate: |x_i - x_j|^2 <= (1 + alpha)
    // (h_i + h_j)^2, i itself included (§8.3).
    std::vector<double> largest(pp.x.size(), 0.0);
    for (std::uint32_t i : located) largest[i] = pp.h[i];
    const bool any_search = std::any_of(search.begin(), search.end(), [](std::uint8_t s) { return s != 0; });
    std::vector<double> xs, ys, zs;
    if (any_search)
        for (std::uint32_t i : located) xs.push_back(pp.x[i]), ys.push_back(pp.y[i]), zs.push_back(pp.z[i]);
    const NeighbourGrid grid = any_search ? NeighbourGrid(xs, ys, zs, 2.0 * widen * glob.h_max) : NeighbourGrid();
    for (std::uint32_t i : located) {
        if (!search[i]) continue;
        double best = pp.h[i];
        grid.for_each_block_range(grid.cell_of(pp.x[i], pp.y[i], pp.z[i]), 1, [&](std::uint32_t b, std::uint32_t e) {
            for (std::uint32_t k = b; k < e; ++k) {
                const std::uint32_t j = located[grid.order()[k]];
                const double dx = grid.x()[k] - pp.x[i], dy = grid.y()[k] - pp.y[i], dz = grid.z()[k] - pp.z[i];
                const double reach = pp.h[i] + pp.h[j];
                if (dx * dx + dy * dy + dz * dz <= (1.0 + alpha) * reach * reach) best = std::max(best, pp.h[j]);
            }
        });
        largest[i] = best;
    }
    for (std::uint32_t i : located) {
        if (!candidate[i]) continue;
        std::optional<RadiossPartPreview>& part = out.parts[pp.part[i]].radioss;
        for (std::size_t k = 0; k < glob.planes.size(); ++k) {
            const double dd = distance(i, glob.planes[k]);
            const bool documented = radioss_ghost_documented(dd, pp.h[i], largest[i], alpha);
            const bool coded = radioss_ghost_coded(dd, pp.h[i], glob.h_max, alpha);
            glob.planes[k].ghosts += documented;
            glob.planes[k].ghosts_coded += coded;
            if (part) part->ghosts[k] += documented, part->ghosts_coded[k] += coded;
        }
    }
}

}  // namespace sphdeck::preproc
