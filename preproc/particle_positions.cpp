#include "preproc/particle_positions.hpp"

namespace sphdeck::preproc {

ParticlePositions::ParticlePositions(const model::Model& m) : nodes_(m.nodes), node_of_(m) {}

std::vector<std::uint8_t> ParticlePositions::located() const {
    std::vector<std::uint8_t> out(size(), 1);
    if (!node_of_.all_found())
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = node_of_[i] != none;
    return out;
}

PointSpans ParticlePositions::all() const {
    return {std::span<const double>(nodes_.x).first(size()), std::span<const double>(nodes_.y).first(size()),
            std::span<const double>(nodes_.z).first(size())};
}

PointCopy ParticlePositions::gather(std::span<const std::uint32_t> particles) const {
    PointCopy c;
    c.x.resize(particles.size()), c.y.resize(particles.size()), c.z.resize(particles.size());
    for (std::size_t k = 0; k < particles.size(); ++k) {
        const std::uint32_t at = node(particles[k]);
        c.x[k] = nodes_.x[at], c.y[k] = nodes_.y[at], c.z[k] = nodes_.z[at];
    }
    return c;
}

PointCopy ParticlePositions::gather_all() const {
    PointCopy c;
    c.x.resize(size()), c.y.resize(size()), c.z.resize(size());
    for (std::size_t i = 0; i < size(); ++i) {
        const std::uint32_t at = node(i);
        c.x[i] = nodes_.x[at], c.y[i] = nodes_.y[at], c.z[i] = nodes_.z[at];
    }
    return c;
}

}  // namespace sphdeck::preproc
