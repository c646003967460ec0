// follow_particle_edit (preproc/preview_follow.hpp): the preview of a model whose particles moved,
// came or went, updated from the preview before the edit. Distances are computed with the same
// expression as the full preview's searches (nearest_neighbours.cpp), so the values agree bit for bit.
#include "preproc/preview_follow.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <functional>
#include <span>
#include <limits>
#include <string>

#include "preproc/nearest_neighbours.hpp"
#include "preproc/particle_positions.hpp"
#include "preproc/preview_follow_window.hpp"
#include "preproc/smoothing_length.hpp"
#include "preproc/stats_of.hpp"

namespace sphdeck::preproc {
namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

struct Place {
    double x = 0, y = 0, z = 0;
};

double squared_distance(const Place& a, const Place& b) {
    const double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
    return dx * dx + dy * dy + dz * dz;
}

// sqrt(r2) <= d, the square root taken only near the bound (most particles stand far away).
bool within_reach(double r2, double d) { return r2 <= d * d * (1 + 1e-9) && std::sqrt(r2) <= d; }

Place place_of(const ParticlePositions& at, std::size_t i) { return {at.x(i), at.y(i), at.z(i)}; }

// The first index below `n` where a and b differ bitwise (n when none), block by block with memcmp.
template <typename T>
std::size_t first_difference(const T* a, const T* b, std::size_t n) {
    constexpr std::size_t kBlock = 1024;
    std::size_t i = 0;
    while (i + kBlock <= n && std::memcmp(a + i, b + i, kBlock * sizeof(T)) == 0) i += kBlock;
    while (i < n && std::memcmp(a + i, b + i, sizeof(T)) == 0) ++i;
    return i;
}

// The same from the end: the count of equal elements at the ends of a[0, n) and b[0, n).
template <typename T>
std::size_t common_tail(const T* a, const T* b, std::size_t n) {
    constexpr std::size_t kBlock = 1024;
    std::size_t k = 0;
    while (k + kBlock <= n && std::memcmp(a + n - k - kBlock, b + n - k - kBlock, kBlock * sizeof(T)) == 0) k += kBlock;
    while (k < n && std::memcmp(a + n - k - 1, b + n - k - 1, sizeof(T)) == 0) ++k;
    return k;
}

// The particles of `now` against those of `before`: a common run at the start and one at the end;
// old [prefix, old_end) were replaced by new [prefix, new_end).
struct ParticleDiff {
    std::size_t prefix = 0, old_end = 0, new_end = 0;
    // The index before the edit of new particle j, kNone for an added one.
    std::uint32_t old_index(std::size_t j) const {
        if (j < prefix) return static_cast<std::uint32_t>(j);
        if (j >= new_end) return static_cast<std::uint32_t>(j - new_end + old_end);
        return kNone;
    }
};

ParticleDiff diff_particles(const model::Particles& before, const model::Particles& now) {
    ParticleDiff d;
    const std::size_t n_old = before.size(), n_new = now.size(), common = std::min(n_old, n_new);
    // Bitwise (a mass written -0.0 for 0.0 counts as changed: the particle is then computed again).
    d.prefix = std::min({first_difference(before.node, now.node, common),  // model::IdColumn's
                         first_difference(before.part, now.part, common),
                         first_difference(before.mass.data(), now.mass.data(), common),
                         first_difference(before.volume.data(), now.volume.data(), common)});
    const auto tail = [&](const auto& a, const auto& b) {
        if constexpr (std::is_same_v<std::decay_t<decltype(a)>, model::IdColumn>)
            return common_tail(a, n_old, b, n_new, common - d.prefix);
        else
            return common_tail(a.data() + n_old - (common - d.prefix), b.data() + n_new - (common - d.prefix),
                               common - d.prefix);
    };
    const std::size_t suffix = std::min({tail(before.node, now.node), tail(before.part, now.part),
                                         tail(before.mass, now.mass), tail(before.volume, now.volume)});
    d.old_end = n_old - suffix;
    d.new_end = n_new - suffix;
    return d;
}

// stats_of (preproc/stats_of.hpp) from one pass over `values` when at most a few changed since their median was
// `pivot`: the values below and at the pivot are counted and the `window` nearest on each side kept, which hold the new
// median unless more than about `window` values crossed it (then nullopt).
template <typename T>
std::optional<Stats> statistics_near(std::span<const T> values, double pivot, std::size_t window) {
    Stats s;
    if (values.empty()) return s;
    std::size_t below = 0, equal = 0;
    std::vector<T> under, over;  // heaps: the largest values below the pivot, the smallest above it
    under.reserve(window + 1), over.reserve(window + 1);
    T lo = values[0], hi = values[0];
    for (const T v : values) {
        lo = std::min(lo, v), hi = std::max(hi, v);
        const double d = static_cast<double>(v);
        if (d == pivot) {
            ++equal;
        } else if (d < pivot) {
            ++below;
            if (under.size() < window || v > under.front()) {
                under.push_back(v), std::push_heap(under.begin(), under.end(), std::greater<T>());
                if (under.size() > window)
                    std::pop_heap(under.begin(), under.end(), std::greater<T>()), under.pop_back();
            }
        } else if (over.size() < window || v < over.front()) {
            over.push_back(v), std::push_heap(over.begin(), over.end());
            if (over.size() > window) std::pop_heap(over.begin(), over.end()), over.pop_back();
        }
    }
    std::sort(under.begin(), under.end()), std::sort(over.begin(), over.end());
    const auto rank = [&](std::size_t r) -> std::optional<T> {  // the r-th smallest (0-based)
        if (r < below) {
            if (r + under.size() < below) return std::nullopt;
            return under[r + under.size() - below];
        }
        if (r < below + equal) return static_cast<T>(pivot);
        if (r - below - equal < over.size()) return over[r - below - equal];
        return std::nullopt;
    };
    const std::size_t mid = values.size() / 2;
    const auto at_mid = rank(mid);
    if (!at_mid) return std::nullopt;
    s.min = static_cast<double>(lo), s.max = static_cast<double>(hi);
    s.median = static_cast<double>(*at_mid);
    if (values.size() % 2 == 0) {
        const auto before = rank(mid - 1);
        if (!before) return std::nullopt;
        s.median = 0.5 * (s.median + static_cast<double>(*before));
    }
    return s;
}

template <typename T>
Stats statistics_from(std::span<const T> values, double pivot) {
    if (auto s = statistics_near(values, pivot, 1024)) return *s;
    return stats_of(std::vector<T>(values.begin(), values.end()));
}

// A changed particle: where it stands (new, or old for one moved or removed) and its part index.
struct Changed {
    std::uint32_t index = 0;  // new index (a moved or added particle), else its old index
    std::uint32_t part = 0;
    Place at;
};

class Follower {
public:
    Follower(const Preview& old, const model::Model& before, const model::Model& now)
        : old_(old), before_(before), now_(now), at_before_(before), at_now_(now) {}

