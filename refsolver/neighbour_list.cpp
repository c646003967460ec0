#include "refsolver/neighbour_list.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <omp.h>
#include <span>

#include "preproc/neighbour_grid.hpp"

namespace sphdeck::refsolver {

namespace {

using preproc::NeighbourGrid;

// Fills `c` with the candidates of `grid` (ScanCandidates, neighbour_list.hpp), reusing its arrays.
void fill(ScanCandidates& c, const NeighbourGrid& grid, const std::array<double, 3>& origin, int threads,
          const auto& usable_of, const auto& id_of) {
    const std::size_t n = grid.size();
    c.x.resize(n + 4), c.y.resize(n + 4), c.z.resize(n + 4), c.usable.resize(n + 4), c.id.resize(n + 4);
    for (std::size_t q = n; q < n + 4; ++q) c.x[q] = c.y[q] = c.z[q] = 0.0f, c.usable[q] = 0, c.id[q] = 0;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t q = 0; q < n; ++q) {
        c.x[q] = static_cast<float>(grid.x()[q] - origin[0]);
        c.y[q] = static_cast<float>(grid.y()[q] - origin[1]);
        c.z[q] = static_cast<float>(grid.z()[q] - origin[2]);
        c.usable[q] = usable_of(q), c.id[q] = id_of(q);
    }
}

using float4 = float __attribute__((vector_size(16)));
using int4 = std::int32_t __attribute__((vector_size(16)));

// Appends to `out` (from `used` on) the usable candidates b..e within r2 of p. Four distances at a
// time in single precision (r2 carries a margin for the rounding: the lists may hold a few pairs
// just beyond the radius, never miss one); branch-free: every candidate is written and the count
// advances only for a hit (a hit/miss branch would be mispredicted about one time in four).
void scan(const ScanCandidates& c, std::uint32_t b, std::uint32_t e, const float p[3], float r2,
          std::vector<std::uint32_t>& out, std::size_t& used) {
    if (used + (e - b) + 4 > out.size()) out.resize(std::max(2 * out.size(), used + (e - b) + 4));
    std::uint32_t* o = out.data() + used;
    std::size_t n = 0;
    const float4 px = {p[0], p[0], p[0], p[0]}, py = {p[1], p[1], p[1], p[1]}, pz = {p[2], p[2], p[2], p[2]};
    const float4 limit = {r2, r2, r2, r2};
    for (std::uint32_t q = b; q < e; q += 4) {
        float4 dx, dy, dz;
        std::memcpy(&dx, c.x.data() + q, sizeof dx), std::memcpy(&dy, c.y.data() + q, sizeof dy);
        std::memcpy(&dz, c.z.data() + q, sizeof dz);
        dx = px - dx, dy = py - dy, dz = pz - dz;
        const int4 hit = dx * dx + dy * dy + dz * dz < limit;  // -1 or 0 per lane
        for (std::uint32_t l = 0; l < 4; ++l) {
            o[n] = c.id[q + l];
            n += static_cast<std::size_t>(hit[l] & c.usable[q + l] & (q + l < e));
        }
    }
    used += n;
}

// The first occupied cell of each thread's share: about real / team particles each.
std::vector<std::size_t> split_cells(const NeighbourGrid& grid, std::size_t points, int team) {
    std::vector<std::size_t> first(static_cast<std::size_t>(team) + 1, grid.occupied());
    first[0] = 0;
    for (int t = 1; t < team; ++t) {
        const std::size_t target = points * static_cast<std::size_t>(t) / static_cast<std::size_t>(team);
        std::size_t lo = 0, hi = grid.occupied();
        while (lo < hi) {  // first cell whose range starts at or after `target`
            const std::size_t mid = (lo + hi) / 2;
            if (grid.occupied_range(mid).first < target)
                lo = mid + 1;
            else
                hi = mid;
        }
        first[static_cast<std::size_t>(t)] = lo;
    }
    return first;
}

}  // namespace

