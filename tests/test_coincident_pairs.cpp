// Coincident particles (preproc/collapsed_points.hpp, preproc/first_pairs.hpp): the neighbour counts and the
// coincident pairs of clouds with crowds at one place equal a brute force over all pairs, their number exact
// and the first pairs kept in order; a crowd far past the pair bound is counted exactly without sampling;
// sampled counts count them too, on 64-bit keys (preproc/close_pairs.hpp);
// SPH114 says how many pairs there are; an edit that moves a particle into or out of a crowd gives the
// preview a fresh one gives (preproc/preview_follow.hpp), followed or recomputed.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <map>
#include <random>
#include <string>

#include "engine/check.hpp"
#include "engine/preview_after_edit.hpp"
#include "preproc/close_pairs.hpp"
#include "preproc/first_pairs.hpp"
#include "preproc/nearest_neighbours.hpp"
#include "preproc/preview.hpp"
#include "preproc/preview_follow.hpp"

namespace test_coincident_pairs_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using Pair = std::pair<std::uint32_t, std::uint32_t>;

namespace {

struct Cloud {
    std::vector<double> x, y, z;
    std::vector<std::uint32_t> group;
    std::size_t size() const { return x.size(); }
    void add(double a, double b, double c, std::uint32_t g = 0) {
        x.push_back(a), y.push_back(b), z.push_back(c), group.push_back(g);
    }
};

// A jittered lattice of n^3 points (spacing 1) with crowds at one place: `crowds` sizes, each at a lattice
// point's place (that point included), a few of a crowd's points in group 1 (another support), and pairs
// 1e-12 apart (within the tolerance, not at one place); then shuffled, so that a crowd's indices interleave.
Cloud crowded(int n, std::initializer_list<std::size_t> crowds, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    Cloud c;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) c.add(i + u(rng), j + u(rng), k + u(rng));
    std::size_t at = 7;
    for (const std::size_t size : crowds) {
        for (std::size_t m = 1; m < size; ++m) c.add(c.x[at], c.y[at], c.z[at], m % 17 == 0 ? 1 : 0);
        c.add(c.x[at + 1] + 1e-12, c.y[at + 1], c.z[at + 1]);  // near, not at one place
        at += 11;
    }
    std::vector<std::size_t> order(c.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    Cloud s;
    for (const std::size_t i : order) s.add(c.x[i], c.y[i], c.z[i], c.group[i]);
    return s;
}

struct Brute {
    std::vector<std::uint32_t> count;
    std::vector<Pair> pairs;  // every coincident pair, in order
};

// Every pair: the counts (r < (s_i + s_j) / 2) and the coincident pairs (coincident_at, the larger tolerance).
Brute brute_force(const Cloud& c, const double* support, const double* tolerance) {
    Brute b;
    b.count.assign(c.size(), 0);
    for (std::uint32_t i = 0; i < c.size(); ++i)
        for (std::uint32_t j = i + 1; j < c.size(); ++j) {
            const double dx = c.x[i] - c.x[j], dy = c.y[i] - c.y[j], dz = c.z[i] - c.z[j];
            const double si = support[c.group[i]], sj = support[c.group[j]];
            const double r = 0.5 * (si + sj);
            if (dx * dx + dy * dy + dz * dz < r * r) ++b.count[i], ++b.count[j];
            const double t = std::max(tolerance[c.group[i]], tolerance[c.group[j]]);
            if (preproc::coincident_at(c.x[i], c.y[i], c.z[i], c.x[j], c.y[j], c.z[j], t)) b.pairs.push_back({i, j});
        }
    return b;
}

// A one-part deck: a regular lattice (8 x 6 x 5 by default, kSpacing apart; every nearest distance the
// same, so that one particle moved keeps the part's spacing) and `crowd` more particles at the place of
// particle 0; `sphini` the section's h0.
constexpr double kSpacing = 0.01;
std::string crowd_deck(int crowd, int nx = 8, int ny = 6, int nz = 5, const char* sphini = "0.013") {
    std::string deck = "*KEYWORD\n*CONTROL_SPH\n         1         0   1.0e+20         3       150\n";
    deck += fmt::format("*SECTION_SPH\n{:>10}{:>10}{:>10}{:>10}{:>10}\n", 1, "1.2", "0.2", "2.0", sphini);
    deck += "*PART\nblock\n         1         1         1         1\n";
    deck += "*MAT_NULL\n         1    1000.0\n*EOS_MURNAGHAN\n         1       7.0     340.0\n";
    std::string nodes = "*NODE\n", elements = "*ELEMENT_SPH\n";
    int id = 0;
    const auto add = [&](double x, double y, double z) {
        ++id;
        nodes += fmt::format("{:>8}{:>16.9e}{:>16.9e}{:>16.9e}\n", id, x, y, z);
        elements += fmt::format("{:>8}{:>8}{:>16}\n", id, 1, "1.0e-3");
    };
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            for (int k = 0; k < nz; ++k) add(i * kSpacing, j * kSpacing, k * kSpacing);
    for (int m = 0; m < crowd; ++m) add(0, 0, 0);
    return deck + nodes + elements + "*END\n";
}

preproc::PreviewOptions kept() {
    preproc::PreviewOptions options;
    options.particle_arrays = false;
    options.neighbour_counts = true;
    return options;
}

// The values an edit can change, or what differs.
std::string difference(const preproc::Preview& a, const preproc::Preview& b) {
    if (a.coincident_pairs != b.coincident_pairs)
        return fmt::format("{} coincident pairs against {}", a.coincident_pairs, b.coincident_pairs);
    if (a.coincident != b.coincident) return "the coincident pairs kept";
    if (a.particles.neighbours != b.particles.neighbours) return "neighbour counts";
    if (a.particles.nn_distance != b.particles.nn_distance) return "nearest distances";
    if (a.parts.size() != b.parts.size()) return "parts";
    for (std::size_t q = 0; q < a.parts.size(); ++q)
        if (a.parts[q].spacing != b.parts[q].spacing || a.parts[q].neighbours.median != b.parts[q].neighbours.median)
            return "part statistics";
    return {};
}

// Particle `particle`'s node moved to (x, y, z).
model::Model moved(const model::Model& m, std::size_t particle, double x, double y, double z) {
    model::Model now = m;
    const long long id = now.particles.node[particle];
    const auto k =
        static_cast<std::size_t>(std::find(now.nodes.id.begin(), now.nodes.id.end(), id) - now.nodes.id.begin());
    now.nodes.x[k] = x, now.nodes.y[k] = y, now.nodes.z[k] = z;
    return now;
}

}  // namespace

