#include "refsolver/neighbour_list.hpp"

#include <omp.h>
#include <span>

#include "preproc/neighbour_grid.hpp"

namespace sphdeck::refsolver {

void NeighbourList::build(Particles& s, double search_radius, int threads) {
    radius = search_radius;
    const std::size_t n = s.total(), real = s.real;
    const preproc::NeighbourGrid grid(std::span<const double>(s.x.data(), n), std::span<const double>(s.y.data(), n),
                                      std::span<const double>(s.z.data(), n), 0.5 * radius);
    const std::vector<std::uint32_t>& order = grid.order();

    // Real particles into cell order; `number[k]`: the new index of sorted point k (ghosts keep theirs).
    std::vector<std::uint32_t> permutation;
    permutation.reserve(real);
    for (std::uint32_t old : order)
        if (old < real) permutation.push_back(old);
    s.permute(permutation);
    std::vector<std::uint32_t> renumber(real), number(n);
    for (std::size_t k = 0; k < real; ++k) renumber[permutation[k]] = static_cast<std::uint32_t>(k);
    std::vector<std::uint8_t> usable(n);  // sorted point k may be listed: active (or its source is)
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t old = order[k];
        number[k] = old < real ? renumber[old] : old;
        usable[k] = old < real ? s.active[number[k]] : s.active[s.ghost_source[old - real]];
    }

    const std::vector<double>&gx = grid.x(), &gy = grid.y(), &gz = grid.z();
    const double r2max = radius * radius;
    const int team = threads > 0 ? threads : omp_get_max_threads();
    std::vector<std::vector<std::uint32_t>> local(static_cast<std::size_t>(team));
    std::vector<std::uint32_t> count(real, 0);
    const std::size_t cells = grid.occupied();
#pragma omp parallel num_threads(team)
    {
        std::vector<std::uint32_t>& mine = local[static_cast<std::size_t>(omp_get_thread_num())];
        mine.reserve(real * 64 / static_cast<std::size_t>(team) + 64);
        std::vector<preproc::NeighbourGrid::Range> rows;
        // schedule(static): each thread one contiguous run of cells, so of real particles, in
        // thread order: the per-thread lists concatenate into the CSR arrays.
#pragma omp for schedule(static)
        for (std::size_t o = 0; o < cells; ++o) {
            const auto [first, last] = grid.occupied_range(o);
            rows.clear();
            grid.for_each_block_range(grid.occupied_cell(o), 2,
                                      [&](std::uint32_t b, std::uint32_t e) { rows.emplace_back(b, e); });
            for (std::uint32_t k = first; k < last; ++k) {
                if (order[k] >= real) continue;  // a ghost: it has no list of its own
                const std::uint32_t i = number[k];
                if (!s.active[i]) continue;
                const double px = gx[k], py = gy[k], pz = gz[k];
                const std::size_t before = mine.size();
                for (const auto& [b, e] : rows)
                    for (std::uint32_t q = b; q < e; ++q) {
                        const double dx = px - gx[q], dy = py - gy[q], dz = pz - gz[q];
                        if (dx * dx + dy * dy + dz * dz < r2max && q != k && usable[q]) mine.push_back(number[q]);
                    }
                count[i] = static_cast<std::uint32_t>(mine.size() - before);
            }
        }
    }
    offsets.assign(real + 1, 0);
    for (std::size_t i = 0; i < real; ++i) offsets[i + 1] = offsets[i] + count[i];
    neighbours.resize(offsets[real]);
    std::size_t at = 0;
    for (const auto& part : local) {
        std::copy(part.begin(), part.end(), neighbours.begin() + static_cast<std::ptrdiff_t>(at));
        at += part.size();
    }
}

}  // namespace sphdeck::refsolver
