#include "preproc/collapsed_points.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <utility>

namespace sphdeck::preproc {

namespace {

// A point's identity for collapsing: its coordinates', support's and tolerance's bits (-0.0 and 0.0 stay
// apart: equal places, but collapsing them is not needed for the bound).
using Key = std::array<std::uint64_t, 5>;

std::uint64_t hash_of(const Key& key) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (const std::uint64_t v : key) {
        h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
        h *= 0xFF51AFD7ED558CCDull;
    }
    return h ^ (h >> 33);
}

}  // namespace

CollapsedPoints collapse_coincident(const NeighbourGrid& g, const GroupedRadii& radii, std::uint32_t least) {
    CollapsedPoints out;
    const std::size_t n = g.size();
    if (least < 2 || n < least) return out;
    const auto key_of = [&](std::uint32_t k) {
        const std::uint32_t group = radii.group[g.order()[k]];
        return Key{std::bit_cast<std::uint64_t>(g.x()[k]), std::bit_cast<std::uint64_t>(g.y()[k]),
                   std::bit_cast<std::uint64_t>(g.z()[k]), std::bit_cast<std::uint64_t>(radii.support[group]),
                   std::bit_cast<std::uint64_t>(radii.tolerance[group])};
    };
    // Per input point: the input point that stands for its set (the set's smallest), or itself. A crowded cell's
    // points are sorted by a hash of their key first (16 bytes a point, not 48), and only runs of one hash
    // long enough by the key itself.
    std::vector<std::uint32_t> head;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> hashed;
    std::vector<std::uint32_t> run;
    const auto by_key = [&](std::uint32_t a, std::uint32_t b) {
        const Key ka = key_of(a), kb = key_of(b);
        return ka != kb ? ka < kb : g.order()[a] < g.order()[b];
    };
    for (std::size_t o = 0; o < g.occupied(); ++o) {
        const auto [first, last] = g.occupied_range(o);
        if (last - first < least) continue;
        hashed.resize(last - first);
        for (std::uint32_t k = first; k < last; ++k) hashed[k - first] = {hash_of(key_of(k)), k};
        std::sort(hashed.begin(), hashed.end());
        for (std::size_t r = 0; r < hashed.size();) {
            std::size_t e = r + 1;
            while (e < hashed.size() && hashed[e].first == hashed[r].first) ++e;
            if (e - r >= least) {
                run.clear();
                for (std::size_t q = r; q < e; ++q) run.push_back(hashed[q].second);
                std::sort(run.begin(), run.end(), by_key);
                for (std::size_t u = 0; u < run.size();) {
                    std::size_t v = u + 1;
                    const Key ku = key_of(run[u]);
                    while (v < run.size() && key_of(run[v]) == ku) ++v;
                    if (v - u >= least) {
                        if (head.empty()) {
                            head.resize(n);
                            for (std::size_t i = 0; i < n; ++i) head[i] = static_cast<std::uint32_t>(i);
                        }
                        for (std::size_t w = u + 1; w < v; ++w) head[g.order()[run[w]]] = g.order()[run[u]];
                    }
                    u = v;
                }
            }
            r = e;
        }
    }
    if (head.empty()) return out;
    // Collapsed points in input order of their heads; the members in input order by a counting sort.
    out.of.resize(n);
    std::uint32_t collapsed = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (head[i] == i) out.of[i] = collapsed++;
    for (std::size_t i = 0; i < n; ++i) out.of[i] = out.of[head[i]];
    std::vector<std::uint32_t>().swap(head);
    out.weight.assign(collapsed, 0);
    for (std::size_t i = 0; i < n; ++i) ++out.weight[out.of[i]];
    out.member_begin.assign(collapsed + 1, 0);
    for (std::uint32_t c = 0; c < collapsed; ++c) out.member_begin[c + 1] = out.member_begin[c] + out.weight[c];
    out.members.resize(n);
    out.x.resize(collapsed), out.y.resize(collapsed), out.z.resize(collapsed), out.group.resize(collapsed);
    std::vector<std::uint32_t> next(out.member_begin.begin(), out.member_begin.end() - 1);
    for (std::size_t i = 0; i < n; ++i) out.members[next[out.of[i]]++] = static_cast<std::uint32_t>(i);
    // Places from the grid (the input's, copied in cell order): each collapsed point's from any member.
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t i = g.order()[k], c = out.of[i];
        if (out.members[out.member_begin[c]] != i) continue;
        out.x[c] = g.x()[k], out.y[c] = g.y()[k], out.z[c] = g.z()[k], out.group[c] = radii.group[i];
    }
    return out;
}

}  // namespace sphdeck::preproc
