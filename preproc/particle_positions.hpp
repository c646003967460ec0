// Where each particle of a model is: the position of its node (model::ParticleNodes), read in place from the
// model's node arrays (no copy per particle). When the particles come in node order (particle i is node
// i: the usual deck, generators write *NODE and *ELEMENT_SPH alike) every particle's position is read where
// it is (all()). Copies of positions are made only for the searches that
// need a subset (a part, the located particles), and are dropped after them.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "model/model.hpp"
#include "model/particle_nodes.hpp"

namespace sphdeck::preproc {

struct PointSpans {
    std::span<const double> x, y, z;
};

// A copy of some particles' positions, in the order asked.
struct PointCopy {
    std::vector<double> x, y, z;
    PointSpans spans() const { return {x, y, z}; }
};

class ParticlePositions {
public:
    explicit ParticlePositions(const model::Model& m);

    static constexpr std::uint32_t none = model::ParticleNodes::no_node;
    std::size_t size() const { return node_of_.size(); }
    // Particle i's node position in the model's node arrays, `none` when its node is missing.
    std::uint32_t node(std::size_t i) const { return node_of_[i]; }
    double x(std::size_t i) const { return nodes_.x[node(i)]; }
    double y(std::size_t i) const { return nodes_.y[node(i)]; }
    double z(std::size_t i) const { return nodes_.z[node(i)]; }

    // 1 per particle whose node exists, else 0.
    std::vector<std::uint8_t> located() const;
    // Particle i is node i for every particle: all() is then every particle's position, in place.
    bool in_place() const { return node_of_.identity(); }
    PointSpans all() const;
    PointCopy gather(std::span<const std::uint32_t> particles) const;
    PointCopy gather_all() const;  // every particle, in order (each must be located)

private:
    const model::Nodes& nodes_;
    model::ParticleNodes node_of_;
};

}  // namespace sphdeck::preproc
