#include "lint/particle_groups.hpp"

#include <algorithm>

namespace sphdeck::lint {

std::string ParticleGroup::ids(const model::Particles& p) const {
    std::string s;
    for (std::size_t k = 0; k < first.size(); ++k) s += (k ? ", " : "") + std::to_string(p.node[first[k]]);
    return count > first.size() ? s + ", ..." : s;
}

ParticleGroup PartGroups::merged() const {
    ParticleGroup all;
    std::vector<std::size_t> firsts;
    for (const auto& [part, g] : by_part) {
        all.count += g.count;
        firsts.insert(firsts.end(), g.first.begin(), g.first.end());
    }
    // The first particles of the deck, whichever parts they name.
    std::sort(firsts.begin(), firsts.end());
    firsts.resize(std::min(firsts.size(), max_listed));
    all.first = std::move(firsts);
    return all;
}

std::string PartGroups::part_list() const {
    std::string s;
    std::size_t k = 0;
    for (const auto& [part, g] : by_part) {
        if (k == max_listed) return s + ", ...";
        s += (k++ ? ", " : "") + std::to_string(part);
    }
    return s;
}

void add_line_notes(RuleContext& c, diag::Diagnostic& d, const ParticleGroup& g,
                    const std::function<std::string(std::size_t)>& what) {
    for (std::size_t k = 1; k < g.first.size(); ++k) d.notes.push_back({c.particle_span(g.first[k]), what(g.first[k])});
}

}  // namespace sphdeck::lint
