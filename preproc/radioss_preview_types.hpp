// What the preview adds for a Radioss deck (docs/radioss.md): per part the initial h as spinih.F
// computes it, the symmetry mass split, ghost counts and the particle and nodal time steps; per
// /SPHBCS plane the particles on it and the ghosts it would create. Held as optional members of
// PartPreview and Preview (preproc/preview.hpp), set only when Model::radioss is.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace sphdeck::preproc {

struct RadiossPartPreview {
    long long property = 0;         // the /PROP/SPH id (0 when the part has none)
    double mp = 0;                  // the property mass (after the starter's default: <= 0 becomes 1)
    double property_h = 0;          // the property h as written (0: automatic)
    long long h_1d = 0;             // smoothing-length evolution mode
    double hcst = 1.2;              // factor on the largest nearest-neighbour distance (h_1D 3 only)
    double hmin = 0.2, hmax = 2.0;  // bound factors (h_1D 3 only)
    std::string h_rule;             // how h0 was computed, in words
    std::string h_evolution;        // what h does during the run, in words
    double h_smallest = 0, h_median = 0, h_largest = 0;  // over the part's particles
    // Cells by where their mass (and h) comes from: property mp, own MASS, own volume.
    std::size_t cells_from_property = 0, cells_with_mass = 0, cells_with_volume = 0;
    // Symmetry planes at t = 0 (inspcnd.F, spinit3.F; sph-algorithms.md §8.5).
    double mass_before = 0, mass_after = 0;         // part mass before and after the split
    std::array<std::size_t, 4> on_planes{};         // particles on 0, 1, 2, 3 or more planes
    std::vector<std::size_t> ghosts, ghosts_coded;  // per plane (RadiossPreview::planes order)
    // Time steps (sph-algorithms.md §7.2, §7.3), at rest.
    double qa = 2.0, qb = 1.0;
    double dt_particle = 0;  // /DT/SPHCEL scale x min_i h_i / (c (qb + sqrt(qb^2 + 1)))
    double dt_nodal = 0;     // /DT/NODA scale x sqrt(2 m / K*), K* the starter's 2 m / dt^2
};

struct RadiossPlanePreview {
    long long id = 0;  // the /SPHBCS id
    std::string type;  // "SLIDE", "TIED", as written
    std::array<double, 3> origin{}, normal{};
    std::size_t on_plane = 0;      // particles with dd < 1e-3 h_ref at t = 0
    std::size_t ghosts = 0;        // particles that would create a ghost, documented criterion
    std::size_t ghosts_coded = 0;  // the same, coded criterion (spsym_alloc.F)
};

struct RadiossPreview {
    double alpha_sort = 0.25;        // /SPHGLO (0 → 0.25)
    double h_max = 0;                // largest h of the model (the coded ghost criterion uses it)
    double dt_scale_particle = 0.9;  // /DT/SPHCEL DTsca (0 → the /DT factor, default 0.9)
    double dt_scale_nodal = 0;       // /DT/NODA DTsca (0 when no /DT/NODA)
    bool nodal = false;              // /DT/NODA is set: its factor replaces the SPH one
    bool engine_deck = false;        // an engine deck was read (else the scales are defaults)
    std::vector<RadiossPlanePreview> planes;
    std::vector<long long> unknown_planes;  // /SPHBCS ids whose plane is not known (no frame, bad Dir)
};

}  // namespace sphdeck::preproc
