// A preview that follows an edit (preproc/preview_follow.hpp, issue 45 item 3): after random moves,
// additions and removals of particles the followed preview equals compute_preview of the new model,
// value for value; a deliberately wrong update is caught; the editor's re-check uses it
// (engine/preview_after_edit.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <fmt/format.h>
#include <random>
#include <string>

#include "engine/check.hpp"
#include "engine/preview_after_edit.hpp"
#include "preproc/preview.hpp"
#include "preproc/preview_follow.hpp"
#include "preproc/preview_follow_window.hpp"
#include "preproc/stats_of.hpp"

namespace test_preview_follow_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

constexpr double kSpacing = 0.01;

// Two parts of particles on a jittered lattice, side by side (their supports overlap at the seam).
// `sphini`: the sections give h0 (else h0 = CSLH * the largest nearest distance, which most moves change).
std::string lattice_deck(bool sphini, int parts = 2) {
    std::string deck = "*KEYWORD\n*CONTROL_SPH\n         1         0   1.0e+20         3       150\n";
    for (int secid : {1, 2})
        deck += fmt::format("*SECTION_SPH\n{:>10}{:>10}{:>10}{:>10}{:>10}\n", secid, "1.2", "0.2", "2.0",
                            sphini ? (secid == 1 ? "0.013" : "0.012") : "0.0");
    deck +=
        "*PART\nleft\n         1         1         1         1\n*PART\nright\n         2         2         1         1\n";
    deck += "*MAT_NULL\n         1    1000.0\n*EOS_MURNAGHAN\n         1       7.0     340.0\n";
    std::mt19937 rng(45);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    std::string nodes = "*NODE\n", elements = "*ELEMENT_SPH\n";
    int id = 0;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 6; ++j)
            for (int k = 0; k < 5; ++k) {
                ++id;
                nodes += fmt::format("{:>8}{:>16.9e}{:>16.9e}{:>16.9e}\n", id, (i + jitter(rng)) * kSpacing,
                                     (j + jitter(rng)) * kSpacing, (k + jitter(rng)) * kSpacing);
                elements += fmt::format("{:>8}{:>8}{:>16}\n", id, i < 4 || parts == 1 ? 1 : 2, "1.0e-3");
            }
    return deck + nodes + elements + "*END\n";
}

preproc::PreviewOptions kept() {
    preproc::PreviewOptions options;
    options.particle_arrays = false;
    options.neighbour_counts = true;
    return options;
}

// Every value of two previews, or the first that differs.
std::string difference(const preproc::Preview& a, const preproc::Preview& b) {
    if (a.parts.size() != b.parts.size()) return "parts";
    for (std::size_t q = 0; q < a.parts.size(); ++q) {
        const auto &p = a.parts[q], &r = b.parts[q];
        const auto same_stats = [](const preproc::Stats& s, const preproc::Stats& t) {
            return s.min == t.min && s.median == t.median && s.max == t.max;
        };
        if (p.part != r.part || p.particles != r.particles || p.mass_total != r.mass_total || p.spacing != r.spacing ||
            p.h0 != r.h0 || p.h_min != r.h_min || p.h_max != r.h_max || !same_stats(p.nn_distance, r.nn_distance) ||
            !same_stats(p.neighbours, r.neighbours) || p.sound_speed != r.sound_speed ||
            p.dt_estimate != r.dt_estimate || p.support != r.support || p.mass_median != r.mass_median ||
            p.notes != r.notes)
            return fmt::format("part {}: nn {}/{}/{} against {}/{}/{}, neighbours {}/{}/{} against {}/{}/{}", p.part,
                               p.nn_distance.min, p.nn_distance.median, p.nn_distance.max, r.nn_distance.min,
                               r.nn_distance.median, r.nn_distance.max, p.neighbours.min, p.neighbours.median,
                               p.neighbours.max, r.neighbours.min, r.neighbours.median, r.neighbours.max);
    }
    const auto &x = a.particles, &y = b.particles;
    if (x.part != y.part || x.located != y.located) return "particle parts";
    for (std::size_t i = 0; i < x.nn_distance.size() && i < y.nn_distance.size(); ++i) {
        if (x.nn_distance[i] != y.nn_distance[i])
            return fmt::format("particle {}: nearest {} against {}", i, x.nn_distance[i], y.nn_distance[i]);
        if (x.neighbours[i] != y.neighbours[i])
            return fmt::format("particle {}: {} neighbours against {}", i, x.neighbours[i], y.neighbours[i]);
    }
    if (x.nn_distance.size() != y.nn_distance.size() || x.neighbours.size() != y.neighbours.size()) return "sizes";
    if (a.coincident != b.coincident || a.coincident_pairs != b.coincident_pairs)
        return fmt::format("coincident pairs: {} ({} kept) against {} ({} kept)", a.coincident_pairs,
                           a.coincident.size(), b.coincident_pairs, b.coincident.size());
    return {};
}

