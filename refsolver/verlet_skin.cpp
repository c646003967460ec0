#include "refsolver/verlet_skin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <omp.h>
#include <utility>

#include "preproc/thread_share.hpp"

namespace sphdeck::refsolver {

namespace {

constexpr double infinite_skin = std::numeric_limits<double>::infinity();

struct Box : DisplacementBox {
    Box()
        : DisplacementBox{{infinite_skin, infinite_skin, infinite_skin},
                          {-infinite_skin, -infinite_skin, -infinite_skin}} {}
};
void add_skin(DisplacementBox& b, const double p[3]) {
    for (int a = 0; a < 3; ++a) b.lo[a] = std::min(b.lo[a], p[a]), b.hi[a] = std::max(b.hi[a], p[a]);
}
bool empty(const DisplacementBox& b) { return !(b.lo[0] <= b.hi[0]); }

// The diagonal of the box bounding two boxes (0 when both are empty).
double box_diagonal(const DisplacementBox& a, const DisplacementBox& b) {
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
        const double extent = std::max(a.hi[k], b.hi[k]) - std::min(a.lo[k], b.lo[k]);
        sum += extent > 0 ? extent * extent : 0.0;
    }
    return std::sqrt(sum);
}

// Calls f(build position, displacement) for the points [first, last) of the active real particles
// (0 .. real) and the ghosts of active ones (real .. real + ghosts).
template <class F>
void for_each_point(const Particles& s, const std::vector<SymmetryPlane>& planes, std::size_t first, std::size_t last,
                    F&& f) {
    for (std::size_t i = first; i < std::min(last, s.real); ++i) {
        if (!s.active[i]) continue;
        const double at[3] = {s.x_built[i], s.y_built[i], s.z_built[i]};
        const double d[3] = {s.x[i] - at[0], s.y[i] - at[1], s.z[i] - at[2]};
        f(at, d);
    }
    for (std::size_t k = std::max(first, s.real) - s.real; k + s.real < last; ++k) {
        const std::size_t j = s.ghost_source[k];
        if (!s.active[j]) continue;
        double at[3] = {s.x_built[j], s.y_built[j], s.z_built[j]};
        double d[3] = {s.x[j] - at[0], s.y[j] - at[1], s.z[j] - at[2]};
        for (std::size_t q = 0; q < planes.size() && q < 8; ++q) {  // in plane order, as update_ghosts
            if (!(s.ghost_planes[k] >> q & 1u)) continue;
            const auto& n = planes[q].normal;
            const double an = at[0] * n[0] + at[1] * n[1] + at[2] * n[2] - planes[q].offset;
            const double dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
            for (int a = 0; a < 3; ++a) at[a] -= 2 * an * n[a], d[a] -= 2 * dn * n[a];
        }
        f(at, d);
    }
}

void merge_skin(DisplacementBox& into, const DisplacementBox& b) {
    for (int a = 0; a < 3; ++a) into.lo[a] = std::min(into.lo[a], b.lo[a]), into.hi[a] = std::max(into.hi[a], b.hi[a]);
}

}  // namespace