void NeighbourList::build(Particles& s, double search_radius, int threads, bool full) {
    radius = search_radius;
    ++builds;
    const std::size_t real = s.real, ghosts = s.ghosts();
    const int team = threads > 0 ? threads : omp_get_max_threads();

    // Bin the real particles and sort them into cell order: index k is then sorted position k.
    const NeighbourGrid grid(std::span<const double>(s.x.data(), real), std::span<const double>(s.y.data(), real),
                             std::span<const double>(s.z.data(), real), 0.5 * radius);
    s.permute(grid.order(), team);
    // The ghosts on a grid of their own (same cell size), scanned only by particles near a plane.
    const NeighbourGrid ghost_grid(std::span<const double>(s.x.data() + real, ghosts),
                                   std::span<const double>(s.y.data() + real, ghosts),
                                   std::span<const double>(s.z.data() + real, ghosts), 0.5 * radius);
    std::vector<std::uint8_t>& near_plane = near_plane_;
    near_plane.assign(real, 0);
    for (std::size_t k = 0; k < ghosts; ++k) near_plane[s.ghost_source[k]] = 1;

    // Single-precision candidates relative to the centre of the domain; the radius gets a margin of
    // a few float roundings of the largest coordinate.
    std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
    for (int a = 0; a < 3; ++a) {
        const std::vector<double>& v = a == 0 ? s.x : a == 1 ? s.y : s.z;
        const auto [l, h] = std::minmax_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(s.total()));
        if (s.total() > 0 && std::isfinite(*l) && std::isfinite(*h)) lo[a] = *l, hi[a] = *h;
    }
    const std::array<double, 3> centre{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
    const double half = 0.5 * std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    const float r2 = static_cast<float>(std::pow(radius + 4e-6 * (half + radius), 2));
    ScanCandidates &reals = reals_, &images = images_;
    fill(
        reals, grid, centre, team, [&](std::size_t q) { return s.active[q]; },
        [](std::size_t q) { return static_cast<std::uint32_t>(q); });
    fill(
        images, ghost_grid, centre, team,
        [&](std::size_t q) { return s.active[s.ghost_source[ghost_grid.order()[q]]]; },
        [&](std::size_t q) { return static_cast<std::uint32_t>(real + ghost_grid.order()[q]); });

    const std::vector<std::size_t> first_cell = split_cells(grid, real, team);
    forward_offsets.assign(real + 1, 0);
    ghost_offsets.assign(real + 1, 0);
    chunks_.resize(static_cast<std::size_t>(team));
    std::vector<std::size_t> forward_used(static_cast<std::size_t>(team)), ghost_used(forward_used);
    const NeighbourGrid::Cell n = grid.cells();

#pragma omp parallel num_threads(team)
    {
        const auto t = static_cast<std::size_t>(omp_get_thread_num());
        Chunk& mine = chunks_[t];
        std::size_t fu = 0, gu = 0;
        for (std::size_t o = first_cell[t]; o < first_cell[t + 1]; ++o) {
            const auto [first, last] = grid.occupied_range(o);
            const NeighbourGrid::Cell c = grid.occupied_cell(o);
            const std::uint32_t x0 = c[0] >= 2 ? c[0] - 2 : 0, x1 = std::min(c[0] + 2, n[0] - 1);
            // The forward half of the 5x5 block of rows: rows further along z, or along y in the same z.
            NeighbourGrid::Range rows[12];
            int row_count = 0;
            for (std::uint32_t dz = 0; dz <= 2; ++dz)
                for (int dy = -2; dy <= 2; ++dy) {
                    if (dz == 0 && dy <= 0) continue;
                    const long long iy = static_cast<long long>(c[1]) + dy, iz = static_cast<long long>(c[2]) + dz;
                    if (iy < 0 || iy >= n[1] || iz >= n[2]) continue;
                    rows[row_count++] =
                        grid.row_range(x0, x1, static_cast<std::uint32_t>(iy), static_cast<std::uint32_t>(iz));
                }
            const std::uint32_t own_row_end = grid.row_range(c[0], x1, c[1], c[2]).second;
            for (std::uint32_t i = first; i < last; ++i) {
                if (s.active[i]) {
                    const float p[3] = {reals.x[i], reals.y[i], reals.z[i]};
                    // Same row: the rest of this cell and the next two cells along x.
                    scan(reals, i + 1, own_row_end, p, r2, mine.forward, fu);
                    for (int r = 0; r < row_count; ++r)
                        scan(reals, rows[r].first, rows[r].second, p, r2, mine.forward, fu);
                    if (near_plane[i])
                        ghost_grid.for_each_block_range(ghost_grid.cell_of(s.x[i], s.y[i], s.z[i]), 2,
                                                        [&](std::uint32_t b, std::uint32_t e) {
                                                            scan(images, b, e, p, r2, mine.ghost, gu);
                                                        });
                }
                forward_offsets[i + 1] = static_cast<std::uint32_t>(fu);  // per-thread running counts for now
                ghost_offsets[i + 1] = static_cast<std::uint32_t>(gu);
            }
        }
        forward_used[t] = fu, ghost_used[t] = gu;
    }

    // Per-thread running counts to global offsets: each thread's particles are one contiguous
    // range, so its list is one contiguous block of the CSR arrays.
    std::vector<std::size_t> first_particle(static_cast<std::size_t>(team) + 1, real);
    for (int t = 0; t < team; ++t) {
        const std::size_t o = first_cell[static_cast<std::size_t>(t)];
        first_particle[static_cast<std::size_t>(t)] = o < grid.occupied() ? grid.occupied_range(o).first : real;
    }
    std::vector<std::size_t> forward_base(static_cast<std::size_t>(team) + 1, 0), ghost_base(forward_base);
    for (std::size_t t = 0; t < static_cast<std::size_t>(team); ++t)
        forward_base[t + 1] = forward_base[t] + forward_used[t], ghost_base[t + 1] = ghost_base[t] + ghost_used[t];
    if (team == 1) {
        // One chunk: it becomes the list, without a copy; the old list's storage (its full
        // capacity) is the next build's chunk.
        // The spare gets room for a quarter more than this list at once (at the first build, outside
        // the stepping), so that later builds neither grow it nor touch fresh pages.
        forward.swap(chunks_[0].forward), ghost.swap(chunks_[0].ghost);
        forward.resize(forward_used[0]), ghost.resize(ghost_used[0]);
        for (auto [spare, list] : {std::pair{&chunks_[0].forward, &forward}, {&chunks_[0].ghost, &ghost}})
            spare->resize(std::max(spare->capacity(), list->size() + list->size() / 4 + 64));
        if (full)
            fill_full_lists();
        else
            offsets.clear(), neighbours.clear();
        return;
    }
    forward.resize(forward_base.back());
    ghost.resize(ghost_base.back());
#pragma omp parallel num_threads(team)
    {
        const auto t = static_cast<std::size_t>(omp_get_thread_num());
        for (std::size_t i = first_particle[t]; i < first_particle[t + 1]; ++i) {
            forward_offsets[i + 1] += static_cast<std::uint32_t>(forward_base[t]);
            ghost_offsets[i + 1] += static_cast<std::uint32_t>(ghost_base[t]);
        }
        std::copy_n(chunks_[t].forward.begin(), forward_used[t],
                    forward.begin() + static_cast<std::ptrdiff_t>(forward_base[t]));
        std::copy_n(chunks_[t].ghost.begin(), ghost_used[t],
                    ghost.begin() + static_cast<std::ptrdiff_t>(ghost_base[t]));
    }
    // Cells hold at least one particle, so every particle belongs to a thread; offsets[0] = 0.
    if (full)
        fill_full_lists();
    else
        offsets.clear(), neighbours.clear();
}