// One random edit of the particles: a move (now and then onto another particle), an addition or a removal.
void random_edit(model::Model& m, std::mt19937& rng, int parts) {
    auto& nodes = m.nodes;
    auto& particles = m.particles;
    std::uniform_int_distribution<std::size_t> any(0, particles.size() - 1);
    std::uniform_real_distribution<double> step(-0.4 * kSpacing, 0.4 * kSpacing);
    const auto node_of = [&](long long id) {
        return static_cast<std::size_t>(std::find(nodes.id.begin(), nodes.id.end(), id) - nodes.id.begin());
    };
    switch (rng() % 8) {
        case 0:
        case 1:
        case 2:
        case 3: {  // a move
            const std::size_t k = node_of(particles.node[any(rng)]);
            nodes.x[k] += step(rng), nodes.y[k] += step(rng), nodes.z[k] += step(rng);
            break;
        }
        case 4: {  // onto another particle
            const std::size_t k = node_of(particles.node[any(rng)]), l = node_of(particles.node[any(rng)]);
            nodes.x[k] = nodes.x[l], nodes.y[k] = nodes.y[l], nodes.z[k] = nodes.z[l];
            break;
        }
        case 5: {  // an addition, beside a particle, at a random place of the list
            const std::size_t k = node_of(particles.node[any(rng)]);
            const long long id = *std::max_element(nodes.id.begin(), nodes.id.end()) + 1;
            nodes.id.push_back(id);
            nodes.x.push_back(nodes.x[k] + step(rng)), nodes.y.push_back(nodes.y[k] + step(rng));
            nodes.z.push_back(nodes.z[k] + step(rng));
            const auto at = static_cast<std::ptrdiff_t>(any(rng));
            particles.node.insert(particles.node.begin() + at, id);
            particles.part.insert(particles.part.begin() + at, 1 + static_cast<long long>(rng() % parts));
            particles.mass.insert(particles.mass.begin() + at, 1.5e-3);
            particles.volume.insert(particles.volume.begin() + at, 0);
            particles.line.insert(static_cast<std::size_t>(at), 0);
            break;
        }
        default: {  // a removal
            const auto at = static_cast<std::ptrdiff_t>(any(rng));
            particles.node.erase(particles.node.begin() + at), particles.part.erase(particles.part.begin() + at);
            particles.mass.erase(particles.mass.begin() + at), particles.volume.erase(particles.volume.begin() + at);
            particles.line.erase(static_cast<std::size_t>(at));
        }
    }
}

// A settings edit through the re-check's preview: what it gives equals a full preview of the model.
template <typename Edit>
void section_or_control(const engine::CheckResult& first, Edit edit) {
    model::Model changed = first.model;
    edit(changed);
    const auto again = engine::preview_after_edit(first, changed, false);
    REQUIRE(again);
    CHECK(again != first.preview);
    const preproc::Preview full = preproc::compute_preview(changed, kept());
    CHECK_MESSAGE(difference(*again, full).empty(), difference(*again, full));
    const auto direct = preproc::recompute_settings(changed, *first.preview, kept());
    REQUIRE(direct);
    CHECK(difference(*direct, full).empty());
}

}  // namespace

