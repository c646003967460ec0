// The particles *DEFINE_SPH_MESH_BOX generates, for `sphdeck smooth` (docs/sph-keywords.md).
//
// pydyna's field texts (define_sph_mesh_box.py): XMIN/YMIN/ZMIN the minimum coordinates,
// XLEN/YLEN/ZLEN the box lengths, NX/NY/NZ "number of SPH particles in the x-direction" (y, z),
// IPID the part of the generated elements. The particles sit at the centres of the NX x NY x NZ
// cells of the box (spacing XLEN/NX...): pydyna's own deck isph.k fills a 1176-long box with 98
// particles beside *DEFINE_SPH_MESH_SURFACE SPACE 12.0 = 1176/98. Each particle's volume is its
// cell's, so the preview gives it the part's density times that volume.
//
// Not generated (a note says why): boxes with IDSEG != 0 (the solver removes the particles on one
// side of a segment set and near it), counts or lengths <= 0, and boxes beyond `max_particles`.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace sphdeck::preproc {

struct MeshBox {
    long long part = 0;
    long long nx = 0, ny = 0, nz = 0;
    double x0 = 0, y0 = 0, z0 = 0, dx = 0, dy = 0, dz = 0;  // minimum corner, cell sizes
    std::size_t particles = 0;                              // generated (0 when skipped)
    grammar::Span span;                                     // the keyword
    std::string skipped;                                    // why no particles, else empty
};

struct MeshBoxParticles {
    std::vector<MeshBox> boxes;
    std::vector<double> x, y, z, volume;
    std::vector<long long> part;
    std::size_t size() const { return x.size(); }
};

// Particles beyond this many in all are not generated (a deck may ask for billions).
inline constexpr std::size_t max_mesh_box_particles = 20'000'000;

MeshBoxParticles generate_mesh_box_particles(const model::Model& model,
                                             std::size_t max_particles = max_mesh_box_particles);

// A copy of `model` with the generated particles appended as *ELEMENT_SPH_VOLUME particles on new
// nodes (ids above the largest node id), so that the preview treats them like the deck's own.
model::Model with_mesh_box_particles(const model::Model& model, const MeshBoxParticles& generated);

}  // namespace sphdeck::preproc
