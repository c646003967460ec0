#include "preproc/nearest_tree.hpp"

#include <algorithm>
#include <cmath>

namespace sphdeck::preproc {

namespace {

constexpr std::uint32_t none = 0xFFFFFFFFu;
constexpr std::uint32_t leaf_points = 8;
constexpr double inf = std::numeric_limits<double>::infinity();

// The shell of cell c around cell `at`: its Chebyshev distance, at least 1 (the first block is 3x3x3).
std::uint32_t shell_of(NeighbourGrid::Cell at, NeighbourGrid::Cell c) {
    std::uint32_t s = 1;
    for (int a = 0; a < 3; ++a) s = std::max(s, at[a] > c[a] ? at[a] - c[a] : c[a] - at[a]);
    return s;
}

bool finite_point(const NeighbourGrid& g, std::uint32_t k) {
    return std::isfinite(g.x()[k]) && std::isfinite(g.y()[k]) && std::isfinite(g.z()[k]);
}

// A candidate's order: (squared distance, shell, sorted position), the shell left out (0) when the walk's
// scan of every point decides. Never a candidate at an infinite distance (the walk keeps only a strictly
// smaller one than its first, infinite, best).
struct Key {
    double d2;
    std::uint32_t shell, position;
    bool before(const Key& o) const {
        if (d2 != o.d2) return d2 < o.d2;
        return d2 < inf && (shell != o.shell ? shell < o.shell : position < o.position);
    }
};

// The walk's answer from a search for the least key: with shells first; then, when the walk ends by
// scanning every point before reaching the shell of that answer, by sorted position alone.
template <typename Search>
NearestFound as_the_walk(const NeighbourGrid& g, std::uint32_t k, Search&& search) {
    if (!finite_point(g, k)) return {};  // every squared distance NaN: the walk finds none
    NearestFound found = search(true);
    if (found.best == none) return found;
    const NeighbourGrid::Cell at = g.cell_of(g.x()[k], g.y()[k], g.z()[k]);
    const WalkEnd end = walk_end(g, k, at, found.best2);
    const NeighbourGrid::Cell c = g.cell_of(g.x()[found.best], g.y()[found.best], g.z()[found.best]);
    if (end.scanned_all && shell_of(at, c) > end.reach) found = search(false);
    return found;
}

}  // namespace

WalkEnd walk_end(const NeighbourGrid& g, std::uint32_t k, NeighbourGrid::Cell at, double best2) {
    const double px = g.x()[k], py = g.y()[k], pz = g.z()[k];
    const double points = static_cast<double>(g.size());
    // The walk's tests at reach r, in its order; each turns true at some reach and stays true.
    const auto covers = [&](std::uint32_t r) { return g.block_covers_grid(at, r); };
    const auto clear = [&](std::uint32_t r) {
        const double c = g.block_clearance(px, py, pz, at, r);
        return c > 0 && best2 <= c * c;
    };
    const auto scans_all = [&](std::uint32_t r) { return g.block_cells(at, r + 1) > points; };
    const auto ends = [&](std::uint32_t r) { return covers(r) || clear(r) || scans_all(r); };
    std::uint32_t most = 1;  // the block of this reach covers the grid
    for (int a = 0; a < 3; ++a) most = std::max({most, at[a], g.cells()[a] - 1 - at[a]});
    // The first reach that ends: doubling from 1 (usually a few cells), then halving the last step.
    std::uint32_t lo = 1, hi = 1;
    while (hi < most && !ends(hi)) lo = hi + 1, hi = std::min(most, 2 * hi);
    while (lo < hi) {
        const std::uint32_t mid = lo + (hi - lo) / 2;
        if (ends(mid))
            hi = mid;
        else
            lo = mid + 1;
    }
    return {lo, !covers(lo) && !clear(lo)};
}

NearestTree::NearestTree(const NeighbourGrid& g) : g_(g) {
    const auto n = static_cast<std::uint32_t>(g.size());
    points_.reserve(n);
    for (std::uint32_t j = 0; j < n; ++j)
        if (finite_point(g, j)) points_.push_back({g.x()[j], g.y()[j], g.z()[j], j});
    if (points_.empty()) return;
    nodes_.reserve(2 * (points_.size() / leaf_points + 1));
    build(0, static_cast<std::uint32_t>(points_.size()));
}

// Split at the median of the widest axis, equal coordinates by sorted position: duplicates split into runs
// of positions, so that a query among them stops at the lowest (its first_position bound).
std::uint32_t NearestTree::build(std::uint32_t begin, std::uint32_t end) {
    const auto id = static_cast<std::uint32_t>(nodes_.size());
    Node node{{inf, inf, inf}, {-inf, -inf, -inf}, {none, none, none}, {0, 0, 0}, begin, end, none, 0};
    building_work_ += end - begin;
    for (std::uint32_t i = begin; i < end; ++i) {
        const Point& p = points_[i];
        node.lo[0] = std::min(node.lo[0], p.x), node.hi[0] = std::max(node.hi[0], p.x);
        node.lo[1] = std::min(node.lo[1], p.y), node.hi[1] = std::max(node.hi[1], p.y);
        node.lo[2] = std::min(node.lo[2], p.z), node.hi[2] = std::max(node.hi[2], p.z);
        node.first_position = std::min(node.first_position, p.position);
    }
    // A cell's coordinate along an axis grows with the point's along it alone: the cells' box is the box's.
    node.cell_lo = g_.cell_of(node.lo[0], node.lo[1], node.lo[2]);
    node.cell_hi = g_.cell_of(node.hi[0], node.hi[1], node.hi[2]);
    nodes_.push_back(node);
    if (end - begin <= leaf_points) return id;
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (node.hi[a] - node.lo[a] > node.hi[axis] - node.lo[axis]) axis = a;
    const std::uint32_t mid = begin + (end - begin) / 2;
    const auto coordinate = [axis](const Point& p) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; };
    std::nth_element(points_.begin() + begin, points_.begin() + mid, points_.begin() + end,
                     [&](const Point& a, const Point& b) {
                         const double u = coordinate(a), v = coordinate(b);
                         return u != v ? u < v : a.position < b.position;
                     });
    build(begin, mid);  // node id + 1
    const std::uint32_t second = build(mid, end);
    nodes_[id].second = second;
    return id;
}