double closing_bound(const Particles& s, const std::vector<SymmetryPlane>& planes, double support,
                     std::vector<DisplacementBox>& cells, int threads) {
    // Every step of a stretching flow asks this (the global bound is spent): each pass runs on the
    // threads. Boxes only grow by min and max, so the result is the same at any thread count.
    const std::size_t points = s.real + s.ghosts();
    threads = std::max(1, threads);
    double largest = 0;  // max |d|
    bool finite = true;
    double lo[3] = {infinite_skin, infinite_skin, infinite_skin},
           hi[3] = {-infinite_skin, -infinite_skin, -infinite_skin};
#pragma omp parallel num_threads(threads) reduction(max : largest) reduction(&& : finite) reduction(min : lo[:3]) \
    reduction(max : hi[:3])
    {
        const auto [first, last] = preproc::share_of(points, omp_get_thread_num(), omp_get_num_threads());
        Box where;  // of the build positions
        for_each_point(s, planes, first, last, [&](const double at[3], const double d[3]) {
            const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            finite = finite && std::isfinite(length);
            largest = std::max(largest, length);
            add_skin(where, at);
        });
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], where.lo[a]), hi[a] = std::max(hi[a], where.hi[a]);
    }
    DisplacementBox where{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
    if (empty(where)) return 0.0;
    if (!finite || !std::isfinite(support) || !std::isfinite(box_diagonal(where, where))) return infinite_skin;
    // Cells of at least support + 2 max|d| (the margin covers the rounding of the cell indices);
    // coarser when that would make too many cells.
    double cell = (support + 2 * largest) * (1 + 1e-9) + 1e-300;
    std::size_t n[3];
    constexpr std::size_t most_cells = std::size_t{1} << 22;
    for (;;) {
        double total = 1;
        for (int a = 0; a < 3; ++a) {
            // Capped before the conversion: a tiny support over a wide box is +inf cells, which no
            // integer holds (issue 32); the product in double cannot wrap.
            const double along = std::min((where.hi[a] - where.lo[a]) / cell, static_cast<double>(most_cells));
            n[a] = static_cast<std::size_t>(along) + 1;
            total *= static_cast<double>(n[a]);
        }
        if (total <= static_cast<double>(most_cells)) break;
        cell *= 2;
    }
    const std::size_t count = n[0] * n[1] * n[2];
    // One set of cells per thread while they are few beside the points (else one thread bins them).
    const int binning = count * static_cast<std::size_t>(threads) <= std::max<std::size_t>(points, 4096) ? threads : 1;
    cells.assign(count * static_cast<std::size_t>(binning), Box{});
    const auto index = [&](const double at[3], std::size_t c[3]) {
        for (int a = 0; a < 3; ++a) c[a] = std::min(n[a] - 1, static_cast<std::size_t>((at[a] - where.lo[a]) / cell));
    };
#pragma omp parallel num_threads(binning)
    {
        const int t = omp_get_thread_num();
        const auto [first, last] = preproc::share_of(points, t, omp_get_num_threads());
        DisplacementBox* own = cells.data() + static_cast<std::size_t>(t) * count;
        for_each_point(s, planes, first, last, [&](const double at[3], const double d[3]) {
            std::size_t c[3];
            index(at, c);
            add_skin(own[(c[2] * n[1] + c[1]) * n[0] + c[0]], d);
        });
#pragma omp barrier
#pragma omp for schedule(static)
        for (std::size_t c = 0; c < count; ++c)
            for (std::size_t u = 1; u < static_cast<std::size_t>(binning); ++u)
                merge_skin(cells[c], cells[u * count + c]);
    }
    // Each cell with itself and its neighbours (both orders give the same box: the forward half).
    double bound = 0;
#pragma omp parallel for schedule(static) reduction(max : bound) num_threads(threads)
    for (std::size_t z = 0; z < n[2]; ++z)
        for (std::size_t y = 0; y < n[1]; ++y)
            for (std::size_t x = 0; x < n[0]; ++x) {
                const DisplacementBox& here = cells[(z * n[1] + y) * n[0] + x];
                if (empty(here)) continue;
                for (int dz = 0; dz <= 1; ++dz)
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            if (dz == 0 && (dy < 0 || (dy == 0 && dx < 0))) continue;
                            const long long ox = static_cast<long long>(x) + dx, oy = static_cast<long long>(y) + dy;
                            const std::size_t oz = z + static_cast<std::size_t>(dz);
                            if (ox < 0 || oy < 0 || ox >= static_cast<long long>(n[0]) ||
                                oy >= static_cast<long long>(n[1]) || oz >= n[2])
                                continue;
                            const DisplacementBox& there =
                                cells[(oz * n[1] + static_cast<std::size_t>(oy)) * n[0] + static_cast<std::size_t>(ox)];
                            if (!empty(there)) bound = std::max(bound, box_diagonal(here, there));
                        }
            }
    return bound;
}

}  // namespace sphdeck::refsolver
