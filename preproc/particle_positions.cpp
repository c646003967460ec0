#include "preproc/particle_positions.hpp"

#include "model/id_index.hpp"

namespace sphdeck::preproc {

namespace {
// Particle i names node i for every i, and no earlier node has its id (ids rising: the index
// would find no earlier copy), so the node index would map every particle to itself.
bool particles_in_node_order(const model::Model& m) {
    const model::IdColumn& ids = m.nodes.id;
    const model::IdColumn& named = m.particles.node;
    const std::size_t n = named.size();
    if (n > ids.size()) return false;
    bool in_order = true;
#pragma omp parallel for reduction(&& : in_order) schedule(static) if (n > 65536)
    for (std::size_t i = 0; i < n; ++i) in_order = in_order && ids[i] == named[i] && (i == 0 || ids[i - 1] < ids[i]);
    return in_order;
}
}  // namespace

ParticlePositions::ParticlePositions(const model::Model& m) : nodes_(m.nodes), size_(m.particles.size()) {
    in_place_ = particles_in_node_order(m);
    if (in_place_) return;
    const model::IdIndex index(m.nodes.id);
    node_of_.assign(size_, none);
    const model::IdColumn& named = m.particles.node;
#pragma omp parallel for schedule(static) if (size_ > 65536)
    for (std::size_t i = 0; i < size_; ++i)
        if (auto at = index.find(named[i])) node_of_[i] = static_cast<std::uint32_t>(*at);
}

std::vector<std::uint8_t> ParticlePositions::located() const {
    std::vector<std::uint8_t> out(size_, 1);
    if (!in_place_)
        for (std::size_t i = 0; i < size_; ++i) out[i] = node_of_[i] != none;
    return out;
}

PointSpans ParticlePositions::all() const {
    return {std::span<const double>(nodes_.x).first(size_), std::span<const double>(nodes_.y).first(size_),
            std::span<const double>(nodes_.z).first(size_)};
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
    c.x.resize(size_), c.y.resize(size_), c.z.resize(size_);
    for (std::size_t i = 0; i < size_; ++i) {
        const std::uint32_t at = node(i);
        c.x[i] = nodes_.x[at], c.y[i] = nodes_.y[at], c.z[i] = nodes_.z[at];
    }
    return c;
}

}  // namespace sphdeck::preproc
