#include "preproc/nearest_neighbours.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include "preproc/close_pairs.hpp"
#include "preproc/collapsed_points.hpp"
#include "preproc/count_cell_float.hpp"
#include "preproc/first_pairs.hpp"
#include "preproc/nearest_tree.hpp"
#include "preproc/neighbour_grid.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

// The counting and nearest-neighbour loops vectorise with AVX2 (a double comparison into 64-bit lanes) but not with
// the SSE2 baseline; x86-64 builds carry both and pick one when loaded. GCC and Clang (14 and
// later) both clone plain functions, but Clang refuses target_clones on a function template, so
// the clones are non-template functions. Not under the sanitizers: the ifunc resolver
// runs before their runtime is set up.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer) || __has_feature(coverage_sanitizer)
#define SPHDECK_NO_CLONES 1
#endif
#endif
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__AVX2__) && !defined(__SANITIZE_ADDRESS__) && \
    !defined(SPHDECK_NO_CLONES) && (!defined(__clang__) || __clang_major__ >= 14)
#define SPHDECK_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define SPHDECK_CLONES
#endif

namespace sphdeck::preproc {

namespace {

// Axes the points span, and their bounding-box measure over those axes.
std::pair<int, double> spanned(std::span<const double> x, std::span<const double> y, std::span<const double> z) {
    if (x.empty()) return {0, 0.0};
    std::array<double, 3> lo{x[0], y[0], z[0]}, hi = lo;
    for (std::size_t i = 1; i < x.size(); ++i) {
        lo[0] = std::min(lo[0], x[i]), hi[0] = std::max(hi[0], x[i]);
        lo[1] = std::min(lo[1], y[i]), hi[1] = std::max(hi[1], y[i]);
        lo[2] = std::min(lo[2], z[i]), hi[2] = std::max(hi[2], z[i]);
    }
    const double largest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    double measure = 1;
    int axes = 0;
    for (int a = 0; a < 3; ++a)
        if (hi[a] - lo[a] > 1e-12 * largest && hi[a] > lo[a] && std::isfinite(hi[a] - lo[a]))
            measure *= hi[a] - lo[a], ++axes;
    return {axes, measure};
}

}  // namespace

int pass_threads(std::size_t points) {
#ifdef _OPENMP
    return points < 4096 ? 1 : std::max(1, omp_get_max_threads());
#else
    (void)points;
    return 1;
#endif
}

double estimated_spacing(std::span<const double> x, std::span<const double> y, std::span<const double> z) {
    const auto [axes, measure] = spanned(x, y, z);
    if (axes == 0) return 0;
    return std::pow(measure / static_cast<double>(x.size()), 1.0 / axes);
}

namespace {

// The nearest point to sorted point k among sorted [b, e), updating (best2, best). Branch-free:
// the running minimum changes unpredictably, and a mispredicted branch costs more than a distance.
inline void scan_range(const NeighbourGrid& g, std::uint32_t k, std::uint32_t b, std::uint32_t e, double& best2,
                       std::uint32_t& best) {
    const double px = g.x()[k], py = g.y()[k], pz = g.z()[k];
    const double *gx = g.x().data(), *gy = g.y().data(), *gz = g.z().data();
    double m = best2;
    std::uint32_t at = best;
    for (std::uint32_t j = b; j < e; ++j) {
        const double dx = px - gx[j], dy = py - gy[j], dz = pz - gz[j];
        const double r2 = dx * dx + dy * dy + dz * dz;
        const bool closer = r2 < m;
        m = closer ? r2 : m;
        at = closer ? j : at;
    }
    best2 = m, best = at;
}

// The same, leaving k itself out. Each range starts a running minimum of its own, merged after it:
// the short ranges' minima then overlap in the processor instead of waiting on one chain, and the
// merge keeps the first point of the smallest distance, as one scan in order would.
inline void scan_cells(const NeighbourGrid& g, std::uint32_t k, std::uint32_t b, std::uint32_t e, double& best2,
                       std::uint32_t& best) {
    double m = std::numeric_limits<double>::infinity();
    std::uint32_t at = NearestNeighbours::none;
    if (k >= b && k < e) {
        scan_range(g, k, b, k, m, at);
        scan_range(g, k, k + 1, e, m, at);
    } else {
        scan_range(g, k, b, e, m, at);
    }
    const bool closer = m < best2;
    best2 = closer ? m : best2;
    best = closer ? at : best;
}

// Four doubles, and the 64-bit lanes of a comparison of them (GCC and Clang vector extensions):
// one AVX2 register, two SSE2 ones in the baseline clone.
using Doubles4 = double __attribute__((vector_size(32)));
using Lanes4 = long long __attribute__((vector_size(32)));

// The nearest other point of each point k of one cell's sorted [first, last) in its 3x3x3 block:
// best2[k - first] (squared distance, infinite when none) and best[k - first] (sorted position,
// `none` when none). Four candidates at a time, read in place: a row of the block (about three
// points) is one vector step, its lanes past the row's end masked out, instead of a scalar loop
// whose varying length the processor mispredicts. The rows come in increasing sorted position
// (z, then y, then x), and each lane keeps its first smallest distance, so the smallest over the
// lanes at the lowest position is the point scan_cells finds over the same rows, bit for bit.
SPHDECK_CLONES void nearest_in_block(const NeighbourGrid& g, std::uint32_t first, std::uint32_t last,
                                     std::span<const NeighbourGrid::Range> block, double* best2, std::uint32_t* best) {
    constexpr long long lanes = 4;
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double *gx = g.x().data(), *gy = g.y().data(), *gz = g.z().data();
    const long long n = static_cast<long long>(g.size());
    for (std::uint32_t k = first; k < last; ++k) {
        const Doubles4 px = Doubles4{} + gx[k], py = Doubles4{} + gy[k], pz = Doubles4{} + gz[k];
        const Lanes4 self = Lanes4{} + static_cast<long long>(k), lane = {0, 1, 2, 3};
        Doubles4 m = Doubles4{} + inf;
        Lanes4 at = Lanes4{} - 1;
        double tail2 = inf;  // rows at the very end of the sorted arrays, where a vector would read past them
        std::uint32_t tail = NearestNeighbours::none;
        for (const auto& [b, e] : block) {
            long long j = b;
            for (; j < e && j + lanes <= n; j += lanes) {
                Doubles4 qx, qy, qz;
                std::memcpy(&qx, gx + j, sizeof qx), std::memcpy(&qy, gy + j, sizeof qy);
                std::memcpy(&qz, gz + j, sizeof qz);
                const Doubles4 dx = px - qx, dy = py - qy, dz = pz - qz;
                const Doubles4 r2 = dx * dx + dy * dy + dz * dz;
                const Lanes4 position = lane + j;
                const Lanes4 closer = (r2 < m) & (position < e) & (position != self);  // never for NaN
                m = (Doubles4)(((Lanes4)r2 & closer) | ((Lanes4)m & ~closer));
                at = (position & closer) | (at & ~closer);
            }
            if (j < e) {  // within the last three points: one scalar scan, merged in order below
                double t2 = inf;
                std::uint32_t t = NearestNeighbours::none;
                if (k >= j && k < e) {
                    scan_range(g, k, static_cast<std::uint32_t>(j), k, t2, t);
                    scan_range(g, k, k + 1, e, t2, t);
                } else {
                    scan_range(g, k, static_cast<std::uint32_t>(j), e, t2, t);
                }
                if (t2 < tail2) tail2 = t2, tail = t;
            }
        }
        // Each lane holds its first smallest; the smallest over lanes, then the lowest position.
        double b2 = inf;
        long long bp = -1;
        for (unsigned l = 0; l < lanes; ++l)
            if (at[l] >= 0 && (m[l] < b2 || (m[l] == b2 && at[l] < bp))) b2 = m[l], bp = at[l];
        // The tail's points come after every vector's (the highest positions): they win only when closer.
        if (tail2 < b2) b2 = tail2, bp = tail;
        best2[k - first] = b2;
        best[k - first] = bp < 0 ? NearestNeighbours::none : static_cast<std::uint32_t>(bp);
    }
}

// Calls f(begin, end) for the cells at Chebyshev distance exactly `reach` from cell c; returns the rows
// looked up.
template <typename F>
std::uint64_t for_each_shell_range(const NeighbourGrid& g, NeighbourGrid::Cell c, std::uint32_t reach, F&& f) {
    std::uint64_t rows = 0;
    const auto n = g.cells();
    const long long r = reach;
    const long long x0 = c[0] - r, x1 = c[0] + r;
    for (long long dz = -r; dz <= r; ++dz) {
        const long long iz = c[2] + dz;
        if (iz < 0 || iz >= n[2]) continue;
        for (long long dy = -r; dy <= r; ++dy) {
            const long long iy = c[1] + dy;
            if (iy < 0 || iy >= n[1]) continue;
            const auto row = [&](long long a, long long b) {
                ++rows;
                const auto [begin, end] = g.row_range(static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b),
                                                      static_cast<std::uint32_t>(iy), static_cast<std::uint32_t>(iz));
                if (begin != end) f(begin, end);
            };
            if (dz == -r || dz == r || dy == -r || dy == r) {  // a whole row of the shell
                const long long a = std::max(0LL, x0), b = std::min<long long>(n[0] - 1, x1);
                if (a <= b) row(a, b);
            } else {  // the two ends of the row
                if (x0 >= 0) row(x0, x0);
                if (x1 < n[0]) row(x1, x1);
            }
        }
    }
    return rows;
}

// A spacing from the interquartile box: (product of the quartile ranges / (n / 2^d))^(1/d) over
// the axes with a range. Blind to a few far points, which the bounding box is not.
double quartile_spacing(std::span<const double> x, std::span<const double> y, std::span<const double> z) {
    double measure = 1;
    int axes = 0;
    for (auto axis : {x, y, z}) {
        std::vector<double> v(axis.begin(), axis.end());
        const std::size_t q1 = v.size() / 4, q3 = 3 * v.size() / 4;
        std::nth_element(v.begin(), v.begin() + q1, v.end());
        const double a = v[q1];
        std::nth_element(v.begin() + q1, v.begin() + q3, v.end());
        if (v[q3] - a > 0 && std::isfinite(v[q3] - a)) measure *= v[q3] - a, ++axes;
    }
    if (axes == 0) return 0;
    return std::pow(measure * std::pow(2.0, axes) / static_cast<double>(x.size()), 1.0 / axes);
}

// A grid with about one point per occupied cell: the bounding-box spacing first; when the points
// crowd into part of the box (a stray point, far-apart clusters), the quartile spacing, then
// refinements by the crowding measured.
NeighbourGrid nearest_neighbour_grid(std::span<const double> x, std::span<const double> y, std::span<const double> z) {
    const int axes = spanned(x, y, z).first;
    // The points read in place when in cell order already (a generated lattice in node order): the search's
    // grid lives no longer than x, y, z.
    NeighbourGrid g(x, y, z, estimated_spacing(x, y, z), true);
    for (int refine = 0; refine < 4 && axes > 0; ++refine) {
        const double crowding = g.crowding();
        if (crowding <= 3.0) break;
        double cell = g.cell_size() * std::pow(1.5 / crowding, 1.0 / axes);
        if (refine == 0) {
            const double quartile = quartile_spacing(x, y, z);
            if (quartile > 0) cell = std::min(cell, quartile);
        }
        g = NeighbourGrid(x, y, z, cell, true);
    }
    return g;
}

// Where the grid walk hands a point to the tree (nearest_tree.hpp): a 3x3x3 block of more points than this
// (a crowded cell: a lattice's block holds about 27), a walk that may pass this reach (a lattice point's
// stops at reach 1 or 2), or shells of more points than this. Each bounds the walk's work a point.
constexpr std::uint32_t walk_block_points = 256;
constexpr std::uint32_t walk_reach = 3;
constexpr std::uint32_t walk_shell_points = 256;
// Up to this many points left to the tree, a scan of every point each instead (stray points): a scan costs
// about a nanosecond a point, building the tree about 300 (measured at 1M points).
constexpr std::size_t scanned_points = 128;

// The nine rows of the 3x3x3 block around a cell.
constexpr NeighbourGrid::RowOffset block_rows[] = {{-1, 1, -1, -1}, {-1, 1, 0, -1}, {-1, 1, 1, -1},
                                                   {-1, 1, -1, 0},  {-1, 1, 0, 0},  {-1, 1, 1, 0},
                                                   {-1, 1, -1, 1},  {-1, 1, 0, 1},  {-1, 1, 1, 1}};

// The 25 rows of the 5x5x5 block: on a hashed grid the walk's second shell comes from these, through
// cursors that step through the occupied cells (once a cell that needs them), rather than from a hash
// look-up per cell of the shell and point (a lattice with a stray point, or blobs: cells smaller than the
// spacing, and many points need that shell).
constexpr auto reach_two_rows = [] {
    std::array<NeighbourGrid::RowOffset, 25> rows{};
    for (int dz = -2, r = 0; dz <= 2; ++dz)
        for (int dy = -2; dy <= 2; ++dy) rows[static_cast<std::size_t>(r++)] = {-2, 2, dy, dz};
    return rows;
}();

// The search; `walk_only`: every point walks its shells to the end, as before the tree (tests' reference).
NearestNeighbours nearest_neighbours(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                                     NearestWork* work, bool walk_only) {
    const std::size_t n = x.size();
    if (n < 2) return {std::vector<double>(n, 0.0), std::vector<std::uint32_t>(n, NearestNeighbours::none)};
    // The results before the grid: in a heap that keeps freed memory (text/big_file_heap.hpp) the grid,
    // freed last, leaves its pages at the heap's top, where the counts' grid takes them again; allocated
    // after the grid, the results would split that space (2.5 MB more at the peak, 1M-particle deck).
    NearestNeighbours out{std::vector<double>(n, 0.0), std::vector<std::uint32_t>(n, NearestNeighbours::none)};
    const NeighbourGrid g = nearest_neighbour_grid(x, y, z);
    const auto put = [&](std::uint32_t k, double best2, std::uint32_t best) {
        const std::uint32_t i = g.order()[k];
        out.distance[i] = std::sqrt(best2);
        out.index[i] = best == NearestNeighbours::none ? best : g.order()[best];
    };
    const std::uint32_t most_block_points = walk_only ? NearestNeighbours::none : walk_block_points;
    const std::uint64_t most_shell_points = walk_only ? std::uint64_t(-1) : walk_shell_points;
    // Each point's search is its own and writes only its own entry: contiguous runs of cells
    // go to the threads, and the numbers are those of one thread. The points whose walk would be long
    // (a crowded block, a nearest neighbour shells away) are left to a tree afterwards (nearest_tree.hpp).
    const int threads = pass_threads(n);
    const std::size_t cells = g.occupied();
    std::vector<std::vector<std::uint32_t>> left(static_cast<std::size_t>(threads));
    std::uint64_t distances = 0, rows = 0;
#pragma omp parallel for num_threads(threads) schedule(static, 1) if (threads > 1) reduction(+ : distances, rows)
    for (int t = 0; t < threads; ++t) {
        const std::size_t from = cells * static_cast<std::size_t>(t) / static_cast<std::size_t>(threads);
        const std::size_t to = cells * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(threads);
        std::vector<std::uint32_t>& later = left[static_cast<std::size_t>(t)];
        std::vector<double> cell_best2;
        std::vector<std::uint32_t> cell_best;
        std::vector<NeighbourGrid::Range> shell;
        std::array<std::size_t, reach_two_rows.size()> reach_two_cursor{};
        std::vector<NeighbourGrid::Range> reach_two;  // the cell's, once a point of it needs them
        g.for_each_cell_rows(block_rows, from, to, [&](std::size_t o, NeighbourGrid::Cell at, const auto& block) {
            reach_two.clear();
            const auto [first, last] = g.occupied_range(o);
            std::uint32_t block_points = 0;
            for (const auto& [b, e] : block) block_points += e - b;
            rows += std::size(block_rows);
            if (block_points > most_block_points) {
                for (std::uint32_t k = first; k < last; ++k) later.push_back(k);
                return;
            }
            distances += std::uint64_t{block_points} * (last - first);
            const NeighbourGrid::BlockBounds block_bounds = g.block_bounds(at, 1);  // the cell's, not per point
            const bool covers_at_one = g.block_covers_grid(at, 1);
            cell_best2.resize(last - first), cell_best.resize(last - first);
            nearest_in_block(g, first, last, block, cell_best2.data(), cell_best.data());
            for (std::uint32_t k = first; k < last; ++k) {
                double best2 = cell_best2[k - first];
                std::uint32_t best = cell_best[k - first];
                // Most walks end with the block (the loop below, at reach 1, in short).
                const double clear = covers_at_one ? 0.0 : block_bounds.clearance(g.x()[k], g.y()[k], g.z()[k]);
                if (covers_at_one || (clear > 0 && best2 <= clear * clear)) {
                    put(k, best2, best);
                    continue;
                }
                // A walk that may pass walk_reach (its best so far farther than that block's clearance): the
                // tree at once, not after crossing shells of cells, which cost most when the cells are small.
                if (!walk_only && !g.block_covers_grid(at, walk_reach)) {
                    const double reach_clear = g.block_clearance(g.x()[k], g.y()[k], g.z()[k], at, walk_reach);
                    if (!(reach_clear > 0 && best2 <= reach_clear * reach_clear)) {
                        later.push_back(k);
                        continue;
                    }
                }
                // Widen shell by shell until nothing outside the searched block can be closer; when the
                // next block would hold more cells than there are points, scan all points instead; shells
                // of more than most_shell_points, the tree decides.
                std::uint64_t walked = 0;
                bool done = true;
                for (std::uint32_t reach = 1; !g.block_covers_grid(at, reach); ++reach) {
                    const double clear = reach == 1 ? block_bounds.clearance(g.x()[k], g.y()[k], g.z()[k])
                                                    : g.block_clearance(g.x()[k], g.y()[k], g.z()[k], at, reach);
                    if (clear > 0 && best2 <= clear * clear) break;
                    if (g.block_cells(at, reach + 1) > static_cast<double>(n)) {
                        scan_cells(g, k, 0, static_cast<std::uint32_t>(n), best2, best);
                        distances += n;
                        break;
                    }
                    shell.clear();
                    if (reach == 1 && g.hashed() && !walk_only) {
                        // The 5x5x5 block's rows: its inner block's points again too, none of them closer than
                        // best2 (the least over them), so the strict comparison leaves them out as before.
                        if (reach_two.empty()) {
                            for (std::size_t r = 0; r < reach_two_rows.size(); ++r)
                                reach_two.push_back(g.offset_row_range(reach_two_rows[r], at, reach_two_cursor[r]));
                            rows += reach_two_rows.size();
                        }
                        shell.assign(reach_two.begin(), reach_two.end());
                    } else {
                        rows += for_each_shell_range(g, at, reach + 1, [&](std::uint32_t b, std::uint32_t e) {
                            shell.push_back({b, e});
                        });
                    }
                    for (const auto& [b, e] : shell) walked += e - b;
                    if (walked > most_shell_points) {
                        done = false;
                        break;
                    }
                    for (const auto& [b, e] : shell) scan_cells(g, k, b, e, best2, best);
                }
                distances += walked;
                if (done)
                    put(k, best2, best);
                else
                    later.push_back(k);
            }
        });
    }
    std::vector<std::uint32_t> rest;
    for (const auto& l : left) rest.insert(rest.end(), l.begin(), l.end());
    std::uint64_t visits = 0;
    if (rest.size() <= scanned_points) {  // a few stray points: a scan each, cheaper than a tree
        for (std::uint32_t k : rest) {
            const NearestFound f = nearest_by_scan(g, k, visits);
            put(k, f.best2, f.best);
        }
    } else {
        const NearestTree tree(g);
        visits += tree.building_work();
        const auto count = static_cast<std::ptrdiff_t>(rest.size());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 256) if (threads > 1) reduction(+ : visits)
        for (std::ptrdiff_t r = 0; r < count; ++r) {
            const std::uint32_t k = rest[static_cast<std::size_t>(r)];
            const NearestFound f = tree.nearest(k, visits);
            put(k, f.best2, f.best);
        }
    }
    if (work) {
        work->distances += distances;
        work->rows += rows;
        work->tree_visits += visits;
        work->left_to_tree += rest.size();
    }
    return out;
}

}  // namespace

