// Particles that share one problem, and the flood guard of the per-particle rules: a deck of
// millions of particles (or a mesh fragment without its parts) must make a handful of findings,
// each with a count, the first ids and the first lines, never one finding per particle or part.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "lint/rule_context.hpp"

namespace sphdeck::lint {

inline constexpr std::size_t max_listed = 5;  // ids named in one message, lines shown as notes

// Particles that share one problem: how many, the first few, and the first one's index.
struct ParticleGroup {
    std::size_t count = 0;
    std::vector<std::size_t> first;  // particle indices, at most max_listed

    void add(std::size_t i) {
        if (count++ < max_listed) first.push_back(i);
    }
    // "101, 102, 103, ..." (node ids of the first particles).
    std::string ids(const model::Particles& p) const;
};

// Groups keyed by part: when more than max_listed parts have the problem, one merged group (all
// particles, the first parts' ids) replaces them, so a deck where every particle names its own
// part makes one finding.
struct PartGroups {
    std::map<long long, ParticleGroup> by_part;

    void add(long long part, std::size_t i) { by_part[part].add(i); }
    bool flood() const { return by_part.size() > max_listed; }
    ParticleGroup merged() const;   // every particle of every part, in deck order of the groups
    std::string part_list() const;  // "1, 2, 3, 4, 5, ..."
};

// Notes at the lines of a group's particles after the first (the primary span shows the first),
// each saying `what(particle index)`.
void add_line_notes(RuleContext& c, diag::Diagnostic& d, const ParticleGroup& g,
                    const std::function<std::string(std::size_t)>& what);

}  // namespace sphdeck::lint
