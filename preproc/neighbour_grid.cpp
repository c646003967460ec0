#include "preproc/neighbour_grid.hpp"

#include <cmath>
#include <limits>

namespace sphdeck::preproc {

NeighbourGrid::NeighbourGrid(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                             double cell_size) {
    const std::size_t n = x.size();
    std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
    if (n > 0) {
        lo = hi = {x[0], y[0], z[0]};
        for (std::size_t i = 1; i < n; ++i) {
            lo[0] = std::min(lo[0], x[i]), hi[0] = std::max(hi[0], x[i]);
            lo[1] = std::min(lo[1], y[i]), hi[1] = std::max(hi[1], y[i]);
            lo[2] = std::min(lo[2], z[i]), hi[2] = std::max(hi[2], z[i]);
        }
    }
    origin_ = lo;
    double extent = 0;
    for (int a = 0; a < 3; ++a) extent = std::max(extent, hi[a] - lo[a]);
    cell_ = cell_size > 0 && std::isfinite(cell_size) ? cell_size : std::max(extent, 1.0);
    cell_ = std::max(cell_, extent * 1e-9);  // no more than 1e9 cells along an axis
    // A dense grid: at most about two cells per point (plus a little for tiny sets).
    const double cell_limit = 2.0 * static_cast<double>(n) + 64.0;
    for (;;) {
        double total = 1;
        for (int a = 0; a < 3; ++a) total *= std::floor((hi[a] - lo[a]) / cell_) + 1;
        if (total <= cell_limit) break;
        cell_ *= 1.25;
    }
    inv_cell_ = 1.0 / cell_;
    for (int a = 0; a < 3; ++a) n_[a] = static_cast<std::uint32_t>(std::floor((hi[a] - lo[a]) * inv_cell_)) + 1;

    // Counting sort by cell.
    const std::size_t cells = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
    start_.assign(cells + 1, 0);
    std::vector<std::uint32_t> cell_id(n);
    for (std::size_t i = 0; i < n; ++i) {
        auto c = cell_of(x[i], y[i], z[i]);
        cell_id[i] = static_cast<std::uint32_t>(cell_index(c[0], c[1], c[2]));
        ++start_[cell_id[i] + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
    order_.resize(n);
    x_.resize(n), y_.resize(n), z_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t k = next[cell_id[i]]++;
        order_[k] = static_cast<std::uint32_t>(i);
        x_[k] = x[i], y_[k] = y[i], z_[k] = z[i];
    }
}

std::array<std::uint32_t, 3> NeighbourGrid::cell_of(double px, double py, double pz) const {
    std::array<std::uint32_t, 3> c{};
    const double p[3] = {px, py, pz};
    for (int a = 0; a < 3; ++a) {
        const double f = std::floor((p[a] - origin_[a]) * inv_cell_);
        c[a] = f <= 0 ? 0 : f >= n_[a] - 1 ? n_[a] - 1 : static_cast<std::uint32_t>(f);
    }
    return c;
}

bool NeighbourGrid::block_covers_grid(std::array<std::uint32_t, 3> c, std::uint32_t reach) const {
    for (int a = 0; a < 3; ++a)
        if (c[a] > reach || c[a] + reach < n_[a] - 1) return false;
    return true;
}

double NeighbourGrid::block_clearance(double px, double py, double pz, std::uint32_t reach) const {
    const double p[3] = {px, py, pz};
    const auto c = cell_of(px, py, pz);
    double clearance = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (c[a] > reach)  // cells exist below the block
            clearance = std::min(clearance, p[a] - (origin_[a] + (static_cast<double>(c[a]) - reach) * cell_));
        if (c[a] + reach < n_[a] - 1)  // and above it
            clearance = std::min(clearance, origin_[a] + (static_cast<double>(c[a]) + reach + 1) * cell_ - p[a]);
    }
    // A margin for the rounding of cell boundaries: never claim more than is certain.
    return clearance - 1e-9 * cell_;
}

}  // namespace sphdeck::preproc