    std::optional<Preview> run(const FollowOptions& options) {
        if (!applies()) return std::nullopt;
        window_width_ = options.window_width;
        diff_ = diff_particles(before_.particles, now_.particles);
        if (!find_changes(options.max_changed)) return std::nullopt;
        if (!build_arrays()) return std::nullopt;
        update_unchanged(options.forget_old_places);
        kept_pairs();
        search_again();
        std::sort(out_.coincident.begin(), out_.coincident.end());
        out_.coincident.erase(std::unique(out_.coincident.begin(), out_.coincident.end()), out_.coincident.end());
        out_.coincident_pairs = out_.coincident.size();  // every pair (applies()), the first kept
        if (out_.coincident.size() > coincident_pairs_kept) {
            out_.coincident.resize(coincident_pairs_kept);
            out_.coincident.shrink_to_fit();
        }
        if (!part_statistics()) return std::nullopt;
        return std::move(out_);
    }

private:
    bool applies() const {
        const ParticlePreview& pp = old_.particles;
        return !before_.radioss && !now_.radioss && !old_.radioss && pp.x.empty() &&
               old_.neighbour_sample_stride == 1 && pp.neighbours.size() == before_.particles.size() &&
               old_.coincident.size() == old_.coincident_pairs &&  // every pair kept, to renumber
               pp.part.size() == before_.particles.size() && pp.nn_distance.size() == before_.particles.size() &&
               now_.particles.size() > 0;
    }

    std::optional<std::uint32_t> part_index(long long id) const {
        const auto found = std::lower_bound(old_.parts.begin(), old_.parts.end(), id,
                                            [](const PartPreview& p, long long v) { return p.part < v; });
        if (found == old_.parts.end() || found->part != id) return std::nullopt;
        return static_cast<std::uint32_t>(found - old_.parts.begin());
    }