TEST_CASE("coincident pairs: counts, number and first pairs equal a brute force on clouds with crowds") {
    // Crowds below and above the collapsing threshold (64), uniform and mixed supports, all pairs kept or few.
    const Cloud c = crowded(7, {3, 40, 70, 130}, 11);
    for (const bool mixed : {false, true}) {
        CAPTURE(mixed);
        const double support[2] = {2.4, mixed ? 1.9 : 2.4}, tolerance[2] = {1e-9, mixed ? 2e-9 : 1e-9};
        const Brute b = brute_force(c, support, tolerance);
        REQUIRE(b.pairs.size() > 9000);  // 130 at one place alone: 8385
        for (const std::size_t keep :
             {std::size_t{0}, std::size_t{1}, std::size_t{37}, preproc::coincident_pairs_kept, std::size_t{1} << 20}) {
            CAPTURE(keep);
            const preproc::NeighbourCounts counts =
                preproc::count_neighbours(c.x, c.y, c.z, preproc::GroupedRadii{c.group, support, tolerance}, 0, keep);
            CHECK(counts.sample_stride == 1);
            CHECK(counts.count == b.count);
            CHECK(counts.coincident_pairs == b.pairs.size());
            const std::vector<Pair> first(b.pairs.begin(), b.pairs.begin() + static_cast<std::ptrdiff_t>(
                                                                                 std::min(keep, b.pairs.size())));
            CHECK(counts.coincident == first);
        }
    }
}

