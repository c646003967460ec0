#include "preproc/nearest_neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "preproc/neighbour_grid.hpp"

namespace sphdeck::preproc {

double estimated_spacing(std::span<const double> x, std::span<const double> y, std::span<const double> z) {
    const std::size_t n = x.size();
    if (n == 0) return 0;
    std::array<double, 3> lo{x[0], y[0], z[0]}, hi = lo;
    for (std::size_t i = 1; i < n; ++i) {
        lo[0] = std::min(lo[0], x[i]), hi[0] = std::max(hi[0], x[i]);
        lo[1] = std::min(lo[1], y[i]), hi[1] = std::max(hi[1], y[i]);
        lo[2] = std::min(lo[2], z[i]), hi[2] = std::max(hi[2], z[i]);
    }
    const double largest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    double measure = 1;
    int axes = 0;
    for (int a = 0; a < 3; ++a)
        if (hi[a] - lo[a] > 1e-12 * largest && hi[a] > lo[a]) measure *= hi[a] - lo[a], ++axes;
    if (axes == 0) return 0;
    return std::pow(measure / static_cast<double>(n), 1.0 / axes);
}

namespace {

// The nearest point to sorted point k among sorted [b, e), updating (best2, best).
inline void scan(const NeighbourGrid& g, std::uint32_t k, std::uint32_t b, std::uint32_t e, double& best2,
                 std::uint32_t& best) {
    const double px = g.x()[k], py = g.y()[k], pz = g.z()[k];
    const double *gx = g.x().data(), *gy = g.y().data(), *gz = g.z().data();
    for (std::uint32_t j = b; j < e; ++j) {
        const double dx = px - gx[j], dy = py - gy[j], dz = pz - gz[j];
        const double r2 = dx * dx + dy * dy + dz * dz;
        if (r2 < best2 && j != k) best2 = r2, best = j;
    }
}

// Calls f(begin, end) for the cells at Chebyshev distance exactly `reach` from cell c.
template <typename F>
void for_each_shell_range(const NeighbourGrid& g, std::array<std::uint32_t, 3> c, std::uint32_t reach, F&& f) {
    const auto n = g.cells();
    const long long r = reach;
    for (long long dz = -r; dz <= r; ++dz) {
        const long long iz = c[2] + dz;
        if (iz < 0 || iz >= n[2]) continue;
        for (long long dy = -r; dy <= r; ++dy) {
            const long long iy = c[1] + dy;
            if (iy < 0 || iy >= n[1]) continue;
            const auto cell = [&](long long ix) {
                return g.cell_index(static_cast<std::uint32_t>(ix), static_cast<std::uint32_t>(iy),
                                    static_cast<std::uint32_t>(iz));
            };
            const long long x0 = c[0] - r, x1 = c[0] + r;
            if (dz == -r || dz == r || dy == -r || dy == r) {  // a whole row of the shell
                const long long a = std::max(0LL, x0), b = std::min<long long>(n[0] - 1, x1);
                if (a <= b) f(g.cell_begin(cell(a)), g.cell_end(cell(b)));
            } else {  // the two ends of the row
                if (x0 >= 0) f(g.cell_begin(cell(x0)), g.cell_end(cell(x0)));
                if (x1 < n[0]) f(g.cell_begin(cell(x1)), g.cell_end(cell(x1)));
            }
        }
    }
}

}  // namespace

NearestNeighbours nearest_neighbours_grid(std::span<const double> x, std::span<const double> y,
                                          std::span<const double> z) {
    const std::size_t n = x.size();
    NearestNeighbours out{std::vector<double>(n, 0.0), std::vector<std::uint32_t>(n, NearestNeighbours::none)};
    if (n < 2) return out;
    // About two points per cell: the 27-cell block then nearly always holds the nearest one.
    const NeighbourGrid g(x, y, z, 1.3 * estimated_spacing(x, y, z));
    const auto cells = g.cells();
    for (std::uint32_t iz = 0; iz < cells[2]; ++iz)
        for (std::uint32_t iy = 0; iy < cells[1]; ++iy)
            for (std::uint32_t ix = 0; ix < cells[0]; ++ix) {
                const std::size_t c = g.cell_index(ix, iy, iz);
                for (std::uint32_t k = g.cell_begin(c); k < g.cell_end(c); ++k) {
                    double best2 = std::numeric_limits<double>::infinity();
                    std::uint32_t best = NearestNeighbours::none;
                    const std::array<std::uint32_t, 3> at{ix, iy, iz};
                    g.for_each_block_range(at, 1, [&](std::uint32_t b, std::uint32_t e) { scan(g, k, b, e, best2, best); });
                    // Widen until nothing outside the searched block can be closer.
                    for (std::uint32_t reach = 1; !g.block_covers_grid(at, reach);) {
                        const double clear = g.block_clearance(g.x()[k], g.y()[k], g.z()[k], reach);
                        if (clear > 0 && best2 <= clear * clear) break;
                        ++reach;
                        for_each_shell_range(g, at, reach,
                                             [&](std::uint32_t b, std::uint32_t e) { scan(g, k, b, e, best2, best); });
                    }
                    const std::uint32_t i = g.order()[k];
                    out.distance[i] = std::sqrt(best2);
                    out.index[i] = g.order()[best];
                }
            }
    return out;
}

NearestNeighbours nearest_neighbours_all_pairs(std::span<const double> x, std::span<const double> y,
                                               std::span<const double> z, const std::function<void(double)>& progress) {
    const std::size_t n = x.size();
    NearestNeighbours out{std::vector<double>(n, 0.0), std::vector<std::uint32_t>(n, NearestNeighbours::none)};
    if (n < 2) return out;
    std::vector<double> best2(n, std::numeric_limits<double>::infinity());
    const double pairs = 0.5 * static_cast<double>(n) * static_cast<double>(n - 1);
    double done = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double px = x[i], py = y[i], pz = z[i];
        double bi = best2[i];
        std::uint32_t ki = out.index[i];
        for (std::size_t j = i + 1; j < n; ++j) {
            const double dx = px - x[j], dy = py - y[j], dz = pz - z[j];
            const double r2 = dx * dx + dy * dy + dz * dz;
            if (r2 < bi) bi = r2, ki = static_cast<std::uint32_t>(j);
            if (r2 < best2[j]) best2[j] = r2, out.index[j] = static_cast<std::uint32_t>(i);
        }
        best2[i] = bi, out.index[i] = ki;
        done += static_cast<double>(n - 1 - i);
        if (progress && (i & 1023) == 0) progress(done / pairs);
    }
    for (std::size_t i = 0; i < n; ++i) out.distance[i] = std::sqrt(best2[i]);
    if (progress) progress(1.0);
    return out;
}