    // The moved, added and removed particles; false when the update does not apply.
    bool find_changes(std::size_t max_changed) {
        const std::size_t n_new = now_.particles.size();
        changed_.assign(n_new, 0);
        part_delta_.assign(old_.parts.size(), 0);
        for (std::size_t i = diff_.prefix; i < diff_.old_end; ++i) {  // removed
            if (at_before_.node(i) == ParticlePositions::none) return false;
            const std::uint32_t q = old_.particles.part[i];
            gone_.push_back({static_cast<std::uint32_t>(i), q, place_of(at_before_, i)});
            --part_delta_[q];
            masses_changed_ = true;
        }
        for (std::size_t j = diff_.prefix; j < diff_.new_end; ++j) {  // added
            const auto q = part_index(now_.particles.part[j]);
            if (!q || at_now_.node(j) == ParticlePositions::none) return false;
            came_.push_back({static_cast<std::uint32_t>(j), *q, place_of(at_now_, j)});
            changed_[j] = 1;
            ++part_delta_[*q];
            masses_changed_ = true;
        }
        // Moved: a particle on both sides whose node stands elsewhere (one pass over the positions).
        const auto moved = [&](std::size_t j) {
            const std::uint32_t o = diff_.old_index(j);
            const bool located_before = at_before_.node(o) != ParticlePositions::none;
            const bool located_now = at_now_.node(j) != ParticlePositions::none;
            if (located_before != located_now) return false;  // a node that came or went
            if (!located_now) return true;
            const Place a = place_of(at_before_, o), b = place_of(at_now_, j);
            if (a.x == b.x && a.y == b.y && a.z == b.z) return true;
            const std::uint32_t q = old_.particles.part[o];
            gone_.push_back({o, q, a});
            came_.push_back({static_cast<std::uint32_t>(j), q, b});
            changed_[j] = 1;
            return gone_.size() <= max_changed && came_.size() <= max_changed;
        };
        if (at_before_.in_place() && at_now_.in_place()) {
            // Particle i is node i on both sides (every particle located): the node arrays compared
            // block by block, only the particles in differing blocks one by one.
            const model::Nodes &a = before_.nodes, &b = now_.nodes;
            const auto scan = [&](std::size_t first, std::size_t last) {  // new indices [first, last)
                constexpr std::size_t kBlock = 512;
                const std::size_t shift = first < diff_.prefix ? 0 : diff_.old_end;
                const std::size_t base = first < diff_.prefix ? 0 : diff_.new_end;
                for (std::size_t j = first; j < last; j += kBlock) {
                    const std::size_t n = std::min(kBlock, last - j), o = j - base + shift;
                    if (std::memcmp(a.x.data() + o, b.x.data() + j, n * sizeof(double)) == 0 &&
                        std::memcmp(a.y.data() + o, b.y.data() + j, n * sizeof(double)) == 0 &&
                        std::memcmp(a.z.data() + o, b.z.data() + j, n * sizeof(double)) == 0)
                        continue;
                    for (std::size_t k = j; k < j + n; ++k)
                        if (!moved(k)) return false;
                }
                return true;
            };
            if (!scan(0, diff_.prefix) || !scan(diff_.new_end, n_new)) return false;
        } else {
            for (std::size_t j = 0; j < diff_.prefix; ++j)
                if (!moved(j)) return false;
            for (std::size_t j = diff_.new_end; j < n_new; ++j)
                if (!moved(j)) return false;
        }
        if (gone_.size() > max_changed || came_.size() > max_changed) return false;
        for (std::size_t q = 0; q < old_.parts.size(); ++q)
            if (static_cast<long long>(old_.parts[q].particles) + part_delta_[q] <= 0) return false;  // a part empties
        return true;
    }

    // The per-particle arrays of the new model: those of the particles kept, blanks for the others.
    bool build_arrays() {
        out_.dimension = old_.dimension;
        out_.parts = old_.parts;
        out_.neighbour_sample_stride = 1;
        const std::size_t n_new = now_.particles.size();
        const ParticlePreview& a = old_.particles;
        ParticlePreview& b = out_.particles;
        // The kept particles' values: the run before the edited ones, then the run after them.
        const auto splice = [&](const auto& from, auto& to, auto added) {
            using T = typename std::decay_t<decltype(to)>::value_type;
            to.reserve(n_new);
            to.assign(from.begin(), from.begin() + static_cast<std::ptrdiff_t>(diff_.prefix));
            to.resize(diff_.new_end, static_cast<T>(added));
            to.insert(to.end(), from.begin() + static_cast<std::ptrdiff_t>(diff_.old_end), from.end());
        };
        splice(a.part, b.part, 0);
        splice(a.located, b.located, 1);  // an added particle has a node (find_changes)
        splice(a.nn_distance, b.nn_distance, 0.0);
        splice(a.neighbours, b.neighbours, 0);
        for (std::size_t j = diff_.prefix; j < diff_.new_end; ++j) b.part[j] = *part_index(now_.particles.part[j]);
        again_.assign(n_new, 0);
        touched_.assign(old_.parts.size(), 0);
        for (const Changed& c : gone_) touched_[c.part] = 1;
        for (const Changed& c : came_) touched_[c.part] = 1;
        return true;
    }

