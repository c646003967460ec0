// generate_mesh_box_particles: cell-centred particles of *DEFINE_SPH_MESH_BOX (sph_mesh_box.hpp).
#include "preproc/sph_mesh_box.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "grammar/number_cast.hpp"

namespace sphdeck::preproc {
namespace {

double box_number(const model::KeywordRecord& r, std::string_view field) {
    const model::FieldRecord* f = r.field(field);
    return f && f->valid ? f->number : 0.0;
}

// A count field as an integer; 0 when blank, not a whole number or absurd.
long long count_in_box(const model::KeywordRecord& r, std::string_view field) {
    const double v = box_number(r, field);
    return v >= 1 && v <= 1e9 && v == std::floor(v) ? static_cast<long long>(v) : 0;
}

MeshBox read_box(const model::KeywordRecord& r) {
    MeshBox b;
    b.span = r.span;
    b.part = grammar::saturating_integer<long long>(box_number(r, "IPID"));
    b.nx = count_in_box(r, "NX"), b.ny = count_in_box(r, "NY"), b.nz = count_in_box(r, "NZ");
    b.x0 = box_number(r, "XMIN"), b.y0 = box_number(r, "YMIN"), b.z0 = box_number(r, "ZMIN");
    const double lx = box_number(r, "XLEN"), ly = box_number(r, "YLEN"), lz = box_number(r, "ZLEN");
    if (box_number(r, "IDSEG") != 0)
        b.skipped =
            "IDSEG is set: the solver removes the particles on one side of the segment set, which the "
            "preview does not follow";
    else if (b.nx == 0 || b.ny == 0 || b.nz == 0)
        b.skipped = "NX, NY and NZ must be whole numbers of at least 1";
    else if (!(lx > 0 && ly > 0 && lz > 0))
        b.skipped = "XLEN, YLEN and ZLEN must be positive";
    else
        b.dx = lx / static_cast<double>(b.nx), b.dy = ly / static_cast<double>(b.ny),
        b.dz = lz / static_cast<double>(b.nz);
    return b;
}

}  // namespace

MeshBoxParticles generate_mesh_box_particles(const model::Model& model, std::size_t max_particles) {
    MeshBoxParticles out;
    for (const model::KeywordRecord& r : model.records) {
        if (r.schema->name != "*DEFINE_SPH_MESH_BOX") continue;
        MeshBox b = read_box(r);
        if (b.skipped.empty()) {
            // Counts are at most 1e9 each: compare in double before multiplying integers.
            const double n = static_cast<double>(b.nx) * static_cast<double>(b.ny) * static_cast<double>(b.nz);
            if (n > static_cast<double>(max_particles - std::min(max_particles, out.size())))
                b.skipped =
                    fmt::format("{:.0f} particles exceed what the preview generates ({} in all)", n, max_particles);
        }
        if (b.skipped.empty()) {
            const double cell = b.dx * b.dy * b.dz;
            for (long long k = 0; k < b.nz; ++k)
                for (long long j = 0; j < b.ny; ++j)
                    for (long long i = 0; i < b.nx; ++i) {
                        out.x.push_back(b.x0 + (static_cast<double>(i) + 0.5) * b.dx);
                        out.y.push_back(b.y0 + (static_cast<double>(j) + 0.5) * b.dy);
                        out.z.push_back(b.z0 + (static_cast<double>(k) + 0.5) * b.dz);
                        out.volume.push_back(cell);
                        out.part.push_back(b.part);
                    }
            b.particles = static_cast<std::size_t>(b.nx * b.ny * b.nz);
        }
        out.boxes.push_back(std::move(b));
    }
    return out;
}

model::Model with_mesh_box_particles(const model::Model& model, const MeshBoxParticles& generated) {
    model::Model m = model;
    long long next = 1;
    for (long long id : m.nodes.id) next = std::max(next, id + 1);
    const std::size_t n = generated.size();
    m.nodes.id.reserve(m.nodes.id.size() + n);
    m.particles.node.reserve(m.particles.size() + n);
    for (std::size_t i = 0; i < n; ++i, ++next) {
        m.nodes.id.push_back(next);
        m.nodes.x.push_back(generated.x[i]), m.nodes.y.push_back(generated.y[i]), m.nodes.z.push_back(generated.z[i]);
        m.particles.node.push_back(next);
        m.particles.part.push_back(generated.part[i]);
        m.particles.mass.push_back(generated.volume[i]);
        m.particles.volume.push_back(1);  // the mass column holds a volume (*ELEMENT_SPH_VOLUME)
        m.particles.line.push_back(0);
    }
    return m;
}

}  // namespace sphdeck::preproc
