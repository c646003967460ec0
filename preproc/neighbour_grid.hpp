// A uniform cell-list neighbour grid (sph-algorithms.md §12.1): cubic cells of one edge length,
// particles binned by a counting sort and copied in cell order (row-major cells, x fastest), so
// that the particles of one cell, and of a run of cells along x, are contiguous. Built once per
// query set; rebuilding is cheap (a few tens of ms per million particles), so a solver can
// rebuild every step. With the cell edge at least the largest search radius, a radius query
// visits the 3x3x3 block of cells around a particle: nine contiguous row ranges.
//
// Dense or hashed: the grid is dense over the bounding box when that takes at most about two
// cells per point (the usual case: one counting sort, rows found by indexing). A sparse domain
// (a projectile far from its target, a stray particle far from its part) would need far more
// empty cells; the occupied cells are then sorted by key and found through a hash table, with
// the same cell size and the same queries (sph-algorithms.md §12.1, item 3).
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace sphdeck::preproc {

class NeighbourGrid {
public:
    using Cell = std::array<std::uint32_t, 3>;
    using Range = std::pair<std::uint32_t, std::uint32_t>;  // sorted positions [first, second)

    NeighbourGrid() = default;
    // Bins the points (x[i], y[i], z[i]); `cell_size` > 0 is the cell edge wanted. Non-finite
    // coordinates are binned into the border cells. With `may_read_in_place`, points already in cell order
    // (each in the cell of the point before it or a later one: a generated lattice in node order, with cells
    // of its spacing) are read where they are instead of copied (24 MB a million points, issue 40): the
    // caller then keeps x, y and z alive and unchanged while the grid, or a copy of it, is used.
    NeighbourGrid(std::span<const double> x, std::span<const double> y, std::span<const double> z, double cell_size,
                  bool may_read_in_place = false);
    // A copy reads its own coordinates, or, where the original reads the caller's in place, the same ones.

    std::size_t size() const { return order_.size(); }
    double cell_size() const { return cell_; }
    bool hashed() const { return hashed_; }
    Cell cells() const { return n_; }  // cells along each axis (of the bounding box)

    // Sorted (cell-order) position k holds the input point order()[k].
    const std::vector<std::uint32_t>& order() const { return order_; }
    // The order taken out of the grid, which is left empty (no query after it): its coordinates freed
    // before the caller's next array.
    std::vector<std::uint32_t> release_order() && {
        std::vector<std::uint32_t> order = std::move(order_);
        *this = NeighbourGrid();
        return order;
    }
    // Coordinates in cell order.
    std::span<const double> x() const { return in_place_ ? caller_x_ : std::span<const double>(x_); }
    std::span<const double> y() const { return in_place_ ? caller_y_ : std::span<const double>(y_); }
    std::span<const double> z() const { return in_place_ ? caller_z_ : std::span<const double>(z_); }
    // Whether the coordinates are the caller's, read in place (the points were in cell order already).
    bool reads_in_place() const { return in_place_; }

    // The occupied cells, in cell order: their coordinates and sorted ranges.
    std::size_t occupied() const { return hashed_ ? occupied_keys_.size() : occupied_cells_.size(); }
    Cell occupied_cell(std::size_t o) const { return decode(occupied_key(o)); }
    Range occupied_range(std::size_t o) const {
        return hashed_ ? Range{start_[o], start_[o + 1]}
                       : Range{start_[occupied_cells_[o]], start_[occupied_cells_[o] + 1]};
    }

    // Cell coordinates of a point: floor((p - origin) / cell) clamped into the grid, NaN to 0.
    // Without std::floor (a library call in the x86-64 baseline, a third of the binning): a value
    // of at least 1 truncates to its floor, and one below 1 is cell 0 either way.
    Cell cell_of(double px, double py, double pz) const {
        Cell c{};
        const double p[3] = {px, py, pz};
        for (int a = 0; a < 3; ++a) {
            const double f = (p[a] - origin_[a]) * inv_cell_;
            c[a] = !(f >= 1) ? 0 : f >= n_[a] - 1 ? n_[a] - 1 : static_cast<std::uint32_t>(f);
        }
        return c;
    }

    // The points of cells x0..x1 (x0 <= x1 < cells()[0]) of row (iy, iz): one sorted range.
    Range row_range(std::uint32_t x0, std::uint32_t x1, std::uint32_t iy, std::uint32_t iz) const {
        if (!hashed_) return {start_[index(x0, iy, iz)], start_[index(x1, iy, iz) + 1]};
        return hashed_row_range(x0, x1, iy, iz);
    }

    // Calls f(begin, end) for the sorted ranges covering the (2*reach+1)^3 block of cells around
    // cell c, clipped to the grid: one range per (y, z) row of the block.
    template <typename F>
    void for_each_block_range(Cell c, std::uint32_t reach, F&& f) const {
        const std::uint32_t x0 = c[0] > reach ? c[0] - reach : 0, x1 = std::min(c[0] + reach, n_[0] - 1);
        const std::uint32_t y0 = c[1] > reach ? c[1] - reach : 0, y1 = std::min(c[1] + reach, n_[1] - 1);
        const std::uint32_t z0 = c[2] > reach ? c[2] - reach : 0, z1 = std::min(c[2] + reach, n_[2] - 1);
        for (std::uint32_t iz = z0; iz <= z1; ++iz)
            for (std::uint32_t iy = y0; iy <= y1; ++iy) {
                const auto [b, e] = row_range(x0, x1, iy, iz);
                if (b != e) f(b, e);
            }
    }

    // A row of cells relative to a cell (ix, iy, iz): x from ix + dx0 to ix + dx1, at iy + dy, iz + dz.
    struct RowOffset {
        int dx0, dx1, dy, dz;
    };

    // Walks the occupied cells in order: f(o, cell, ranges) with one sorted range per row offset
    // (empty when the row is outside the grid or holds no point). Cheaper than row_range() per
    // cell on a hashed grid: one cursor per row offset moves forward through the occupied cells.
    template <typename F>
    void for_each_cell_rows(std::span<const RowOffset> rows, F&& f) const {
        for_each_cell_rows(rows, 0, occupied(), std::forward<F>(f));
    }
    // The same for the occupied cells [begin, end) only: threads walk disjoint runs of cells.
    template <typename F>
    void for_each_cell_rows(std::span<const RowOffset> rows, std::size_t begin, std::size_t end_cell, F&& f) const {
        std::vector<Range> ranges(rows.size());
        std::vector<std::size_t> cursor(rows.size(), 0);
        // A dense grid's cell whose rows all lie inside the grid: each row's first cell, and the cell after its
        // last, at a fixed distance in cell indices from the cell's own (no clipping, no index to compute).
        std::vector<long long> first_cell(rows.size()), after_cell(rows.size());
        long long reach_lo[3] = {0, 0, 0}, reach_hi[3] = {0, 0, 0};
        bool straight = !hashed_;
        const long long plane = static_cast<long long>(n_[0]) * n_[1];
        for (std::size_t r = 0; r < rows.size(); ++r) {
            const RowOffset& w = rows[r];
            straight = straight && w.dx0 <= w.dx1;
            const long long shift = w.dy * static_cast<long long>(n_[0]) + w.dz * plane;
            first_cell[r] = shift + w.dx0, after_cell[r] = shift + w.dx1 + 1;
            reach_lo[0] = std::min<long long>(reach_lo[0], w.dx0),
            reach_hi[0] = std::max<long long>(reach_hi[0], w.dx1);
            reach_lo[1] = std::min<long long>(reach_lo[1], w.dy), reach_hi[1] = std::max<long long>(reach_hi[1], w.dy);
            reach_lo[2] = std::min<long long>(reach_lo[2], w.dz), reach_hi[2] = std::max<long long>(reach_hi[2], w.dz);
        }
        const auto inside = [&](const Cell& c) {
            for (int a = 0; a < 3; ++a)
                if (static_cast<long long>(c[a]) + reach_lo[a] < 0 ||
                    static_cast<long long>(c[a]) + reach_hi[a] >= static_cast<long long>(n_[a]))
                    return false;
            return true;
        };
        Cell c{};
        for (std::size_t o = begin; o < end_cell; ++o) {
            // The next cell along x when the key is one more (no division to decode it).
            if (o > begin && occupied_key(o) == occupied_key(o - 1) + 1 && c[0] + 1 < n_[0])
                ++c[0];
            else
                c = occupied_cell(o);
            if (straight && inside(c)) {
                const long long at = occupied_cells_[o];
                for (std::size_t r = 0; r < rows.size(); ++r)
                    ranges[r] = {start_[static_cast<std::size_t>(at + first_cell[r])],
                                 start_[static_cast<std::size_t>(at + after_cell[r])]};
            } else {
                for (std::size_t r = 0; r < rows.size(); ++r) ranges[r] = offset_row_range(rows[r], c, cursor[r]);
            }
            f(o, c, ranges);
        }
    }

    // The sorted range of a row relative to cell c (empty outside the grid). On a hashed grid `cursor`
    // (0 at first) moves forward through the occupied cells: one cursor serves calls whose cells come in
    // cell order, each a step or two, without a hash look-up.
    Range offset_row_range(const RowOffset& row, Cell c, std::size_t& cursor) const {
        const long long y = static_cast<long long>(c[1]) + row.dy, z = static_cast<long long>(c[2]) + row.dz;
        const long long x0 = std::max<long long>(0, static_cast<long long>(c[0]) + row.dx0);
        const long long x1 = std::min<long long>(n_[0] - 1, static_cast<long long>(c[0]) + row.dx1);
        if (y < 0 || y >= n_[1] || z < 0 || z >= n_[2] || x0 > x1) return {0, 0};
        const auto yy = static_cast<std::uint32_t>(y), zz = static_cast<std::uint32_t>(z);
        if (!hashed_) return row_range(static_cast<std::uint32_t>(x0), static_cast<std::uint32_t>(x1), yy, zz);
        const std::size_t count = occupied_keys_.size();
        const std::uint64_t first = key(static_cast<std::uint32_t>(x0), yy, zz);
        const std::uint64_t last = key(static_cast<std::uint32_t>(x1), yy, zz);
        while (cursor < count && occupied_keys_[cursor] < first) ++cursor;
        std::size_t end = cursor;
        while (end < count && occupied_keys_[end] <= last) ++end;
        return {start_[cursor], start_[end]};
    }

    // Calls f(j, r2) for every sorted point j != k within `radius` (r2 < radius^2) of sorted point
    // k. Requires radius <= cell_size().
    template <typename F>
    void for_each_neighbour(std::uint32_t k, double radius, F&& f) const {
        const std::span<const double> gx = x(), gy = y(), gz = z();
        const double px = gx[k], py = gy[k], pz = gz[k], r2max = radius * radius;
        for_each_block_range(cell_of(px, py, pz), 1, [&](std::uint32_t b, std::uint32_t e) {
            for (std::uint32_t j = b; j < e; ++j) {
                const double dx = px - gx[j], dy = py - gy[j], dz = pz - gz[j];
                const double r2 = dx * dx + dy * dy + dz * dz;
                if (r2 < r2max && j != k) f(j, r2);
            }
        });
    }

    // Distance from (px, py, pz), a point of cell c, to the outside of the block of `reach` cells
    // around c: every point binned outside the block is at least this far (a point clamped into a
    // border cell lies even further out). Infinite when the block covers the grid.
    double block_clearance(double px, double py, double pz, Cell c, std::uint32_t reach) const {
        return block_bounds(c, reach).clearance(px, py, pz);
    }
    // The same in two steps, the first once per cell: the planes that bound the block (-inf and
    // +inf where the grid ends), then a point's distance to them.
    struct BlockBounds {
        std::array<double, 3> lower, upper;
        double margin;
        double clearance(double px, double py, double pz) const {
            const double p[3] = {px, py, pz};
            double clear = std::numeric_limits<double>::infinity();
            for (int a = 0; a < 3; ++a) clear = std::min(std::min(clear, p[a] - lower[a]), upper[a] - p[a]);
            return clear - margin;
        }
    };
    BlockBounds block_bounds(Cell c, std::uint32_t reach) const {
        constexpr double inf = std::numeric_limits<double>::infinity();
        BlockBounds b{{-inf, -inf, -inf}, {inf, inf, inf}, 0.0};
        for (int a = 0; a < 3; ++a) {
            if (c[a] > reach)  // cells exist below the block
                b.lower[a] = origin_[a] + (static_cast<double>(c[a]) - reach) * cell_;
            if (c[a] + reach < n_[a] - 1)  // and above it
                b.upper[a] = origin_[a] + (static_cast<double>(c[a]) + reach + 1) * cell_;
        }
        // A margin for the rounding of cell boundaries: never claim more than is certain.
        b.margin = 1e-9 * cell_;
        return b;
    }
    bool block_covers_grid(Cell c, std::uint32_t reach) const;
    // Cells in the block of `reach` around c, clipped to the grid.
    double block_cells(Cell c, std::uint32_t reach) const;

    // Points per occupied cell, averaged over points (sum of n_c^2 / n): about 1-2 for a cell
    // matched to the spacing, far more when the cell is too large for the dense parts.
    double crowding() const;

private:
    static constexpr std::uint32_t none = 0xFFFFFFFFu;
    std::size_t index(std::uint32_t ix, std::uint32_t iy, std::uint32_t iz) const {
        return (static_cast<std::size_t>(iz) * n_[1] + iy) * n_[0] + ix;
    }
    std::uint64_t key(std::uint32_t ix, std::uint32_t iy, std::uint32_t iz) const {
        return hashed_ ? (std::uint64_t{iz} << 42) | (std::uint64_t{iy} << 21) | ix : index(ix, iy, iz);
    }
    // An occupied cell's key: its cell index (dense) or its hashed key.
    std::uint64_t occupied_key(std::size_t o) const { return hashed_ ? occupied_keys_[o] : occupied_cells_[o]; }
    Cell decode(std::uint64_t k) const;
    std::uint32_t find(std::uint64_t k) const;  // occupied id of a hashed cell, or `none`
    // A key's first slot: the top bits of its product by 2^64 / golden ratio, which every bit of the key
    // moves (bits 20 and up of the product left out the z of the cell: a column of cells shared a slot).
    std::size_t slot_of(std::uint64_t k) const {
        return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> table_shift_);
    }
    Range hashed_row_range(std::uint32_t x0, std::uint32_t x1, std::uint32_t iy, std::uint32_t iz) const;
    void bin_dense(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                   bool may_read_in_place);
    // The points in cell order already: the order is the identity and the coordinates are read in place.
    void read_in_place(std::span<const double> x, std::span<const double> y, std::span<const double> z);
    void bin_hashed(std::span<const double> x, std::span<const double> y, std::span<const double> z);
    // Copies the points in cell order; cell_id(i) is point i's cell (dense) or occupied cell (hashed).
    template <typename CellOfPoint>
    void gather(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                const CellOfPoint& cell_id);

    double cell_ = 1.0, inv_cell_ = 1.0;
    std::array<double, 3> origin_{};
    Cell n_{1, 1, 1};
    bool hashed_ = false;
    std::vector<std::uint32_t> start_;  // dense: per cell + 1; hashed: per occupied cell + 1
    // The occupied cells in cell order: a dense grid's cell indices fit in 4 bytes (it has fewer than 2^32
    // cells), a hashed grid's keys take 8. One point per cell in a nearest-neighbour search: 4 bytes a point
    // less at the preview's peak of memory (issue 40).
    std::vector<std::uint32_t> occupied_cells_;  // dense
    std::vector<std::uint64_t> occupied_keys_;   // hashed
    std::vector<std::uint64_t> table_keys_;      // hashed: open addressing, key + 1 (0 = empty)
    int table_shift_ = 60;                       // 64 - log2 of the table's size
    std::vector<std::uint32_t> table_ids_;
    std::vector<std::uint32_t> order_;
    std::vector<double> x_, y_, z_;                           // the copies in cell order (empty when read in place)
    std::span<const double> caller_x_, caller_y_, caller_z_;  // the caller's, when read in place
    bool in_place_ = false;
};

}  // namespace sphdeck::preproc
