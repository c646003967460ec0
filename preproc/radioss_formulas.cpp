#include "preproc/radioss_formulas.hpp"

#include <cmath>
#include <fmt/format.h>

#include "preproc/sound_speed.hpp"

namespace sphdeck::preproc {

double radioss_h_from_volume(double volume) { return volume > 0 ? std::cbrt(std::sqrt(2.0) * volume) : 0.0; }

RadiossCellH radioss_cell_h(int type, double cell_value, bool from_property, double property_h, double mp,
                            double density) {
    if (from_property) {
        if (property_h > 0) return {property_h, RadiossHSource::PropertyH};
        if (!(density > 0)) return {};
        return {radioss_h_from_volume(mp / density), RadiossHSource::PropertyMass};
    }
    if (type == 2) return {radioss_h_from_volume(cell_value), RadiossHSource::CellVolume};
    if (!(density > 0)) return {};
    return {radioss_h_from_volume(cell_value / density), RadiossHSource::CellMass};
}

double radioss_symmetry_reference_h(double property_h, double mp, double density) {
    if (property_h != 0) return property_h;
    return density > 0 ? radioss_h_from_volume(mp / density) : 0.0;
}

bool radioss_on_plane(double signed_distance, double reference_h) { return signed_distance < 1e-3 * reference_h; }

double radioss_symmetry_mass(double mass, int planes) { return mass / (1.0 + std::max(planes, 0)); }

bool radioss_ghost_documented(double signed_distance, double h_i, double largest_neighbour_h, double alpha_sort) {
    const double reach = h_i + largest_neighbour_h;
    return signed_distance * signed_distance <= (1.0 + alpha_sort) * reach * reach;
}

bool radioss_ghost_coded(double signed_distance, double h_i, double h_max, double alpha_sort) {
    return signed_distance <= std::sqrt(1.0 + alpha_sort) * (h_i + h_max);
}

double radioss_nodal_time_step(double scale, double mass, double stiffness) {
    return stiffness > 0 && mass > 0 ? scale * std::sqrt(2.0 * mass / stiffness) : 0.0;
}

double radioss_particle_stiffness(double mass, double particle_dt) {
    return 2.0 * mass / std::max(1e-20, particle_dt * particle_dt);
}

RadiossSoundSpeed radioss_sound_speed(const model::RadiossFacts& facts, long long material) {
    RadiossSoundSpeed out;
    const model::RadiossMaterial* mat = facts.material(material);
    if (!mat) {
        out.note = fmt::format("material {} is not defined: no sound speed", material);
        return out;
    }
    const double rho = mat->density;
    if (!(rho > 0)) {
        out.note = fmt::format("material {} has no positive density: no sound speed", material);
        return out;
    }
    if (const model::RadiossEos* eos = facts.eos_of(material)) {
        const double c[7] = {eos->c[0], eos->c[1], eos->c[2], eos->c[3], eos->c[4], eos->c[5], 0.0};
        const double rho0 = eos->rho0 > 0 ? eos->rho0 : rho;
        out.c = linear_polynomial_sound_speed(c, eos->e0, rho0);
        out.source = eos->keyword;
        if (!(out.c > 0)) out.note = eos->keyword + " gives no positive sound speed at rest";
        return out;
    }
    if (mat->bulk > 0) {
        out.c = std::sqrt(mat->bulk / rho);
        out.source = mat->keyword + " C1";
        return out;
    }
    if (mat->young > 0) {
        out.c = elastic_sound_speed(mat->young, mat->poisson, rho);
        out.source = mat->keyword;
        if (!(out.c > 0)) out.note = mat->keyword + ": E and nu give no sound speed";
        return out;
    }
    out.note = mat->keyword + ": no bulk modulus, Young's modulus or /EOS read: no sound speed";
    return out;
}

}  // namespace sphdeck::preproc