NearestNeighbours nearest_neighbours_grid(std::span<const double> x, std::span<const double> y,
                                          std::span<const double> z, NearestWork* work) {
    return nearest_neighbours(x, y, z, work, false);
}

NearestNeighbours nearest_neighbours_walk_only(std::span<const double> x, std::span<const double> y,
                                               std::span<const double> z, NearestWork* work) {
    return nearest_neighbours(x, y, z, work, true);
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

// Cells per support radius of the counting grid. Half-support cells and a 5x5x5 block visit 40 %
// fewer candidates than support-sized cells and a 3x3x3 block, but in rows too short for the
// vectorised loop: measured at 1e6 particles, reach 1 was the fastest (0.35 s against 0.46 s).
constexpr std::uint32_t count_reach = 1;

// The fewest points at one place collapsed into one (collapsed_points.hpp): their pairs alone, 2016, pass
// coincident_pairs_kept, so a deck with fewer pairs than that bound is counted as before, point by point.
constexpr std::uint32_t collapsed_least = 64;
static_assert(std::uint64_t{collapsed_least} * (collapsed_least - 1) / 2 > coincident_pairs_kept);

// Symmetric counting: pairs (k, j) with j in sorted [b, e), all after k, each seen once; both
// counts grow. `close` counts pairs within the largest tolerance (checked exactly afterwards).
// Uniform: every point's support is support[0] (one value, no array in grid order). Weighted: a point
// stands for weight[k] points at its place (collapsed_points.hpp), and a pair counts weight times.
template <bool Uniform, bool Weighted>
[[gnu::always_inline]] inline void count_pairs(const NeighbourGrid& g, const double* support,
                                               const std::uint32_t* weight, std::uint32_t k, std::uint32_t b,
                                               std::uint32_t e, double tol2, std::uint32_t* count,
                                               std::uint64_t& within, std::uint64_t& close) {
    const double px = g.x()[k], py = g.y()[k], pz = g.z()[k], sk = Uniform ? support[0] : support[k];
    const std::uint64_t wk = Weighted ? weight[k] : 1;
    const double *gx = g.x().data(), *gy = g.y().data(), *gz = g.z().data();
    const double uniform_r2 = sk * sk;
    std::uint64_t w = 0, c = 0;
    for (std::uint32_t j = b; j < e; ++j) {
        const double dx = px - gx[j], dy = py - gy[j], dz = pz - gz[j];
        const double r2 = dx * dx + dy * dy + dz * dz;
        double radius2 = uniform_r2;
        if constexpr (!Uniform) {
            const double r = 0.5 * (sk + support[j]);
            radius2 = r * r;
        }
        const std::uint32_t m = r2 < radius2;
        if constexpr (Weighted) {
            w += m * weight[j];
            count[j] += m * static_cast<std::uint32_t>(wk);
        } else {
            w += m;
            count[j] += m;
        }
        c += r2 <= tol2;
    }
    within += w, close += c;
}

// The pairs of one occupied cell's points [first, last): with each other, and with the points of
// `ranges` (cells after it in cell order: count_symmetric's half-block rows). `box`: the cell's
// faces (block_bounds at reach 0); `largest`: the largest |support| of any point. The corner rows
// (y - 1 and y + 1 in the next plane, ranges 2 and 4) are left out for a point whose support
// cannot reach them, about one point in five: a tenth of the distance evaluations. Inlined into
// the two cloned functions after it.
template <bool Uniform, bool Weighted>
[[gnu::always_inline]] inline void count_cell(const NeighbourGrid& g, const double* support,
                                              const std::uint32_t* weight, std::uint32_t first, std::uint32_t last,
                                              std::span<const NeighbourGrid::Range> ranges, double tol2,
                                              std::uint32_t* count, std::vector<std::uint32_t>& close_points,
                                              const NeighbourGrid::BlockBounds& box, double largest) {
    for (std::uint32_t k = first; k < last; ++k) {
        std::uint64_t within = 0, close = 0;
        if constexpr (Weighted) {  // the points k stands for, with each other: the same test as two points'
            if (weight[k] > 1) {
                const double dx = g.x()[k] - g.x()[k], dy = g.y()[k] - g.y()[k], dz = g.z()[k] - g.z()[k];
                const double r2 = dx * dx + dy * dy + dz * dz;
                const double sk = Uniform ? support[0] : support[k];
                const double r = Uniform ? sk : 0.5 * (sk + sk);
                within += std::uint64_t{r2 < r * r} * (weight[k] - 1);
                close += r2 <= tol2;
            }
        }
        count_pairs<Uniform, Weighted>(g, support, weight, k, k + 1, last, tol2, count, within, close);
        // The farthest any pair of k counts or is close: (|s_k| + |s_j|) / 2 at most, or the tolerance.
        const double reach = Uniform ? std::abs(support[0]) : 0.5 * (std::abs(support[k]) + largest);
        const double reach2 = std::max(reach * reach, tol2) * (1 + 1e-9);
        const auto [skip_low, skip_high] = corner_rows_out_of_reach(g, box, g.y()[k], g.z()[k], reach2);
        for (std::size_t r = 0; r < ranges.size(); ++r) {
            const auto [b, e] = ranges[r];
            if (b == e || (r == 2 && skip_low) || (r == 4 && skip_high)) continue;
            count_pairs<Uniform, Weighted>(g, support, weight, k, b, e, tol2, count, within, close);
        }
        count[k] += static_cast<std::uint32_t>(within);  // at most the points: below 2^32
        if (close) close_points.push_back(k);
    }
}

// count_cell compiled for AVX2 and the baseline, for uniform and for mixed supports, plain or weighted (points
// collapsed: collapsed_points.hpp).
using CountCell = void (*)(const NeighbourGrid&, const double*, const std::uint32_t*, std::uint32_t, std::uint32_t,
                           std::span<const NeighbourGrid::Range>, double, std::uint32_t*, std::vector<std::uint32_t>&,
                           const NeighbourGrid::BlockBounds&, double);
#define SPHDECK_COUNT_CELL(name, uniform, weighted)                                                                 \
    SPHDECK_CLONES void name(const NeighbourGrid& g, const double* support, const std::uint32_t* weight,            \
                             std::uint32_t first, std::uint32_t last, std::span<const NeighbourGrid::Range> ranges, \
                             double tol2, std::uint32_t* count, std::vector<std::uint32_t>& close_points,           \
                             const NeighbourGrid::BlockBounds& box, double largest) {                               \
        count_cell<uniform, weighted>(g, support, weight, first, last, ranges, tol2, count, close_points, box,      \
                                      largest);                                                                     \
    }
SPHDECK_COUNT_CELL(count_cell_uniform, true, false)
SPHDECK_COUNT_CELL(count_cell_mixed, false, false)
SPHDECK_COUNT_CELL(count_cell_weighted_uniform, true, true)
SPHDECK_COUNT_CELL(count_cell_weighted_mixed, false, true)
#undef SPHDECK_COUNT_CELL

// Every pair once: for each occupied cell, the pairs inside it and with the cells after it in a
// half-block: the rest of its row, then the rows above it (y + 1 in its plane, the whole next
// plane), all contiguous ranges.
//
// On several threads: a cell's pairs reach its own z plane and the next one only. The occupied
// cells are cut at plane boundaries into 2 x threads runs of about equal points; runs 0, 2, 4...
// write disjoint planes and go together, then runs 1, 3, 5... Counts are sums of 0/1 terms, so
// the order of the additions changes nothing.
template <bool Uniform>
void count_symmetric(const NeighbourGrid& g, std::span<const double> support, const std::uint32_t* weight, double tol2,
                     double largest, std::vector<std::uint32_t>& count, std::vector<std::uint32_t>& close_points) {
    static_assert(count_reach == 1, "the half-block rows assume cells as large as the support");
    // The plain uniform counts in float lanes where the CPU has them (count_cell_float.hpp): the same counts.
    const CountCellFloat in_floats = Uniform && !weight ? count_cell_float() : nullptr;
    const auto run = [&](std::size_t from, std::size_t to, std::vector<std::uint32_t>& close) {
        FloatCellScratch scratch;
        g.for_each_cell_rows(count_half_rows, from, to,
                             [&](std::size_t o, NeighbourGrid::Cell at,
                                 const std::vector<NeighbourGrid::Range>& ranges) {
                                 const auto [first, last] = g.occupied_range(o);
                                 if (in_floats && in_floats(g, support[0], first, last, ranges, tol2, count.data(),
                                                            close, g.block_bounds(at, 0), scratch))
                                     return;
                                 const CountCell cell =
                                     weight ? (Uniform ? count_cell_weighted_uniform : count_cell_weighted_mixed)
                                            : (Uniform ? count_cell_uniform : count_cell_mixed);
                                 cell(g, support.data(), weight, first, last, ranges, tol2, count.data(), close,
                                      g.block_bounds(at, 0), largest);
                             });
    };
    const int threads = pass_threads(g.size());
    const std::size_t cells = g.occupied();
    if (threads == 1) return run(0, cells, close_points);
    // Run boundaries: the first occupied cell of a plane, near each 1/(2 threads) of the points.
    const std::size_t runs = 2 * static_cast<std::size_t>(threads);
    std::vector<std::size_t> bound{0};
    for (std::size_t r = 1; r < runs; ++r) {
        const auto target = static_cast<std::uint32_t>(g.size() * r / runs);
        std::size_t lo = bound.back(), hi = cells;  // first cell whose points start at or after target
        while (lo < hi) {
            const std::size_t mid = lo + (hi - lo) / 2;
            if (g.occupied_range(mid).first < target)
                lo = mid + 1;
            else
                hi = mid;
        }
        while (lo < cells && lo > 0 && g.occupied_cell(lo)[2] == g.occupied_cell(lo - 1)[2]) ++lo;
        bound.push_back(std::max(lo, bound.back()));
    }
    bound.push_back(cells);
    // Runs of one parity must stay a plane apart (an empty run between them would let them touch):
    // otherwise one thread does it all.
    for (std::size_t parity = 0; parity < 2; ++parity) {
        long long reach = -2;  // the last plane the runs so far write into
        for (std::size_t r = parity; r < runs; r += 2) {
            if (bound[r] == bound[r + 1]) continue;
            if (static_cast<long long>(g.occupied_cell(bound[r])[2]) <= reach) return run(0, cells, close_points);
            reach = static_cast<long long>(g.occupied_cell(bound[r + 1] - 1)[2]) + 1;
        }
    }
    std::vector<std::vector<std::uint32_t>> close(runs);
    for (std::size_t parity = 0; parity < 2; ++parity) {
#pragma omp parallel for num_threads(threads) schedule(static, 1)
        for (std::size_t r = parity; r < runs; r += 2) run(bound[r], bound[r + 1], close[r]);
    }
    for (const auto& c : close) close_points.insert(close_points.end(), c.begin(), c.end());
}

// Gather counting of every `stride`-th point (in cell order) over its whole block; the others
// copy the last counted point before them. Weighted: as count_pairs.
template <bool Weighted>
[[gnu::always_inline]] inline void count_sampled(const NeighbourGrid& g, const std::vector<double>& support,
                                                 const std::uint32_t* weight, std::size_t stride,
                                                 std::vector<std::uint32_t>& count) {
    const std::size_t n = g.size();
    const double *gx = g.x().data(), *gy = g.y().data(), *gz = g.z().data(), *s = support.data();
    for (std::size_t k = 0; k < n; k += stride) {
        const double px = gx[k], py = gy[k], pz = gz[k], sk = s[k];
        std::uint64_t w = 0;
        g.for_each_block_range(g.cell_of(px, py, pz), count_reach, [&](std::uint32_t b, std::uint32_t e) {
            for (std::uint32_t j = b; j < e; ++j) {
                const double dx = px - gx[j], dy = py - gy[j], dz = pz - gz[j];
                const double rr = 0.5 * (sk + s[j]);
                if constexpr (Weighted)
                    w += std::uint64_t{dx * dx + dy * dy + dz * dz < rr * rr} * weight[j];
                else
                    w += dx * dx + dy * dy + dz * dz < rr * rr;
            }
        });
        if (sk > 0) --w;  // itself
        for (std::size_t i = k; i < std::min(n, k + stride); ++i) count[i] = static_cast<std::uint32_t>(w);
    }
}
SPHDECK_CLONES void count_sampled_plain(const NeighbourGrid& g, const std::vector<double>& support, std::size_t stride,
                                        std::vector<std::uint32_t>& count) {
    count_sampled<false>(g, support, nullptr, stride, count);
}
void count_sampled_weighted(const NeighbourGrid& g, const std::vector<double>& support, const std::uint32_t* weight,
                            std::size_t stride, std::vector<std::uint32_t>& count) {
    count_sampled<true>(g, support, weight, stride, count);
}

}  // namespace

