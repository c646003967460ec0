#include "preproc/neighbour_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "preproc/thread_share.hpp"

namespace sphdeck::preproc {

namespace {
constexpr std::uint32_t axis_bits = 21;  // hashed keys: 21 bits per axis
constexpr double max_axis_cells = double(1u << axis_bits) - 2;

// Threads for binning: OMP_NUM_THREADS (or --threads) decides; inside a parallel region (a
// solver's loop) or below some tens of thousands of points, one.
int bin_threads(std::size_t points) {
#ifdef _OPENMP
    if (points < 32768 || omp_in_parallel()) return 1;
    return std::max(1, omp_get_max_threads());
#else
    (void)points;
    return 1;
#endif
}

}  // namespace

NeighbourGrid::NeighbourGrid(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                             double cell_size, bool may_read_in_place) {
    const std::size_t n = x.size();
    const std::span<const double> axes[3] = {x, y, z};
    std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
    // The bounding box of the finite coordinates, in one pass (minima and maxima: any order).
    const int threads = bin_threads(n);
    constexpr double inf = std::numeric_limits<double>::infinity();
    double lx = inf, ly = inf, lz = inf, hx = -inf, hy = -inf, hz = -inf;
#pragma omp parallel for num_threads(threads) reduction(min : lx, ly, lz) reduction(max : hx, hy, hz) if (threads > 1)
    for (std::size_t i = 0; i < n; ++i) {
        if (std::isfinite(x[i])) lx = std::min(lx, x[i]), hx = std::max(hx, x[i]);
        if (std::isfinite(y[i])) ly = std::min(ly, y[i]), hy = std::max(hy, y[i]);
        if (std::isfinite(z[i])) lz = std::min(lz, z[i]), hz = std::max(hz, z[i]);
    }
    const double found_lo[3] = {lx, ly, lz}, found_hi[3] = {hx, hy, hz};
    for (int a = 0; a < 3; ++a)
        if (found_lo[a] <= found_hi[a]) lo[a] = found_lo[a], hi[a] = found_hi[a];
    origin_ = lo;
    double extent = 0;
    for (int a = 0; a < 3; ++a) extent = std::max(extent, hi[a] - lo[a]);
    cell_ = cell_size > 0 && std::isfinite(cell_size) ? cell_size : std::max(extent, 1.0);
    inv_cell_ = 1.0 / cell_;
    double dense_cells = 1;
    for (int a = 0; a < 3; ++a) {
        const double cells = std::floor((hi[a] - lo[a]) * inv_cell_) + 1;
        if (!(cells <= max_axis_cells)) {
            // More cells than a key holds (points 1e7 cells apart): the grid covers the
            // max_axis_cells around the median and clamps the few points beyond into its border
            // cells. Queries stay exact: a clamped point lies further out than its cell.
            std::vector<double> v;
            for (double c : axes[a])
                if (std::isfinite(c)) v.push_back(c);
            std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
            origin_[a] = std::max(lo[a], v[v.size() / 2] - 0.5 * max_axis_cells * cell_);
            n_[a] = static_cast<std::uint32_t>(max_axis_cells);
        } else {
            n_[a] = static_cast<std::uint32_t>(cells);
        }
        dense_cells *= n_[a];
    }
    // Dense cell indices are 4 bytes (bin_dense's cell_id, occupied_cells_): more cells than that, hashed.
    hashed_ = dense_cells > 2.0 * static_cast<double>(n) + 64.0 || dense_cells >= 4294967295.0;
    if (hashed_)
        bin_hashed(x, y, z);
    else
        bin_dense(x, y, z, may_read_in_place);
}

template <typename CellOfPoint>
void NeighbourGrid::gather(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                           const CellOfPoint& cell_id) {
    const std::size_t n = x.size(), slots = start_.size() - 1;  // cells (dense) or occupied cells (hashed)
    order_.resize(n);
    x_.resize(n), y_.resize(n), z_.resize(n);
    // start_ serves as the cursors (no copy of a 4-byte entry per cell at the preview's peak):
    // afterwards each entry holds the next cell's start, and one shift puts them back. On several
    // threads each owns the cells of a run of about n / threads points and scans every point.
    const int threads = bin_threads(n);
    std::vector<std::size_t> bound(static_cast<std::size_t>(threads) + 1, slots);  // before any cursor moves
    for (int t = 0; t < threads; ++t)  // the first cell starting at or after the run's first point
        bound[static_cast<std::size_t>(t)] =
            t == 0 ? 0
                   : static_cast<std::size_t>(
                         std::lower_bound(start_.begin(), start_.end() - 1, share_of(n, t, threads).first) -
                         start_.begin());
#pragma omp parallel for num_threads(threads) schedule(static, 1) if (threads > 1)
    for (int t = 0; t < threads; ++t) {
        const std::size_t c0 = bound[static_cast<std::size_t>(t)], c1 = bound[static_cast<std::size_t>(t) + 1];
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t c = cell_id(i);
            if (c < c0 || c >= c1) continue;
            const std::uint32_t k = start_[c]++;
            order_[k] = static_cast<std::uint32_t>(i);
            x_[k] = x[i], y_[k] = y[i], z_[k] = z[i];
        }
    }
    std::copy_backward(start_.begin(), start_.end() - 1, start_.end());
    start_[0] = 0;
}