struct NearestTree::Query {
    double px, py, pz;
    std::uint32_t k;
    NeighbourGrid::Cell at;
    bool by_shell;
    Key best{inf, none, none};
    std::uint64_t visits = 0;
};

NearestFound NearestTree::nearest(std::uint32_t k, std::uint64_t& visits) const {
    return as_the_walk(g_, k, [&](bool by_shell) { return search(k, by_shell, visits); });
}

NearestFound NearestTree::search(std::uint32_t k, bool by_shell, std::uint64_t& visits) const {
    Query q{g_.x()[k], g_.y()[k], g_.z()[k], k, g_.cell_of(g_.x()[k], g_.y()[k], g_.z()[k]), by_shell};
    if (!nodes_.empty()) visit(q, 0);
    visits += q.visits;
    return {q.best.d2, q.best.position};
}

// The least key a node's points can have, by its boxes: a gap per axis computed as the distances are
// (p - q rounded; rounding is monotonic), so no point of the node has a smaller squared distance.
void NearestTree::visit(Query& q, std::uint32_t id) const {
    const auto bound = [&](const Node& node) {
        const double p[3] = {q.px, q.py, q.pz};
        double gap[3];
        std::uint32_t shell = 1;
        for (int a = 0; a < 3; ++a) {
            gap[a] = p[a] < node.lo[a] ? node.lo[a] - p[a] : p[a] > node.hi[a] ? p[a] - node.hi[a] : 0.0;
            const std::uint32_t c = q.at[a];
            shell = std::max(shell, c < node.cell_lo[a]   ? node.cell_lo[a] - c
                                    : c > node.cell_hi[a] ? c - node.cell_hi[a]
                                                          : 0);
        }
        return Key{gap[0] * gap[0] + gap[1] * gap[1] + gap[2] * gap[2], q.by_shell ? shell : 0, node.first_position};
    };
    const Node& node = nodes_[id];
    ++q.visits;
    if (!node.second) {
        for (std::uint32_t i = node.begin; i < node.end; ++i) {
            const Point& p = points_[i];
            const double dx = q.px - p.x, dy = q.py - p.y, dz = q.pz - p.z;
            const double r2 = dx * dx + dy * dy + dz * dz;
            if (!(r2 <= q.best.d2) || p.position == q.k) continue;  // farther, NaN, or itself
            const std::uint32_t shell = q.by_shell ? shell_of(q.at, g_.cell_of(p.x, p.y, p.z)) : 0;
            const Key key{r2, shell, p.position};
            if (key.before(q.best)) q.best = key;
        }
        q.visits += node.end - node.begin;
        return;
    }
    const std::uint32_t first = id + 1, second = node.second;
    const Key a = bound(nodes_[first]), b = bound(nodes_[second]);
    const bool second_first = b.before(a);
    const std::uint32_t order[2] = {second_first ? second : first, second_first ? first : second};
    const Key bounds[2] = {second_first ? b : a, second_first ? a : b};
    for (int i = 0; i < 2; ++i)
        if (bounds[i].before(q.best)) visit(q, order[i]);
}

// One pass for both orders (with the shell, and by position alone for the walk's scan of every point).
NearestFound nearest_by_scan(const NeighbourGrid& g, std::uint32_t k, std::uint64_t& visits) {
    Key plain{inf, none, none};
    return as_the_walk(g, k, [&](bool by_shell) {
        if (!by_shell) return NearestFound{plain.d2, plain.position};
        const double px = g.x()[k], py = g.y()[k], pz = g.z()[k];
        const double *gx = g.x().data(), *gy = g.y().data(), *gz = g.z().data();
        const NeighbourGrid::Cell at = g.cell_of(px, py, pz);
        const auto n = static_cast<std::uint32_t>(g.size());
        Key best{inf, none, none};
        for (std::uint32_t j = 0; j < n; ++j) {
            const double dx = px - gx[j], dy = py - gy[j], dz = pz - gz[j];
            const double r2 = dx * dx + dy * dy + dz * dz;
            if (j == k || !(r2 <= best.d2)) continue;  // both orders' least distance is the same
            const Key key{r2, shell_of(at, g.cell_of(gx[j], gy[j], gz[j])), j};
            if (key.before(best)) best = key;
            if (Key{r2, 0, j}.before(plain)) plain = Key{r2, 0, j};
        }
        visits += n;
        return NearestFound{best.d2, best.position};
    });
}

}  // namespace sphdeck::preproc
