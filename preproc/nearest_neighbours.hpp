// Nearest-neighbour distances and neighbour counts (sph-algorithms.md §2.1, §12.1).
//
// Two nearest-neighbour searches over one set of points (the preview calls them per part, so the
// nearest neighbour is always one of the same part, as in LS-DYNA's rule for h0):
// - nearest_neighbours_grid: a cell list with ring expansion. The 3x3x3 block of cells around a
//   point is searched first; the search widens shell by shell until no point outside the block
//   searched can be closer. The result is therefore exact, not limited to the 27-cell stencil.
//   A point whose walk would be long (a crowded block, a neighbour many shells away) gets the same
//   answer from a k-d tree (nearest_tree.hpp): the work stays about n log n on any cloud.
// - nearest_neighbours_all_pairs: every pair, O(n^2): the reference (INI = 1, "global
//   computation on all the particles").
// Both compute the squared distance with the same expression on the same doubles, so their
// distances agree bit for bit; only the index can differ, between equidistant neighbours.
//
// Where LS-DYNA's two INI modes may still differ (docs/preview.md): LS-DYNA's bucket sort (INI 0)
// is assumed to search adjacent buckets only, so for an isolated particle whose nearest neighbour
// lies beyond them it may find a different (or no) distance; sphdeck reports the exact one in both
// modes and flags such particles (SPH115). And "all the particles of the model" (INI 1) may count
// particles of other parts, which would shorten d_i where parts touch; sphdeck keeps the same-part
// rule of *SECTION_SPH Remark 1 for both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

namespace sphdeck::preproc {

struct NearestNeighbours {
    static constexpr std::uint32_t none = 0xFFFFFFFFu;
    std::vector<double> distance;      // per point; 0 when the set has no other point
    std::vector<std::uint32_t> index;  // the nearest other point, `none` when there is none
};

// Threads for a pass over every point (the grid passes here, preview_follow.cpp's): OMP_NUM_THREADS (or
// --threads) decides; below a few thousand points starting a team costs more than it saves.
int pass_threads(std::size_t points);

// A typical spacing of the points: (bounding-box measure / count)^(1/d) over the axes the points
// span (d = 0..3). 0 when the points span no axis.
double estimated_spacing(std::span<const double> x, std::span<const double> y, std::span<const double> z);

// The work of a search, for tests that bound it: distances evaluated and rows of cells looked up by the
// grid walk, nodes and points of the tree looked at (nearest_tree.hpp; its building's passes over the
// points included), and the points left to the tree.
struct NearestWork {
    std::uint64_t distances = 0, rows = 0, tree_visits = 0, left_to_tree = 0;
};

NearestNeighbours nearest_neighbours_grid(std::span<const double> x, std::span<const double> y,
                                          std::span<const double> z, NearestWork* work = nullptr);
// The same answers by the grid walk alone, every point's shells to the end and each shell's rows looked up
// cell by cell (as before the tree): for tests, whose reference it is; its work grows with the cube of the
// shells a point crosses.
NearestNeighbours nearest_neighbours_walk_only(std::span<const double> x, std::span<const double> y,
                                               std::span<const double> z, NearestWork* work = nullptr);

// `progress`, when set, is called now and then with the fraction done (0..1).
NearestNeighbours nearest_neighbours_all_pairs(std::span<const double> x, std::span<const double> y,
                                               std::span<const double> z,
                                               const std::function<void(double)>& progress = {});

// The coincident pairs kept (the first, in order), whatever their number: m particles at one place make
// m (m - 1) / 2 pairs, which must not cost memory without bound. More than the rules list (SPH114's 20),
// and more than any deck's of the corpus (the editor's followed preview needs every pair and recomputes
// past this: preview_follow.hpp); 8 KB.
inline constexpr std::size_t coincident_pairs_kept = 1000;

struct NeighbourCounts {
    // Per point: the other points j with r_ij < (support_i + support_j) / 2.
    std::vector<std::uint32_t> count;
    // Pairs (i < j) closer than max(tolerance_i, tolerance_j), or at distance 0 (coincident_at): all of
    // them counted, the first `kept_pairs` (in order) kept; sampled counts too (close_pairs.hpp).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> coincident;
    std::uint64_t coincident_pairs = 0;
    // 1 when every point was counted; k when only every k-th point (in cell order) was and the
    // others copy the count of the last counted point before them: the work was over budget
    // (supports of many spacings, usually an h0 inflated by a stray particle).
    std::size_t sample_stride = 1;
};

// Neighbour counts within the kernel support (a radius per point: kernel factor * h), on a grid
// with cells as large as the largest support; each pair is evaluated once. `pair_budget` bounds
// the distance evaluations (0: max(5e8, 400 per point), about a second). Points at one place (64 or
// more with one support and tolerance) are counted as one point of that weight: the work stays about
// n log n however the points crowd (collapsed_points.hpp), with the same counts and pairs.
NeighbourCounts count_neighbours(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                                 std::span<const double> support, std::span<const double> tolerance,
                                 double pair_budget = 0, std::size_t kept_pairs = coincident_pairs_kept);

// Support and tolerance shared by groups of points (the parts of a deck): point i has
// support[group[i]] and tolerance[group[i]]. The same counts as above without two arrays of a
// double per point, nor a third in grid order when every point has the same support.
struct GroupedRadii {
    std::span<const std::uint32_t> group;        // per point
    std::span<const double> support, tolerance;  // per group
};
NeighbourCounts count_neighbours(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                                 const GroupedRadii& radii, double pair_budget = 0,
                                 std::size_t kept_pairs = coincident_pairs_kept);

// Whether points a and b make a coincident pair of count_neighbours, t the larger of their tolerances:
// the very expression of its check (compiled without contraction, as the counts are).
bool coincident_at(double ax, double ay, double az, double bx, double by, double bz, double t);

// The same by brute force over all pairs, for tests.
std::vector<std::uint32_t> count_neighbours_all_pairs(std::span<const double> x, std::span<const double> y,
                                                      std::span<const double> z, std::span<const double> support);

}  // namespace sphdeck::preproc
