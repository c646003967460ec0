// The OpenRadioss starter and engine rules the Radioss preview needs, as small pure functions.
// Every formula cites /work/shared/reference/sph-algorithms.md (§4 initial h, §7 time steps, §8
// symmetry planes, §10 sound speeds) and the OpenRadioss file it comes from.
#pragma once

#include <string>

#include "model/model.hpp"

namespace sphdeck::preproc {

// h of a particle standing for `volume` in a hexagonal compact net: (sqrt(2) V)^(1/3)
// (spinih.F, §4). 0 when the volume is not positive.
double radioss_h_from_volume(double volume);

// Where a particle's initial h comes from (spinih.F, §4), h_1D 3 aside.
enum class RadiossHSource { PropertyH, PropertyMass, CellMass, CellVolume, Unknown };

// The initial h of one /SPHCEL cell: Type 1 (or Type 0 with MASS > 0) from its own mass, Type 2
// from its own volume (property h ignored for both); a cell taking mp from its property uses the
// property h when > 0, else the mass mp. `density` is the material RHO_I. 0 when unknown.
struct RadiossCellH {
    double h = 0;
    RadiossHSource source = RadiossHSource::Unknown;
};
RadiossCellH radioss_cell_h(int type, double cell_value, bool from_property, double property_h, double mp,
                            double density);

// The length the starter compares plane distances with (inspcnd.F, §8.5): the property h, or
// (sqrt(2) mp / rho)^(1/3) when it is 0. Per-cell masses play no part.
double radioss_symmetry_reference_h(double property_h, double mp, double density);

// A particle lies on a plane at t = 0 when its signed distance dd = (x - O).n is below 1e-3 times
// the reference h (inspcnd.F: DD < EM3*DI). Negative dd (the wrong side) passes too.
bool radioss_on_plane(double signed_distance, double reference_h);

// The mass of a particle on n planes at t = 0: m / (1 + n) (inspcnd.F counter from 1, spinit3.F
// V = V0 / counter; §8.5). The seed page's m / n is wrong for n >= 2 (docs/radioss.md).
double radioss_symmetry_mass(double mass, int planes);

// Ghost creation for one plane (§8.1). As documented (seed page, "Maximum created number of ghost
// particles"): d(N_i, P)^2 <= (1 + alpha) max_j (h_i + h_j)^2 over the neighbours j of i
// (unsigned distance). As coded (spsym_alloc.F): dd_i <= sqrt(1 + alpha) (h_i + h_max) (signed).
bool radioss_ghost_documented(double signed_distance, double h_i, double largest_neighbour_h, double alpha_sort);
bool radioss_ghost_coded(double signed_distance, double h_i, double h_max, double alpha_sort);

// The nodal step /DT/NODA of a node carrying mass m and stiffness K: DTsca sqrt(2 m / K) (§7.3);
// 0 when K is not positive.
double radioss_nodal_time_step(double scale, double mass, double stiffness);
// The nodal stiffness a particle adds at t = 0 (spinit3.F: STI = 2 m / dt^2, §7.2 last item), dt
// its unscaled particle step.
double radioss_particle_stiffness(double mass, double particle_dt);

// The sound speed of a Radioss material at rest (§10): /EOS/POLYNOMIAL c^2 = (C1 + C5 E0 + C4 p0)/rho0
// with p0 = C0 + C4 E0; a law's own C1 (LAW3/4/6) c^2 = C1/rho; an elastic law the dilatational
// speed. `source` names what was used, `note` why c is 0.
struct RadiossSoundSpeed {
    double c = 0;
    std::string source, note;
};
RadiossSoundSpeed radioss_sound_speed(const model::RadiossFacts& facts, long long material);

}  // namespace sphdeck::preproc