namespace {

// Neighbours of sorted point k in sorted [b, e): (within the support, within the tolerance).
template <bool Uniform>
inline void count_range(const NeighbourGrid& g, const double* support, std::uint32_t k, std::uint32_t b,
                        std::uint32_t e, double tol2, unsigned& within, unsigned& close) {
    const double px = g.x()[k], py = g.y()[k], pz = g.z()[k], sk = support[k];
    const double *gx = g.x().data(), *gy = g.y().data(), *gz = g.z().data();
    const double uniform_r2 = sk * sk;
    unsigned w = 0, c = 0;
    for (std::uint32_t j = b; j < e; ++j) {
        const double dx = px - gx[j], dy = py - gy[j], dz = pz - gz[j];
        const double r2 = dx * dx + dy * dy + dz * dz;
        double radius2 = uniform_r2;
        if constexpr (!Uniform) {
            const double r = 0.5 * (sk + support[j]);
            radius2 = r * r;
        }
        w += r2 < radius2;
        c += r2 <= tol2;
    }
    within += w, close += c;
}

template <bool Uniform>
void count_all(const NeighbourGrid& g, const std::vector<double>& support, const std::vector<double>& tolerance,
               std::size_t stride, NeighbourCounts& out) {
    const auto cells = g.cells();
    const auto& order = g.order();
    for (std::uint32_t iz = 0; iz < cells[2]; ++iz)
        for (std::uint32_t iy = 0; iy < cells[1]; ++iy)
            for (std::uint32_t ix = 0; ix < cells[0]; ++ix) {
                const std::size_t c = g.cell_index(ix, iy, iz);
                std::uint32_t k = g.cell_begin(c);
                if (stride > 1) k = static_cast<std::uint32_t>((k + stride - 1) / stride * stride);
                for (; k < g.cell_end(c); k += static_cast<std::uint32_t>(stride)) {
                    const double tol2 = tolerance[k] * tolerance[k];
                    unsigned within = 0, close = 0;
                    g.for_each_block_range({ix, iy, iz}, 1, [&](std::uint32_t b, std::uint32_t e) {
                        count_range<Uniform>(g, support.data(), k, b, e, tol2, within, close);
                    });
                    if (support[k] > 0) --within;  // itself, at distance 0
                    out.count[order[k]] = within;
                    if (close > 1)  // itself and at least one other point: name them
                        g.for_each_block_range({ix, iy, iz}, 1, [&](std::uint32_t b, std::uint32_t e) {
                            for (std::uint32_t j = b; j < e; ++j) {
                                const double dx = g.x()[k] - g.x()[j], dy = g.y()[k] - g.y()[j],
                                             dz = g.z()[k] - g.z()[j];
                                if (j != k && dx * dx + dy * dy + dz * dz <= tol2)
                                    out.coincident.emplace_back(std::min(order[k], order[j]), std::max(order[k], order[j]));
                            }
                        });
                }
            }
    if (stride > 1)  // the others copy the last counted point before them in cell order
        for (std::size_t k = 0; k < order.size(); ++k)
            if (k % stride) out.count[order[k]] = out.count[order[k - k % stride]];
}

}  // namespace