TEST_CASE("coincident pairs: counted and kept in full when the counts are sampled") {
    // A pair budget of 1000 sends the counts to their sampled path, which looks at no pair of most points; the
    // coincident pairs must still be every one (close_pairs.hpp), with and without points collapsed.
    const Cloud c = crowded(7, {3, 40, 70, 130}, 12);
    const double support[2] = {2.4, 1.9}, tolerance[2] = {1e-9, 2e-9};
    const Brute b = brute_force(c, support, tolerance);
    for (const std::size_t keep : {std::size_t{37}, preproc::coincident_pairs_kept, std::size_t{1} << 20}) {
        CAPTURE(keep);
        const preproc::NeighbourCounts counts =
            preproc::count_neighbours(c.x, c.y, c.z, preproc::GroupedRadii{c.group, support, tolerance}, 1000, keep);
        CHECK(counts.sample_stride > 1);
        CHECK(counts.coincident_pairs == b.pairs.size());
        const std::vector<Pair> first(b.pairs.begin(),
                                      b.pairs.begin() + static_cast<std::ptrdiff_t>(std::min(keep, b.pairs.size())));
        CHECK(counts.coincident == first);
    }
}

TEST_CASE("coincident pairs: a deck whose counts are sampled reports every pair once") {
    // 32^3 particles in one support (h0 1.0 on a 0.31 cube): 5.4e8 pairs, past the budget, so the counts are
    // sampled; 70 more at particle 0's place make 71 * 70 / 2 pairs, not the parts' nearest-neighbour pairs
    // alone (70), nor those counted twice.
    engine::CheckOptions options;
    options.rules.keep_preview = true;
    const engine::CheckResult checked = engine::check_buffer(crowd_deck(70, 32, 32, 32, "1.0"), "crowd.k", options);
    REQUIRE(checked.preview);
    CHECK(checked.preview->neighbour_sample_stride > 1);
    CHECK(checked.preview->coincident_pairs == 71u * 70 / 2);
    CHECK(checked.preview->coincident.size() == preproc::coincident_pairs_kept);
    CHECK(checked.preview->coincident.front() == Pair{0, 32u * 32 * 32});
}

TEST_CASE("coincident pairs: every pair within the reach found once on 64-bit keys") {
    // Pairs at, just inside and just outside the reach, along and across the axes, near the origin and far
    // from it (where a coordinate's rounding is larger than the reach), and points with no finite place.
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const double offset : {0.0, 1.0e6, -3.7e3, 1.0e-7})
        for (const double reach : {1e-9, 1e-3, 0.25, 0.0}) {
            CAPTURE(offset);
            CAPTURE(reach);
            Cloud c;
            for (int i = 0; i < 300; ++i) {
                const double x = offset + u(rng), y = u(rng), z = offset + u(rng);
                c.add(x, y, z);
                const double d = reach * (1 + 0.5 * u(rng));
                c.add(x + (i % 3 == 0 ? d : 0), y + (i % 3 == 1 ? d : 0), z + (i % 3 == 2 ? d : 0));
                c.add(std::nextafter(x + reach, 1e300), y, z);
                c.add(x, y, std::nextafter(z - reach, -1e300));
                if (i % 50 == 0) c.add(x, y, z), c.add(x, y, z);
            }
            c.add(std::nan(""), 0, 0), c.add(0, std::numeric_limits<double>::infinity(), 0), c.add(0, 0, 0);
            std::map<Pair, int> found;
            preproc::for_each_close_pair(c.x, c.y, c.z, reach, [&](std::uint32_t a, std::uint32_t b) {
                ++found[{std::min(a, b), std::max(a, b)}];
            });
            std::size_t within = 0;
            for (std::uint32_t i = 0; i < c.size(); ++i)
                for (std::uint32_t j = i + 1; j < c.size(); ++j) {
                    if (!preproc::coincident_at(c.x[i], c.y[i], c.z[i], c.x[j], c.y[j], c.z[j], reach)) continue;
                    ++within;
                    const auto at = found.find({i, j});
                    CHECK_MESSAGE(at != found.end(), "pair ", i, " ", j, " not offered");
                }
            REQUIRE(within > (reach > 0 ? 100u : 10u));
            for (const auto& entry : found) CHECK_MESSAGE(entry.second == 1, "pair offered ", entry.second, " times");
        }
}