TEST_CASE("preview follow: random moves, additions and removals give the full preview's values") {
    struct Variant {
        bool sphini;
        int parts;
    };
    for (const Variant variant : {Variant{true, 2}, Variant{true, 1}, Variant{false, 2}}) {
        CAPTURE(variant.sphini);
        CAPTURE(variant.parts);
        const engine::CheckResult checked =
            engine::check_buffer(lattice_deck(variant.sphini, variant.parts), "lattice.k");
        model::Model before = checked.model;
        REQUIRE(before.particles.size() == 240);
        preproc::Preview old = preproc::compute_preview(before, kept());
        REQUIRE(old.parts.size() == static_cast<std::size_t>(variant.parts));
        REQUIRE(old.parts[0].neighbours.median > 10);  // supports of a few spacings: the counts mean something
        std::mt19937 rng(variant.sphini ? 7u + static_cast<unsigned>(variant.parts) : 8u);
        int followed = 0;
        for (int round = 0; round < 40; ++round) {
            CAPTURE(round);
            model::Model now = before;
            const int edits = rng() % 4 == 0 ? 2 : 1;  // mostly one edit, as one types
            for (int e = 0; e < edits; ++e) random_edit(now, rng, variant.parts);
            const preproc::Preview full = preproc::compute_preview(now, kept());
            if (auto local = preproc::follow_particle_edit(old, before, now)) {
                ++followed;
                CHECK_MESSAGE(difference(*local, full).empty(), difference(*local, full));
            }
            before = std::move(now);
            old = full;
        }
        // Not every edit is followed: a moved h0, a moved spacing on a deck of two parts or beside
        // coincident particles, two edits far apart in the list are recomputed. How many are followed
        // depends on the compiler's rounding of the preview (gcc 13-15 of 40, clang 8-11): enough to prove
        // the followed previews equal, never all.
        MESSAGE("followed ", followed, " of 40");
        CHECK(followed >= 5);
        CHECK(followed < 40);
    }
}

TEST_CASE("preview follow: the values kept near a median give stats_of after random changes, or say they cannot") {
    // Windows of a few values and values with many ties (counts) or none (distances): each change is followed
    // by the window alone, then compared with stats_of on the whole array.
    std::mt19937 rng(4545);
    for (const std::size_t width : {std::size_t{16}, std::size_t{1024}}) {
        CAPTURE(width);
        std::vector<std::uint32_t> counts(301);
        std::vector<double> distances(300);
        for (auto& c : counts) c = 20 + rng() % 9;
        for (auto& d : distances) d = std::uniform_real_distribution<double>(0.5, 1.5)(rng);
        auto count_window = preproc::RankWindow<std::uint32_t>::make(counts, 24, width);
        auto distance_window = preproc::RankWindow<double>::make(distances, 1.0, width);
        int exact = 0, remade = 0;
        for (int round = 0; round < 400; ++round) {
            CAPTURE(round);
            // One to three values changed, now and then far from the median (a bound moves).
            for (int k = 0, n = 1 + static_cast<int>(rng() % 3); k < n; ++k) {
                const std::size_t i = rng() % counts.size(), j = rng() % distances.size();
                const std::uint32_t c = rng() % 10 == 0 ? rng() % 60 : 20 + rng() % 9;
                const double d = rng() % 10 == 0 ? std::uniform_real_distribution<double>(0.0, 3.0)(rng)
                                                 : distances[rng() % distances.size()] + 1e-3;
                count_window.replace(counts[i], c), counts[i] = c;
                distance_window.replace(distances[j], d), distances[j] = d;
            }
            count_window.settle_bounds(counts);
            distance_window.settle_bounds(distances);
            const preproc::Stats whole_counts = preproc::stats_of(counts),
                                 whole_distances = preproc::stats_of(distances);
            const auto a = count_window.stats();
            const auto b = distance_window.stats();
            if (a && b) {
                ++exact;
                CHECK(a->median == whole_counts.median);
                CHECK(a->min == whole_counts.min);
                CHECK(a->max == whole_counts.max);
                CHECK(b->median == whole_distances.median);
                CHECK(b->min == whole_distances.min);
                CHECK(b->max == whole_distances.max);
            }
            if (!a || !b || !count_window.recentre() || !distance_window.recentre()) {
                ++remade;  // as the follower does: a pass over the values again
                count_window = preproc::RankWindow<std::uint32_t>::make(counts, 24, width);
                distance_window = preproc::RankWindow<double>::make(distances, 1.0, width);
            }
        }
        MESSAGE("width ", width, ": ", exact, " of 400 from the window, ", remade, " made again");
        // Narrow windows among many equal counts are made again often; what they give is exact.
        CHECK(exact > (width == 1024 ? 399 : 20));
        if (width == 1024) CHECK(remade == 0);
    }
}

