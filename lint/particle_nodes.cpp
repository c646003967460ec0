#include "lint/particle_nodes.hpp"

#include <optional>

namespace sphdeck::lint {

namespace {

// Whether particle i's node is at first + step * i in model.nodes for every particle, with `first` and
// `step` set: both id columns sequences, the particles' first and last nodes found, and the particles'
// step a whole number of the nodes' steps. The index finds id v at (v - nodes' first) / nodes' step when
// that divides and lies inside; for v = a + b * i that is the position of a plus (b / nodes' step) * i,
// inside for every i once inside for the first and the last (it moves one way).
bool arithmetic_positions(const model::Model& model, const model::IdIndex& nodes, long long& first, long long& step) {
    const model::IdColumn& ids = model.nodes.id;
    const model::IdColumn& named = model.particles.node;
    const std::size_t n = named.size();
    if (n == 0 || !ids.sequence() || !named.sequence() || ids.sequence_step() == 0) return false;
    const long long node_step = ids.sequence_step(), particle_step = named.sequence_step();
    if (particle_step % node_step != 0) return false;
    const std::optional<std::size_t> at_first = nodes.find(named[0]), at_last = nodes.find(named[n - 1]);
    if (!at_first || !at_last) return false;
    first = static_cast<long long>(*at_first);
    step = particle_step / node_step;
    // The last particle's position by the formula is the one the index found (a check of the reasoning above,
    // for free; and then no entry's position overflows: each lies between the first and the last).
    long long span = 0;
    return !__builtin_mul_overflow(step, static_cast<long long>(n - 1), &span) &&
           first + span == static_cast<long long>(*at_last);
}

}  // namespace

ParticleNodes::ParticleNodes(const model::Model& model, const model::IdIndex& nodes) : size_(model.particles.size()) {
    if (arithmetic_positions(model, nodes, first_, step_)) return;
    table_.assign(size_, no_node);
    const model::IdColumn& named = model.particles.node;
#pragma omp parallel for schedule(static) if (size_ > 65536)
    for (std::size_t i = 0; i < size_; ++i)
        if (const auto k = nodes.find(named[i])) table_[i] = static_cast<std::uint32_t>(*k);
}

}  // namespace sphdeck::lint