    double support(std::uint32_t q) const { return old_.parts[q].support; }
    double tolerance(std::uint32_t q) const { return 1e-9 * old_.parts[q].spacing; }

    // The particles that did not change: a count moved by one for each changed particle that left or
    // entered their support, a nearer nearest neighbour, or a search again when their nearest one left.
    void update_unchanged(bool forget_old_places) {
        ParticlePreview& b = out_.particles;
        const std::size_t n_new = now_.particles.size();
        const int threads = pass_threads(n_new);
#pragma omp parallel num_threads(threads) if (threads > 1)
        {
            std::vector<std::uint32_t> mine;  // the particles whose values changed
#pragma omp for schedule(static) nowait
            for (std::size_t j = 0; j < n_new; ++j) {
                if (changed_[j] || !b.located[j]) continue;
                const std::uint32_t q = b.part[j];
                const double sj = support(q);
                const Place p = place_of(at_now_, j);
                double nearest = b.nn_distance[j];
                std::uint32_t count = b.neighbours[j];
                bool search = false;
                for (const Changed& c : gone_) {
                    const double r2 = squared_distance(p, c.at);
                    const double r = 0.5 * (sj + support(c.part));
                    if (r2 < r * r && !forget_old_places) --count;
                    if (c.part == q && (nearest == 0 || within_reach(r2, nearest))) search = true;
                }
                for (const Changed& c : came_) {
                    const double r2 = squared_distance(p, c.at);
                    const double r = 0.5 * (sj + support(c.part));
                    if (r2 < r * r) ++count;
                    if (c.part != q) continue;
                    if (nearest == 0)
                        search = true;  // no neighbour before, or one at the same place: search again
                    else if (within_reach(r2, nearest))
                        nearest = std::min(nearest, std::sqrt(r2));
                }
                if (count != b.neighbours[j] || nearest != b.nn_distance[j] || search) {
#pragma omp atomic write
                    touched_[q] = 1;
                    mine.push_back(static_cast<std::uint32_t>(j));
                }
                b.neighbours[j] = count;
                b.nn_distance[j] = nearest;
                if (search) again_[j] = 1;
            }
#pragma omp critical(sphdeck_preview_follow_edited)
            edited_.insert(edited_.end(), mine.begin(), mine.end());
        }
    }

    // The pairs at one place of the particles kept stay, renumbered (those of the changed particles are
    // found again by search_again).
    void kept_pairs() {
        std::vector<std::uint8_t> gone_old(before_.particles.size(), 0);
        for (const Changed& c : gone_) gone_old[c.index] = 1;
        const auto new_index = [&](std::uint32_t o) -> std::uint32_t {
            if (o < diff_.prefix) return o;
            if (o >= diff_.old_end) return static_cast<std::uint32_t>(o - diff_.old_end + diff_.new_end);
            return kNone;
        };
        for (auto [i, j] : old_.coincident) {
            if (gone_old[i] || gone_old[j]) continue;
            const std::uint32_t a = new_index(i), b = new_index(j);
            if (a != kNone && b != kNone) out_.coincident.emplace_back(a, b);
        }
    }

