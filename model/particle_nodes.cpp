#include "model/particle_nodes.hpp"

#include <optional>

namespace sphdeck::model {

namespace {

// Position of `id` in a sequence column (first + step * k, step != 0), as IdIndex finds it.
std::optional<long long> position_in_sequence(const IdColumn& ids, long long id) {
    const long long offset = id - ids.sequence_first(), step = ids.sequence_step();
    if (offset % step != 0) return std::nullopt;
    const long long k = offset / step;
    if (k < 0 || static_cast<std::size_t>(k) >= ids.size()) return std::nullopt;
    return k;
}

// Whether particle i's node is at first + step * i for every particle (`first` and `step` then set): both id
// columns sequences, the particles' first and last nodes found, and the particles' step a whole number of the
// nodes' steps. Node id v is at (v - nodes' first) / nodes' step when that divides and lies inside; for
// v = a + b * i that is the position of a plus (b / nodes' step) * i, inside for every i once inside for the
// first and the last (it moves one way).
bool sequences_line_up(const IdColumn& ids, const IdColumn& named, long long& first, long long& step) {
    const std::size_t n = named.size();
    if (n == 0 || !ids.sequence() || !named.sequence() || ids.sequence_step() == 0) return false;
    const long long node_step = ids.sequence_step(), particle_step = named.sequence_step();
    // Ids of a sequence are 4-byte values (IdColumn::fits): no difference below overflows.
    if (particle_step % node_step != 0) return false;
    const std::optional<long long> at_first = position_in_sequence(ids, named[0]);
    const std::optional<long long> at_last = position_in_sequence(ids, named[n - 1]);
    if (!at_first || !at_last) return false;
    first = *at_first, step = particle_step / node_step;
    // The last particle's position by the formula is the one found (a check of the reasoning above, for free;
    // then no entry's position overflows: each lies between the first and the last).
    long long span = 0;
    return !__builtin_mul_overflow(step, static_cast<long long>(n - 1), &span) && first + span == *at_last;
}

// Particle i names node i for every i, and no earlier node has its id (ids rising: the index would find no
// earlier copy), so the node index would map every particle to itself.
bool particles_in_node_order(const IdColumn& ids, const IdColumn& named) {
    const std::size_t n = named.size();
    if (n > ids.size()) return false;
    bool in_order = true;
#pragma omp parallel for reduction(&& : in_order) schedule(static) if (n > 65536)
    for (std::size_t i = 0; i < n; ++i) in_order = in_order && ids[i] == named[i] && (i == 0 || ids[i - 1] < ids[i]);
    return in_order;
}

}  // namespace

ParticleNodes::ParticleNodes(const Model& model, const IdIndex* index) : size_(model.particles.size()) {
    const IdColumn &ids = model.nodes.id, &named = model.particles.node;
    if (size_ == 0) return;
    long long first = 0, step = 0;
    if (sequences_line_up(ids, named, first, step)) {
        first_ = first, step_ = step;
        return;
    }
    if (particles_in_node_order(ids, named)) return;  // first_ 0, step_ 1
    std::optional<IdIndex> own;
    if (!index) index = &own.emplace(ids);
    table_.assign(size_, no_node);
#pragma omp parallel for schedule(static) if (size_ > 65536)
    for (std::size_t i = 0; i < size_; ++i)
        if (const auto k = index->find(named[i])) table_[i] = static_cast<std::uint32_t>(*k);
}

}  // namespace sphdeck::model