void NeighbourGrid::read_in_place(std::span<const double> x, std::span<const double> y, std::span<const double> z) {
    order_.resize(x.size());
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<std::uint32_t>(i);
    caller_x_ = x, caller_y_ = y, caller_z_ = z;
    in_place_ = true;
}

// A counting sort by cell, stable (points of a cell in input order), the same on any number of
// threads: each thread owns a run of cells and scans every point for those in its run, so no
// two threads write one counter or one slot, and nothing per thread and cell is allocated.
void NeighbourGrid::bin_dense(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                              bool may_read_in_place) {
    const std::size_t n = x.size(), cells = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
    const int threads = bin_threads(n);
    start_.assign(cells + 1, 0);
    const auto cell_index = [&](std::size_t i) {
        const Cell c = cell_of(x[i], y[i], z[i]);
        return static_cast<std::uint32_t>(index(c[0], c[1], c[2]));
    };
    if (threads == 1) {
        // Each point's cell computed again in the gathering rather than kept: no array of a cell a point
        // (4 MB a million points) beside the copies at the preview's peak of memory.
        bool in_cell_order = true;  // each point in the cell of the one before it or a later one
        std::uint32_t previous = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t c = cell_index(i);
            in_cell_order = in_cell_order && c >= previous, previous = c;
            ++start_[c + 1];
        }
        for (std::size_t c = 0; c < cells; ++c) {
            if (start_[c + 1]) occupied_cells_.push_back(static_cast<std::uint32_t>(c));
            start_[c + 1] += start_[c];
        }
        // The counting sort is stable: on points in cell order it would copy them as they are.
        if (in_cell_order && may_read_in_place) return read_in_place(x, y, z);
        return gather(x, y, z, cell_index);
    }
    // On several threads each scans every point for the cells of its run: the cells computed once.
    std::vector<std::uint32_t> cell_id(n);
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t i = 0; i < n; ++i) cell_id[i] = cell_index(i);
    // Counts and running sums per run of cells, then each run's offset.
    std::vector<std::vector<std::uint32_t>> occupied(static_cast<std::size_t>(threads));
    std::vector<std::uint32_t> run_total(static_cast<std::size_t>(threads) + 1, 0);
#pragma omp parallel for num_threads(threads) schedule(static, 1)
    for (int t = 0; t < threads; ++t) {
        const auto [c0, c1] = share_of(cells, t, threads);
        for (std::size_t i = 0; i < n; ++i)
            if (cell_id[i] >= c0 && cell_id[i] < c1) ++start_[cell_id[i] + 1];
        for (std::size_t c = c0; c < c1; ++c) {
            if (start_[c + 1]) occupied[static_cast<std::size_t>(t)].push_back(static_cast<std::uint32_t>(c));
            if (c > c0) start_[c + 1] += start_[c];
        }
        run_total[static_cast<std::size_t>(t) + 1] = c1 > c0 ? start_[c1] : 0;
    }
    for (int t = 0; t < threads; ++t)
        run_total[static_cast<std::size_t>(t) + 1] += run_total[static_cast<std::size_t>(t)];
#pragma omp parallel for num_threads(threads) schedule(static, 1)
    for (int t = 0; t < threads; ++t) {
        const auto [c0, c1] = share_of(cells, t, threads);
        // start_[c0 + 1 .. c1] are this run's sums (start_[c0] closes the run before).
        const std::uint32_t offset = run_total[static_cast<std::size_t>(t)];
        for (std::size_t c = c0 + 1; c <= c1; ++c) start_[c] += offset;
    }
    for (auto& o : occupied) occupied_cells_.insert(occupied_cells_.end(), o.begin(), o.end());
    if (may_read_in_place) {
        bool in_cell_order = true;
#pragma omp parallel for num_threads(threads) schedule(static) reduction(&& : in_cell_order)
        for (std::size_t i = 1; i < n; ++i) in_cell_order = in_cell_order && cell_id[i] >= cell_id[i - 1];
        if (in_cell_order) return read_in_place(x, y, z);
    }
    gather(x, y, z, [&](std::size_t i) { return cell_id[i]; });
}