TEST_CASE("coincident pairs: a crowd far past the bound is counted exactly, its first pairs kept") {
    // 40000 particles at one place: 8e8 pairs, past the pair budget (5e8): counted point by point, the counts
    // would be sampled and the pairs never looked at; collapsed, one point of weight 40000.
    Cloud c = crowded(6, {}, 5);
    const std::uint32_t lattice = static_cast<std::uint32_t>(c.size()), m = 40000;
    for (std::uint32_t k = 0; k < m; ++k) c.add(2.5, 2.5, 2.5);  // no lattice point within 0.5
    std::vector<double> support(c.size(), 1.0), tolerance(c.size(), 1e-9);
    const preproc::NeighbourCounts counts = preproc::count_neighbours(c.x, c.y, c.z, support, tolerance);
    CHECK(counts.sample_stride == 1);
    CHECK(counts.coincident_pairs == std::uint64_t{m} * (m - 1) / 2);
    REQUIRE(counts.coincident.size() == preproc::coincident_pairs_kept);
    // The first pairs: the crowd's first point with the next 999.
    for (std::uint32_t k = 0; k < counts.coincident.size(); ++k)
        CHECK(counts.coincident[k] == Pair{lattice, lattice + 1 + k});
    // Each of the crowd: the others, and the lattice's points within the support.
    const std::vector<std::uint32_t> reference =
        preproc::count_neighbours_all_pairs(std::span(c.x).first(lattice + 1), std::span(c.y).first(lattice + 1),
                                            std::span(c.z).first(lattice + 1), std::span(support).first(lattice + 1));
    REQUIRE(reference[lattice] > 0);
    for (std::uint32_t k = lattice; k < c.size(); k += 997) CHECK(counts.count[k] == m - 1 + reference[lattice]);
    // The lattice's: theirs, with the crowd's whole weight where it stands within the support (one of it there).
    for (std::uint32_t k = 0; k < lattice; ++k) {
        const double dx = c.x[k] - 2.5, dy = c.y[k] - 2.5, dz = c.z[k] - 2.5;
        const bool near = dx * dx + dy * dy + dz * dz < 1.0;
        CHECK(counts.count[k] == reference[k] + (near ? m - 1 : 0));
    }
}

TEST_CASE("coincident pairs: the first pairs of a set offered in order, and the pairs between two sets") {
    preproc::FirstPairs among(5);
    const std::uint32_t a[] = {2, 5, 9, 11};
    among.offer_among(a);
    CHECK(std::move(among).sorted() == std::vector<Pair>{{2, 5}, {2, 9}, {2, 11}, {5, 9}, {5, 11}});
    preproc::FirstPairs between(4);
    const std::uint32_t b[] = {3, 4, 12};
    between.offer_between(a, b);
    CHECK(std::move(between).sorted() == std::vector<Pair>{{2, 3}, {2, 4}, {2, 12}, {3, 5}});
    preproc::FirstPairs later(2);  // pairs offered out of order: the smallest stay
    for (const Pair& p : {Pair{7, 8}, Pair{1, 9}, Pair{3, 4}, Pair{1, 2}}) later.offer(p);
    CHECK(std::move(later).sorted() == std::vector<Pair>{{1, 2}, {1, 9}});
}