// Full lists from the half lists: particle i lists its backward partners (ascending), then its
// forward partners, then its ghosts.
void NeighbourList::fill_full_lists() {
    const std::size_t real = forward_offsets.size() - 1;
    offsets.assign(real + 1, 0);
    for (std::uint32_t j : forward) ++offsets[j + 1];  // backward partners of j
    for (std::size_t i = 0; i < real; ++i)
        offsets[i + 1] +=
            offsets[i] + (forward_offsets[i + 1] - forward_offsets[i]) + (ghost_offsets[i + 1] - ghost_offsets[i]);
    neighbours.resize(offsets[real]);
    std::vector<std::uint32_t> cursor(offsets.begin(), offsets.end() - 1);
    for (std::size_t i = 0; i < real; ++i) {
        // Every backward partner of i is smaller than i, so it has been placed already.
        for (std::uint32_t k = forward_offsets[i]; k < forward_offsets[i + 1]; ++k)
            neighbours[cursor[i]++] = forward[k];
        for (std::uint32_t k = ghost_offsets[i]; k < ghost_offsets[i + 1]; ++k) neighbours[cursor[i]++] = ghost[k];
        for (std::uint32_t k = forward_offsets[i]; k < forward_offsets[i + 1]; ++k)
            neighbours[cursor[forward[k]]++] = static_cast<std::uint32_t>(i);
    }
}

}  // namespace sphdeck::refsolver