TEST_CASE("preview follow: a followed preview followed again gives the full preview's values") {
    // The part's statistics of a followed preview come from the values near its medians that the
    // last followed edit kept (preview_follow_window.hpp), not from a pass: chained here, edit after edit.
    for (const std::size_t width : {std::size_t{6}, std::size_t{1024}}) {
        CAPTURE(width);
        const engine::CheckResult checked = engine::check_buffer(lattice_deck(true, 1), "lattice.k");
        model::Model before = checked.model;
        preproc::Preview current = preproc::compute_preview(before, kept());
        std::mt19937 rng(width == 6 ? 61u : 62u);
        preproc::FollowOptions options;
        options.window_width = width;
        int followed = 0, chained = 0;
        for (int round = 0; round < 60; ++round) {
            CAPTURE(round);
            model::Model now = before;
            // Moves only (the windows are kept over moves): a random_edit of kind 0-4.
            do {
                now = before;
                random_edit(now, rng, 1);
            } while (now.particles.size() != before.particles.size());
            const preproc::Preview full = preproc::compute_preview(now, kept());
            const bool had_windows = current.parts[0].follow != nullptr;
            if (auto local = preproc::follow_particle_edit(current, before, now, options)) {
                ++followed;
                chained += had_windows;
                CHECK_MESSAGE(difference(*local, full).empty(), difference(*local, full));
                current = std::move(*local);  // moved, as the re-check keeps it: its windows stay usable
            } else {
                current = full;
            }
            before = std::move(now);
        }
        MESSAGE("width ", width, ": followed ", followed, " of 60, ", chained, " from kept windows");
        CHECK(followed >= 10);
        CHECK(chained >= 5);
    }
}

TEST_CASE("preview follow: a deliberately wrong update is caught, and the update refuses what it cannot follow") {
    const engine::CheckResult checked = engine::check_buffer(lattice_deck(true, 1), "lattice.k");
    const model::Model& before = checked.model;
    const preproc::Preview old = preproc::compute_preview(before, kept());
    model::Model now = before;
    now.nodes.x[100] += 0.3 * kSpacing;  // particle 100 (node 101) moves
    const preproc::Preview full = preproc::compute_preview(now, kept());
    auto right = preproc::follow_particle_edit(old, before, now);
    REQUIRE(right);
    CHECK(difference(*right, full).empty());
    preproc::FollowOptions wrong;
    wrong.forget_old_places = true;
    auto forgetful = preproc::follow_particle_edit(old, before, now, wrong);
    REQUIRE(forgetful);
    CHECK_FALSE(difference(*forgetful, full).empty());
    // Too many changed particles, a preview without counts, a particle whose node went: recomputed instead.
    model::Model shifted = before;
    for (double& x : shifted.nodes.x) x += 1e-4;
    CHECK_FALSE(preproc::follow_particle_edit(old, before, shifted));
    preproc::PreviewOptions no_counts = kept();
    no_counts.neighbour_counts = false;
    CHECK_FALSE(preproc::follow_particle_edit(preproc::compute_preview(before, no_counts), before, now));
    model::Model lost = before;
    lost.particles.node.set(5, 999999);
    CHECK_FALSE(preproc::follow_particle_edit(old, before, lost));
}

TEST_CASE("preview follow: the editor's re-check follows a coordinate edited inside *NODE") {
    engine::CheckOptions options;
    options.rules.keep_preview = true;
    const std::string text = lattice_deck(true, 1);
    const engine::CheckResult first = engine::check_buffer(text, "lattice.k", options);
    REQUIRE(first.preview);
    CHECK(first.preview->particles.neighbours.size() == 240);  // a kept preview keeps its counts
    model::Model moved = first.model;
    moved.nodes.y[17] -= 0.25 * kSpacing;
    REQUIRE(preproc::follow_particle_edit(*first.preview, first.model, moved));  // the edit can be followed
    const auto followed = engine::preview_after_edit(first, moved, false);
    REQUIRE(followed);
    CHECK(followed != first.preview);
    CHECK(difference(*followed, preproc::compute_preview(moved, kept())).empty());
    // Unchanged inputs: the same preview, not a copy.
    CHECK(engine::preview_after_edit(first, first.model, false) == first.preview);
    // Changed settings: the places' values kept, the rest computed again, equal to a full preview.
    SUBCASE("HMAX: the supports stand") {
        section_or_control(first, [](model::Model& m) { m.sections[0].hmax.value = 3.0; });
    }
    SUBCASE("SPHINI: a support moves, the counts are taken again") {
        section_or_control(first, [](model::Model& m) { m.sections[0].sphini.value = 0.016; });
    }
    SUBCASE("*CONTROL_SPH INI 2: h0 from the masses") {
        section_or_control(first, [](model::Model& m) {
            m.controls.sph.ini.value = model::IniMode::FromMass;
            m.sections[0].sphini.value = 0.0;
        });
    }
    SUBCASE("TSSFAC: the time steps only") {
        section_or_control(first, [](model::Model& m) { m.controls.tssfac.value = 0.5; });
    }
}
}  // namespace test_preview_follow_cpp