    // One pass over every particle for the particles searched again and the changed ones: their
    // nearest neighbour (same part) and, for the changed ones, their count and their pairs at one place.
    void search_again() {
        struct Query {
            std::uint32_t index, part;
            Place at;
            bool changed;
            double best2 = std::numeric_limits<double>::infinity();
            std::uint32_t neighbours = 0;
        };
        ParticlePreview& b = out_.particles;
        const std::size_t n_new = now_.particles.size();
        std::vector<Query> queries;
        for (std::size_t j = 0; j < n_new; ++j)
            if (again_[j] || changed_[j])
                queries.push_back({static_cast<std::uint32_t>(j), b.part[j], place_of(at_now_, j), changed_[j] != 0});
        if (queries.empty()) return;
        for (const Query& q : queries) edited_.push_back(q.index);
        const int threads = pass_threads(n_new);
#pragma omp parallel num_threads(threads) if (threads > 1)
        {
            // Each thread scans a run of the particles with its own copy of the queries, merged after.
            std::vector<Query> mine = queries;
            std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
#pragma omp for schedule(static) nowait
            for (std::size_t k = 0; k < n_new; ++k) {
                if (!b.located[k]) continue;
                const Place at = place_of(at_now_, k);
                const std::uint32_t part = b.part[k];
                for (Query& q : mine) {
                    if (q.index == k) continue;
                    const double r2 = squared_distance(q.at, at);
                    if (part == q.part && r2 < q.best2) q.best2 = r2;
                    if (!q.changed) continue;
                    const double r = 0.5 * (support(q.part) + support(part));
                    q.neighbours += r2 < r * r;
                    const double t = std::max(tolerance(q.part), tolerance(part));
                    if (r2 <= t * t)
                        pairs.emplace_back(std::min<std::uint32_t>(q.index, static_cast<std::uint32_t>(k)),
                                           std::max<std::uint32_t>(q.index, static_cast<std::uint32_t>(k)));
                }
            }
#pragma omp critical(sphdeck_preview_follow_merge)
            {
                for (std::size_t i = 0; i < queries.size(); ++i) {
                    queries[i].best2 = std::min(queries[i].best2, mine[i].best2);
                    queries[i].neighbours += mine[i].neighbours;
                }
                out_.coincident.insert(out_.coincident.end(), pairs.begin(), pairs.end());
            }
        }
        for (const Query& q : queries) {
            b.nn_distance[q.index] = std::isinf(q.best2) ? 0.0 : std::sqrt(q.best2);
            if (q.changed) b.neighbours[q.index] = q.neighbours;
        }
    }

    // The statistics of the parts touched, taken again from their particles; false when a part's h0
    // or spacing moved (then every support or tolerance of the part changes: recompute).
    bool part_statistics() {
        const ParticlePreview& pp = out_.particles;
        const model::Particles& particles = now_.particles;
        const model::IniMode mode = now_.controls.sph.ini.value;
        for (std::size_t q = 0; q < out_.parts.size(); ++q) {
            if (!touched_[q]) continue;
            PartPreview& pv = out_.parts[q];
            const SectionOf section = section_of(pv.part);
            // One part of located particles only (the usual big deck): its values are the arrays themselves.
            const bool whole = out_.parts.size() == 1 && !masses_changed_ && mode != model::IniMode::FromMass &&
                               std::find(pp.located.begin(), pp.located.end(), 0) == pp.located.end();
            std::vector<double> distances, masses, volumes;
            std::vector<std::uint32_t> counts;
            double mass_total = 0;
            std::size_t members = 0;
            for (std::size_t i = 0; i < pp.part.size() && !whole; ++i) {
                if (pp.part[i] != q) continue;
                ++members;
                const bool volume_flag = particles.volume[i] != 0;
                const double mass =
                    masses_changed_ ? particle_mass(particles.mass[i], volume_flag, section.density) : 0;
                mass_total += mass;
                if (!pp.located[i]) continue;
                if (masses_changed_) masses.push_back(mass);
                distances.push_back(pp.nn_distance[i]);
                counts.push_back(pp.neighbours[i]);
                if (mode == model::IniMode::FromMass)
                    volumes.push_back(particle_volume(particles.mass[i], volume_flag, section.density));
            }
            const std::span<const double> d = whole ? std::span<const double>(pp.nn_distance) : distances;
            const std::span<const std::uint32_t> c = whole ? std::span<const std::uint32_t>(pp.neighbours) : counts;
            std::optional<FollowWindows> windows;
            if (whole) windows = follow_windows(pv, d, c);
            const auto window_stats = [](const auto& window, const auto& values) {
                if (auto s = window.stats()) return *s;
                using T = typename std::decay_t<decltype(values)>::value_type;
                return stats_of(std::vector<T>(values.begin(), values.end()));
            };
            const Stats nn =
                windows ? window_stats(windows->nn_distance, d) : statistics_from(d, pv.nn_distance.median);
            // h0 of INI 0 and 1 is CSLH times the largest nearest distance, known from the statistics.
            const double largest[2] = {nn.max, nn.max};
            const std::span<const double> for_h0 = windows && d.size() >= 2 ? std::span<const double>(largest) : d;
            const SmoothingLength h =
                initial_smoothing_length({section.section, mode, for_h0, volumes, out_.dimension});
            if (h.h0 != pv.h0) return false;
            if (nn.median != pv.spacing && !spacing_may_move(pv, nn, d)) return false;
            pv.spacing = nn.median;
            pv.nn_distance = nn;
            pv.neighbours = windows ? window_stats(windows->neighbours, c) : statistics_from(c, pv.neighbours.median);
            pv.follow = nullptr;
            if (windows && windows->nn_distance.recentre() && windows->neighbours.recentre()) {
                windows->nn_distance_data = pp.nn_distance.data(), windows->neighbours_data = pp.neighbours.data();
                pv.follow = std::make_shared<const FollowWindows>(std::move(*windows));
            }
            if (masses_changed_) {
                pv.particles = members;
                pv.mass_total = mass_total;
                pv.mass_median = stats_of(std::move(masses)).median;
            }
        }
        return true;
    }

