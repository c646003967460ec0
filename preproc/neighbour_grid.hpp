// A uniform cell-list neighbour grid (sph-algorithms.md §12.1): cubic cells of one edge length,
// particles binned by a counting sort and copied in cell order (row-major cells, x fastest), so
// that the particles of one cell, and of three cells side by side along x, are contiguous.
// Built once per query set; rebuilding is cheap (about 15 ms per million particles), so a solver
// can rebuild every step. The cell edge should be at least the largest search radius: then a
// radius query only visits the 3x3x3 block of cells around a particle.
//
// The grid is dense over the bounding box. When that box would need more than a few cells per
// particle (a sparse domain, e.g. a projectile far from its target), the cell edge is enlarged
// until it does not; queries stay correct, only slower (a hashed grid would be the next step).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace sphdeck::preproc {

class NeighbourGrid {
public:
    NeighbourGrid() = default;
    // Bins the points (x[i], y[i], z[i]); `cell_size` > 0 is the smallest edge wanted.
    NeighbourGrid(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                  double cell_size);

    std::size_t size() const { return order_.size(); }
    double cell_size() const { return cell_; }
    std::array<std::uint32_t, 3> cells() const { return {n_[0], n_[1], n_[2]}; }
    std::size_t cell_count() const { return start_.empty() ? 0 : start_.size() - 1; }

    // Sorted (cell-order) position k holds the input point order()[k].
    const std::vector<std::uint32_t>& order() const { return order_; }
    // Coordinates in cell order.
    const std::vector<double>& x() const { return x_; }
    const std::vector<double>& y() const { return y_; }
    const std::vector<double>& z() const { return z_; }

    // Cell coordinates of a point, clamped into the grid.
    std::array<std::uint32_t, 3> cell_of(double px, double py, double pz) const;
    std::size_t cell_index(std::uint32_t ix, std::uint32_t iy, std::uint32_t iz) const {
        return (static_cast<std::size_t>(iz) * n_[1] + iy) * n_[0] + ix;
    }
    // Sorted positions [begin, end) of the points of cell `c`.
    std::uint32_t cell_begin(std::size_t c) const { return start_[c]; }
    std::uint32_t cell_end(std::size_t c) const { return start_[c + 1]; }

    // Calls f(begin, end) for the sorted ranges covering the (2*reach+1)^3 block of cells around
    // cell (ix, iy, iz), clipped to the grid: one range per (y, z) row of the block.
    template <typename F>
    void for_each_block_range(std::array<std::uint32_t, 3> c, std::uint32_t reach, F&& f) const {
        const std::uint32_t x0 = c[0] > reach ? c[0] - reach : 0, x1 = std::min(c[0] + reach, n_[0] - 1);
        const std::uint32_t y0 = c[1] > reach ? c[1] - reach : 0, y1 = std::min(c[1] + reach, n_[1] - 1);
        const std::uint32_t z0 = c[2] > reach ? c[2] - reach : 0, z1 = std::min(c[2] + reach, n_[2] - 1);
        for (std::uint32_t iz = z0; iz <= z1; ++iz)
            for (std::uint32_t iy = y0; iy <= y1; ++iy) {
                const std::uint32_t b = start_[cell_index(x0, iy, iz)], e = start_[cell_index(x1, iy, iz) + 1];
                if (b != e) f(b, e);
            }
    }

    // Calls f(j, r2) for every sorted point j != k within `radius` (r2 < radius^2) of sorted point
    // k. Requires radius <= cell_size().
    template <typename F>
    void for_each_neighbour(std::uint32_t k, double radius, F&& f) const {
        const double px = x_[k], py = y_[k], pz = z_[k], r2max = radius * radius;
        for_each_block_range(cell_of(px, py, pz), 1, [&](std::uint32_t b, std::uint32_t e) {
            for (std::uint32_t j = b; j < e; ++j) {
                const double dx = px - x_[j], dy = py - y_[j], dz = pz - z_[j];
                const double r2 = dx * dx + dy * dy + dz * dz;
                if (r2 < r2max && j != k) f(j, r2);
            }
        });
    }

    // Distance from (px, py, pz) to the outside of the block of `reach` cells around its cell:
    // every point outside the block is at least this far. Infinite when the block covers the grid.
    double block_clearance(double px, double py, double pz, std::uint32_t reach) const;
    // Whether the block of `reach` cells around cell c covers the whole grid.
    bool block_covers_grid(std::array<std::uint32_t, 3> c, std::uint32_t reach) const;

private:
    double cell_ = 1.0, inv_cell_ = 1.0;
    std::array<double, 3> origin_{};
    std::array<std::uint32_t, 3> n_{1, 1, 1};
    std::vector<std::uint32_t> start_;  // cell_count() + 1 offsets into the sorted arrays
    std::vector<std::uint32_t> order_;
    std::vector<double> x_, y_, z_;
};

}  // namespace sphdeck::preproc
