// The particles OpenRadioss creates for SOL2SPH solids (sph-algorithms.md §9, soltosph.F): per
// 8-node brick Ndir^3 particles at the sub-cell centres of the parent cube mapped through the
// trilinear shape functions; per 4-node tetra (or brick with 4 distinct nodes) N(N+1)(N+2)/6
// particles at barycentric coordinates (2k_a - 1) / (2(N + 1)) with k_1 + ... + k_4 = N + 3.
// A pure function of the Model (docs/radioss.md, "sphdeck sol2sph").
//
// Masses: `mass` is the particle's exact share of its element, rho times the integral of det J
// over its sub-cell (2x2x2 Gauss, exact for a trilinear map) or V_tet / count; `mass_starter` is
// what the starter gives it, rho (8 / Ndir^3) det J at the sub-cell centre (soltosph.F, §9.1),
// which differs from the exact share on a non-parallelepiped brick. rho is the SPH part's
// density (spinit3.F multiplies the volume by it); the element mass uses the solid's density.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace sphdeck::preproc {

// Particles per element: Ndir^3 for bricks, Ndir (Ndir + 1)(Ndir + 2) / 6 for tetras.
std::size_t sol2sph_brick_count(int ndir);
std::size_t sol2sph_tetra_count(int ndir);

// Sub-cell centres along one parent axis: (2k - 1) / Ndir - 1, k = 1..Ndir.
std::vector<double> sol2sph_brick_abscissae(int ndir);
// Barycentric coordinates of the tetra particles, four per particle.
std::vector<std::array<double, 4>> sol2sph_tetra_barycentrics(int ndir);

struct Sol2sphIssue {
    long long element = 0;
    std::uint32_t line = 0;  // index into RawDeck::lines (the element's line)
    std::string message;
};

struct Sol2sphPart {
    long long solid_part = 0, sph_part = 0, property = 0;
    int ndir = 0;
    std::size_t bricks = 0, tetras = 0, particles = 0;
    std::size_t skipped = 0;  // elements without particles (issues, unsupported kinds)
    double solid_density = 0, sph_density = 0;
    double element_mass = 0;   // solid density x exact volume of the elements used
    double particle_mass = 0;  // sum of `mass`
    double starter_mass = 0;   // sum of `mass_starter`
    double pitch = 0;          // median over elements of (V / particles per element)^(1/3)
    double sph_h = 0;          // the SPH part's /PROP/SPH h (0: not given)
    long long sph_h_1d = 0;
    grammar::Span span;                  // the part's /PART header id, for messages about the part
    double relative_difference() const;  // (particle_mass - element_mass) / element_mass
    double starter_relative_difference() const;
    std::vector<std::string> notes;
    // Set when Ndir is valid but the part gets no particle at all (only /TETRA10 or /PENTA6
    // elements, no elements, or every element rejected): why, for a warning at `span`.
    std::string no_particles;
};

struct Sol2sphParticles {
    std::vector<double> x, y, z, mass, mass_starter, volume;
    std::vector<long long> element, solid_part, sph_part;
    std::size_t size() const { return x.size(); }
};

struct Sol2sph {
    std::vector<Sol2sphPart> parts;
    Sol2sphParticles particles;
    std::vector<Sol2sphIssue> issues;  // elements that got no particles, and why
};

Sol2sph generate_sol2sph(const model::Model& model);

}  // namespace sphdeck::preproc