NeighbourCounts count_neighbours(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                                 std::span<const double> support, std::span<const double> tolerance, double pair_budget,
                                 std::size_t kept_pairs) {
    std::vector<std::uint32_t> own(x.size());  // every point its own group
    for (std::size_t i = 0; i < own.size(); ++i) own[i] = static_cast<std::uint32_t>(i);
    return count_neighbours(x, y, z, GroupedRadii{own, support, tolerance}, pair_budget, kept_pairs);
}

bool coincident_at(double ax, double ay, double az, double bx, double by, double bz, double t) {
    const double dx = ax - bx, dy = ay - by, dz = az - bz;
    return dx * dx + dy * dy + dz * dz <= t * t;
}

NeighbourCounts count_neighbours(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                                 const GroupedRadii& radii, double pair_budget, std::size_t kept_pairs) {
    const std::size_t n = x.size();
    NeighbourCounts out;
    if (n == 0) return out;
    // The largest values over the points (not over the groups: a group without points must not
    // change the grid), and whether one support serves every point.
    double largest_support = 0, largest_tolerance = 0, largest_reach = 0;  // the last: of |support|
    bool uniform = true;
    const int threads = pass_threads(n);
    {
        const auto support_of = [&](std::size_t i) { return radii.support[radii.group[i]]; };
        const auto tolerance_of = [&](std::size_t i) { return radii.tolerance[radii.group[i]]; };
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1) \
    reduction(max : largest_support, largest_tolerance, largest_reach) reduction(&& : uniform)
        for (std::size_t i = 0; i < n; ++i) {
            largest_support = std::max(largest_support, support_of(i));
            largest_reach = std::max(largest_reach, std::abs(support_of(i)));
            largest_tolerance = std::max(largest_tolerance, tolerance_of(i));
            uniform = uniform && support_of(i) == support_of(0);
        }
    }
    double cell = std::max(largest_support, largest_tolerance) / count_reach;
    if (cell <= 0) cell = estimated_spacing(x, y, z);
    NeighbourGrid g(x, y, z, cell);
    // Crowds at one place counted as one point each (collapsed_points.hpp): the grid is then over the
    // collapsed points, `weight` (in grid order) says how many each stands for.
    const CollapsedPoints collapsed = collapse_coincident(g, radii, collapsed_least);
    if (!collapsed.empty()) g = NeighbourGrid(collapsed.x, collapsed.y, collapsed.z, cell);
    const std::size_t points = g.size();
    // Point p of the grid's input: an input point, or a collapsed one.
    const std::span<const std::uint32_t> group =
        collapsed.empty() ? radii.group : std::span<const std::uint32_t>(collapsed.group);
    const auto support_of = [&](std::size_t p) { return radii.support[group[p]]; };
    const auto tolerance_of = [&](std::size_t p) { return radii.tolerance[group[p]]; };
    const auto& order = g.order();
    // The distance evaluations a count takes: points per cell times points in its half-block.
    double work = 0;
    g.for_each_cell_rows(block_rows, [&](std::size_t o, NeighbourGrid::Cell, const auto& ranges) {
        const auto [first, last] = g.occupied_range(o);
        double block = 0;
        for (auto [b, e] : ranges) block += e - b;
        work += 0.5 * double(last - first) * block;
    });
    if (pair_budget <= 0) pair_budget = std::max(5.0e8, 400.0 * static_cast<double>(n));
    const bool sampled = work > pair_budget;
    // Supports in grid order: one value when uniform (and not sampled, which reads an array).
    std::vector<double> s(uniform && !sampled ? 1 : points);
    if (s.size() == 1) {
        s[0] = support_of(0);
    } else {
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
        for (std::size_t k = 0; k < points; ++k) s[k] = support_of(order[k]);
    }
    std::vector<std::uint32_t> weight;  // empty when nothing was collapsed
    if (!collapsed.empty()) {
        weight.resize(points);
        for (std::size_t k = 0; k < points; ++k) weight[k] = collapsed.weight[order[k]];
    }
    const std::uint32_t* w = weight.empty() ? nullptr : weight.data();
    // A count is at most the points' number (weights included), below 2^32: 4 bytes a point.
    std::vector<std::uint32_t> count(points, 0);
    std::vector<std::uint32_t> close_points;
    if (sampled) {
        // A sampled point costs its whole block (twice its half-block): a quarter of the budget.
        out.sample_stride = static_cast<std::size_t>(std::ceil(8 * work / pair_budget));
        if (w)
            count_sampled_weighted(g, s, w, out.sample_stride, count);
        else
            count_sampled_plain(g, s, out.sample_stride, count);
    } else if (uniform) {
        count_symmetric<true>(g, s, w, largest_tolerance * largest_tolerance, largest_reach, count, close_points);
    } else {
        count_symmetric<false>(g, s, w, largest_tolerance * largest_tolerance, largest_reach, count, close_points);
    }
    std::vector<double>().swap(s);  // given back (`s = {}` would keep its capacity)
    // Coincident pairs, checked exactly: all counted, the first `kept_pairs` kept (first_pairs.hpp).
    const auto members = [&](std::uint32_t k) {
        return collapsed.empty() ? std::span<const std::uint32_t>(&order[k], 1) : collapsed.members_of(order[k]);
    };
    FirstPairs first(kept_pairs);
    std::uint64_t total = 0;
    const auto offer_pair = [&](std::uint32_t k, std::uint32_t j) {  // grid points k and j (k != j)
        const double t = std::max(tolerance_of(order[k]), tolerance_of(order[j]));
        if (!coincident_at(g.x()[k], g.y()[k], g.z()[k], g.x()[j], g.y()[j], g.z()[j], t)) return;
        total += (w ? std::uint64_t{w[k]} : 1) * (w ? w[j] : 1);
        first.offer_between(members(k), members(j));
    };
    const auto offer_own = [&](std::uint32_t k) {  // a collapsed point's points with each other
        const std::uint64_t wk = w ? w[k] : 1;
        const double px = g.x()[k], py = g.y()[k], pz = g.z()[k];
        if (wk < 2 || !coincident_at(px, py, pz, px, py, pz, tolerance_of(order[k]))) return;
        total += wk * (wk - 1) / 2;
        first.offer_among(members(k));
    };
    if (sampled) {
        // The counts looked at no pair of most points: every pair within the largest tolerance, on keys of
        // that size (close_pairs.hpp).
        for (std::uint32_t k = 0; w && k < points; ++k) offer_own(k);
        for_each_close_pair(g.x(), g.y(), g.z(), largest_tolerance, offer_pair);
    }
    // Otherwise the few points with a pair inside the largest tolerance. Each such point is the first (in
    // grid order) of its pairs (count_cell), so the pairs with the points after it in its block are every
    // pair once.
    for (std::uint32_t k : close_points) {
        offer_own(k);
        g.for_each_block_range(g.cell_of(g.x()[k], g.y()[k], g.z()[k]), count_reach,
                               [&](std::uint32_t b, std::uint32_t e) {
                                   for (std::uint32_t j = std::max(b, k + 1); j < e; ++j) offer_pair(k, j);
                               });
    }
    out.coincident = std::move(first).sorted();
    out.coincident_pairs = total;
    // The counts in input order, made once the grid's coordinates are gone: not beside them and the
    // counts in grid order at the preview's peak of memory (4 bytes a point, issue 40).
    const std::vector<std::uint32_t> input_of = std::move(g).release_order();
    out.count.resize(n);
    if (collapsed.empty()) {
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
        for (std::size_t k = 0; k < n; ++k) out.count[input_of[k]] = count[k];
    } else {
        std::vector<std::uint32_t> of_point(points);
        for (std::size_t k = 0; k < points; ++k) of_point[input_of[k]] = count[k];
        for (std::size_t i = 0; i < n; ++i) out.count[i] = of_point[collapsed.of[i]];
    }
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