    // Whether a part's spacing (the median nearest distance) may move to `spacing` with nothing else
    // changing: it sets the tolerance of the coincident pairs (1e-9 spacing), so no pair may lie within
    // the larger of the two tolerances: no particle of the part has a nearest distance there, and no
    // other part has particles that could stand there (pairs across parts are not searched here).
    bool spacing_may_move(const PartPreview& pv, const Stats& nn, std::span<const double> distances) const {
        if (out_.parts.size() > 1) return false;
        const double band = 1e-9 * std::max(nn.median, pv.spacing);
        // None of the distances within the band: their smallest is past it.
        return distances.empty() || nn.min > band;
    }

    // The part's values near their medians: those the last followed edit kept, moved by the values this
    // edit changed (a few), or taken in a pass (the first followed edit, particles added or removed).
    FollowWindows follow_windows(const PartPreview& pv, std::span<const double> d, std::span<const std::uint32_t> c) {
        const std::size_t width = window_width_;
        const bool same_particles = diff_.prefix == diff_.old_end && diff_.prefix == diff_.new_end &&
                                    old_.particles.nn_distance.size() == d.size();
        const ParticlePreview& before = old_.particles;
        if (!pv.follow || !same_particles || pv.follow->nn_distance_data != before.nn_distance.data() ||
            pv.follow->neighbours_data != before.neighbours.data() || pv.follow->nn_distance.size() != d.size() ||
            pv.follow->neighbours.size() != c.size())
            return {RankWindow<double>::make(d, pv.nn_distance.median, width),
                    RankWindow<std::uint32_t>::make(c, static_cast<std::uint32_t>(pv.neighbours.median), width)};
        FollowWindows w = *pv.follow;
        std::sort(edited_.begin(), edited_.end());
        edited_.erase(std::unique(edited_.begin(), edited_.end()), edited_.end());
        for (const std::uint32_t j : edited_) {
            w.nn_distance.replace(before.nn_distance[j], d[j]);
            w.neighbours.replace(before.neighbours[j], c[j]);
        }
        w.nn_distance.settle_bounds(d);
        w.neighbours.settle_bounds(c);
        return w;
    }

    struct SectionOf {
        const model::Section* section = nullptr;
        double density = 0;
    };
    // The part's *SECTION_SPH and density as compute_preview resolves them (preview.cpp's resolve).
    SectionOf section_of(long long id) const {
        SectionOf out;
        const model::Part* part = now_.part(std::to_string(id));
        if (!part) return out;
        out.section = now_.section(part->section.value);
        if (out.section && !out.section->sph) out.section = nullptr;
        if (const model::Material* material = now_.material(part->material.value))
            out.density = material->density.value;
        return out;
    }

    const Preview& old_;
    const model::Model& before_;
    const model::Model& now_;
    const ParticlePositions at_before_, at_now_;
    ParticleDiff diff_;
    std::vector<Changed> gone_, came_;   // old places (moved, removed), new places (moved, added)
    std::vector<std::uint8_t> changed_;  // per new particle: moved or added
    std::vector<std::uint8_t> again_;    // per new particle: its nearest neighbour is searched again
    std::vector<std::uint8_t> touched_;  // per part: statistics to take again
    std::vector<long long> part_delta_;  // per part: particles added less removed
    std::size_t window_width_ = 1024;
    std::vector<std::uint32_t> edited_;  // new particles whose nearest distance or count may have changed
    bool masses_changed_ = false;
    Preview out_;
};

}  // namespace

std::optional<Preview> follow_particle_edit(const Preview& old, const model::Model& before, const model::Model& now,
                                            const FollowOptions& options) {
    Follower follower(old, before, now);
    return follower.run(options);
}

}  // namespace sphdeck::preproc
