// Each particle's node as the rules read it: its position in model.nodes, or no_node where the node is
// missing (REF001). A generated mesh puts particle i on node first + i: both id columns are sequences
// (model/id_column.hpp), and the positions are first + step * i, kept as that instead of a table of
// 4 bytes a particle (4 MB a million, at the preview's peak of memory: issue 40). Any other deck: the table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/id_index.hpp"
#include "model/model.hpp"

namespace sphdeck::lint {

class ParticleNodes {
public:
    static constexpr std::uint32_t no_node = 0xFFFFFFFFu;

    // The particles' nodes found in `nodes`, the index of model.nodes.id; on several threads when they are
    // many and kept as a table.
    ParticleNodes(const model::Model& model, const model::IdIndex& nodes);

    std::size_t size() const { return size_; }
    std::uint32_t operator[](std::size_t i) const {
        if (table_.empty()) return static_cast<std::uint32_t>(first_ + step_ * static_cast<long long>(i));
        return table_[i];
    }
    // Kept as first + step * i (no table): for tests.
    bool arithmetic() const { return size_ > 0 && table_.empty(); }

private:
    std::size_t size_ = 0;
    long long first_ = 0, step_ = 0;    // position of particle 0's node, and the step from one to the next
    std::vector<std::uint32_t> table_;  // empty when arithmetic (or no particle)
};

}  // namespace sphdeck::lint