NeighbourCounts count_neighbours(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                                 std::span<const double> support, std::span<const double> tolerance,
                                 double pair_budget) {
    const std::size_t n = x.size();
    NeighbourCounts out;
    out.count.assign(n, 0);
    if (n == 0) return out;
    double cell = 0;
    for (std::size_t i = 0; i < n; ++i) cell = std::max({cell, support[i], tolerance[i]});
    if (cell <= 0) cell = estimated_spacing(x, y, z);
    const NeighbourGrid g(x, y, z, cell);
    const auto& order = g.order();
    std::vector<double> s(n), t(n);
    bool uniform = true;
    for (std::size_t k = 0; k < n; ++k) {
        s[k] = support[order[k]], t[k] = tolerance[order[k]];
        uniform = uniform && s[k] == s[0];
    }
    // The distance evaluations a full count would take: points per cell times points in its block.
    double work = 0;
    const auto cells = g.cells();
    for (std::uint32_t iz = 0; iz < cells[2]; ++iz)
        for (std::uint32_t iy = 0; iy < cells[1]; ++iy)
            for (std::uint32_t ix = 0; ix < cells[0]; ++ix) {
                const std::size_t c = g.cell_index(ix, iy, iz);
                const double here = g.cell_end(c) - g.cell_begin(c);
                if (here == 0) continue;
                double block = 0;
                g.for_each_block_range({ix, iy, iz}, 1, [&](std::uint32_t b, std::uint32_t e) { block += e - b; });
                work += here * block;
            }
    out.sample_stride = work > pair_budget ? static_cast<std::size_t>(std::ceil(work / pair_budget)) : 1;
    if (uniform) count_all<true>(g, s, t, out.sample_stride, out);
    else count_all<false>(g, s, t, out.sample_stride, out);
    std::sort(out.coincident.begin(), out.coincident.end());
    out.coincident.erase(std::unique(out.coincident.begin(), out.coincident.end()), out.coincident.end());
    return out;
}

std::vector<std::uint32_t> count_neighbours_all_pairs(std::span<const double> x, std::span<const double> y,
                                                      std::span<const double> z, std::span<const double> support) {
    const std::size_t n = x.size();
    std::vector<std::uint32_t> count(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            if (i == j) continue;
            const double dx = x[i] - x[j], dy = y[i] - y[j], dz = z[i] - z[j];
            const double r = support[i] == support[j] ? support[i] : 0.5 * (support[i] + support[j]);
            if (dx * dx + dy * dy + dz * dz < r * r) ++count[i];
        }
    return count;
}

}  // namespace sphdeck::preproc