TEST_CASE("coincident pairs: SPH114 and smooth say how many pairs there are, past the pairs kept") {
    engine::CheckOptions options;
    options.rules.keep_preview = true;
    const engine::CheckResult checked = engine::check_buffer(crowd_deck(99), "crowd.k", options);
    REQUIRE(checked.preview);
    CHECK(checked.preview->coincident_pairs == 100u * 99 / 2);  // particle 0 and the 99
    CHECK(checked.preview->coincident.size() == preproc::coincident_pairs_kept);
    std::size_t listed = 0;
    for (const diag::Diagnostic& d : checked.diagnostics)
        if (d.code == "SPH114") {
            if (listed == 0) CHECK(d.message.find("(4950 pairs in all)") != std::string::npos);
            ++listed;
        }
    CHECK(listed == 20);
}

TEST_CASE("coincident pairs: moves into and out of a crowd give the fresh preview, followed or recomputed") {
    // 40 at one place with particle 0 (820 pairs: every pair kept, the edit followed), and 60 (1830: the first
    // 1000 kept, the edit recomputed); one particle moved into the crowd, then one of the crowd moved out.
    for (const int crowd : {40, 60, 44}) {
        CAPTURE(crowd);
        engine::CheckOptions options;
        options.rules.keep_preview = true;
        const engine::CheckResult first = engine::check_buffer(crowd_deck(crowd), "crowd.k", options);
        REQUIRE(first.preview);
        const model::Model& before = first.model;
        const preproc::Preview& old = *first.preview;
        REQUIRE(difference(old, preproc::compute_preview(before, kept())).empty());
        const std::uint64_t pairs = std::uint64_t(crowd + 1) * crowd / 2;
        REQUIRE(old.coincident_pairs == pairs);
        CHECK(old.coincident.size() == std::min<std::uint64_t>(pairs, preproc::coincident_pairs_kept));
        for (const bool into : {true, false}) {
            CAPTURE(into);
            // Into: particle 100 (a lattice particle) onto the crowd's place. Out of: the crowd's last particle onto
            // a place of its own, half a spacing beyond the lattice's far corner.
            const model::Model now =
                into ? moved(before, 100, 0, 0, 0)
                     : moved(before, before.particles.size() - 1, 7.5 * kSpacing, 5.5 * kSpacing, 4.5 * kSpacing);
            const preproc::Preview fresh = preproc::compute_preview(now, kept());
            CHECK(fresh.coincident_pairs == (into ? pairs + crowd + 1 : pairs - crowd));
            const auto followed = preproc::follow_particle_edit(old, before, now);
            // Followed where every pair was kept (and none of them is kept when recomputing), else refused.
            CHECK(followed.has_value() == (old.coincident.size() == old.coincident_pairs));
            if (followed) CHECK_MESSAGE(difference(*followed, fresh).empty(), difference(*followed, fresh));
            const auto again = engine::preview_after_edit(first, now, false);
            REQUIRE(again);
            CHECK_MESSAGE(difference(*again, fresh).empty(), difference(*again, fresh));
        }
        // A settings edit (HMAX alone: the supports stand; SPHINI too: they move): the places' values kept
        // where every pair was, else recomputed; the fresh preview's either way.
        for (const double sphini : {0.013, 0.014}) {
            CAPTURE(sphini);
            model::Model changed = before;
            changed.sections[0].hmax.value = 3.0;
            changed.sections[0].sphini.value = sphini;
            const preproc::Preview fresh = preproc::compute_preview(changed, kept());
            const auto direct = preproc::recompute_settings(changed, old, kept());
            CHECK(direct.has_value() == (old.coincident.size() == old.coincident_pairs));
            if (direct) CHECK_MESSAGE(difference(*direct, fresh).empty(), difference(*direct, fresh));
            const auto again = engine::preview_after_edit(first, changed, false);
            REQUIRE(again);
            CHECK_MESSAGE(difference(*again, fresh).empty(), difference(*again, fresh));
        }
    }
}

}  // namespace test_coincident_pairs_cpp