void NeighbourGrid::bin_hashed(std::span<const double> x, std::span<const double> y, std::span<const double> z) {
    const std::size_t n = x.size();
    std::vector<std::uint64_t> keys(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Cell c = cell_of(x[i], y[i], z[i]);
        keys[i] = key(c[0], c[1], c[2]);
    }
    occupied_keys_ = keys;
    std::sort(occupied_keys_.begin(), occupied_keys_.end());
    occupied_keys_.erase(std::unique(occupied_keys_.begin(), occupied_keys_.end()), occupied_keys_.end());
    std::size_t capacity = 16;
    while (capacity < 2 * occupied_keys_.size()) capacity *= 2;
    table_shift_ = 64 - std::countr_zero(capacity);
    table_keys_.assign(capacity, 0);
    table_ids_.assign(capacity, none);
    for (std::size_t o = 0; o < occupied_keys_.size(); ++o) {
        std::size_t slot = slot_of(occupied_keys_[o]);
        while (table_keys_[slot]) slot = (slot + 1) & (capacity - 1);
        table_keys_[slot] = occupied_keys_[o] + 1;
        table_ids_[slot] = static_cast<std::uint32_t>(o);
    }
    start_.assign(occupied_keys_.size() + 1, 0);
    std::vector<std::uint32_t> cell_id(n);
    for (std::size_t i = 0; i < n; ++i) {
        cell_id[i] = find(keys[i]);
        ++start_[cell_id[i] + 1];
    }
    for (std::size_t o = 0; o < occupied_keys_.size(); ++o) start_[o + 1] += start_[o];
    gather(x, y, z, [&](std::size_t i) { return cell_id[i]; });
}

NeighbourGrid::Cell NeighbourGrid::decode(std::uint64_t k) const {
    if (hashed_) {
        constexpr std::uint64_t mask = (1u << axis_bits) - 1;
        return {static_cast<std::uint32_t>(k & mask), static_cast<std::uint32_t>(k >> axis_bits & mask),
                static_cast<std::uint32_t>(k >> (2 * axis_bits))};
    }
    return {static_cast<std::uint32_t>(k % n_[0]), static_cast<std::uint32_t>(k / n_[0] % n_[1]),
            static_cast<std::uint32_t>(k / n_[0] / n_[1])};
}

std::uint32_t NeighbourGrid::find(std::uint64_t k) const {
    const std::size_t capacity = table_keys_.size();
    for (std::size_t slot = slot_of(k);; slot = (slot + 1) & (capacity - 1)) {
        if (table_keys_[slot] == k + 1) return table_ids_[slot];
        if (table_keys_[slot] == 0) return none;
    }
}

NeighbourGrid::Range NeighbourGrid::hashed_row_range(std::uint32_t x0, std::uint32_t x1, std::uint32_t iy,
                                                     std::uint32_t iz) const {
    std::uint32_t first = none, last = none, at = x0;
    for (; at <= x1 && first == none; ++at) first = find(key(at, iy, iz));
    if (first == none) return {0, 0};
    for (std::uint32_t back = x1; back + 1 >= at && last == none; --back) last = find(key(back, iy, iz));
    return {start_[first], start_[last + 1]};
}

bool NeighbourGrid::block_covers_grid(Cell c, std::uint32_t reach) const {
    for (int a = 0; a < 3; ++a)
        if (c[a] > reach || c[a] + reach < n_[a] - 1) return false;
    return true;
}

double NeighbourGrid::block_cells(Cell c, std::uint32_t reach) const {
    double cells = 1;
    for (int a = 0; a < 3; ++a)
        cells *= std::min<double>(double(c[a]) + reach, n_[a] - 1) - std::max<double>(double(c[a]) - reach, 0) + 1;
    return cells;
}

double NeighbourGrid::crowding() const {
    double sum = 0;
    for (std::size_t o = 0; o < occupied(); ++o) {
        const auto [b, e] = occupied_range(o);
        sum += double(e - b) * double(e - b);
    }
    return size() ? sum / static_cast<double>(size()) : 0.0;
}

}  // namespace sphdeck::preproc
