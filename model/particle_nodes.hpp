// Each particle's node: its position in model.nodes, or no_node where the node is missing (REF001), the node
// index's answer (IdIndex::find). One lookup for the rules (lint::RuleContext::particle_nodes) and the
// geometry (preproc::ParticlePositions). Kept without a table of 4 bytes a particle (4 MB a million, issue 40)
// where a formula gives it: particle i on node first + step * i when both id columns are sequences that line
// up (model/id_column.hpp: a generated mesh's ids, kept as runs), or on node i when the particles name the
// nodes in their order (the same on a deck too small for its ids to be kept as sequences). Else the table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/id_index.hpp"
#include "model/model.hpp"

namespace sphdeck::model {

class ParticleNodes {
public:
    static constexpr std::uint32_t no_node = 0xFFFFFFFFu;

    // `index`: the node ids' index when the caller has one; else one is built if a table is needed. The table
    // is filled on several threads when the particles are many.
    explicit ParticleNodes(const Model& model, const IdIndex* index = nullptr);

    std::size_t size() const { return size_; }
    std::uint32_t operator[](std::size_t i) const {
        if (table_.empty()) return static_cast<std::uint32_t>(first_ + step_ * static_cast<long long>(i));
        return table_[i];
    }
    // Given by first + step * i (no table), so every particle's node exists.
    bool arithmetic() const { return size_ > 0 && table_.empty(); }
    // No particle's node is missing.
    bool all_found() const { return table_.empty(); }
    // Particle i on node i for every particle (none at all included).
    bool identity() const { return table_.empty() && first_ == 0 && step_ == 1; }

private:
    std::size_t size_ = 0;
    long long first_ = 0, step_ = 1;    // position of particle 0's node, and the step from one to the next
    std::vector<std::uint32_t> table_;  // empty when a formula gives the positions (or no particle)
};

}  // namespace sphdeck::model
