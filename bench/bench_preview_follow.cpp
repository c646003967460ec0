// bench_preview_follow: the geometry preview of the editor's re-check after an edit (issue 45 item 3),
// on the 1M-particle deck of gen_big_deck, medians of several runs:
//   node     a coordinate mid *NODE edited (the edit of bench_incremental's bulk figure): the kept
//            preview followed locally (preproc/preview_follow.hpp) against a whole new preview
//   hmax     *SECTION_SPH HMAX edited: the places' values kept, nothing recounted
//   cslh     *SECTION_SPH CSLH edited: the supports move, the counts are taken again
//   tssfac   *CONTROL_TIMESTEP TSSFAC edited: the time steps only
// Each followed or recomputed preview is compared with a whole new one (the bench fails otherwise).
//
//   bench_preview_follow BIG_DECK [RUNS]     (RUNS defaults to 5; deck: gen_big_deck, bench/out/big.k)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "engine/preview_after_edit.hpp"
#include "lint/rules.hpp"

using namespace sphdeck;

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

bool same_values(const preproc::Preview& a, const preproc::Preview& b) {
    if (a.parts.size() != b.parts.size() || a.coincident != b.coincident) return false;
    for (std::size_t q = 0; q < a.parts.size(); ++q) {
        const auto &p = a.parts[q], &r = b.parts[q];
        if (p.h0 != r.h0 || p.spacing != r.spacing || p.nn_distance.max != r.nn_distance.max ||
            p.neighbours.median != r.neighbours.median || p.neighbours.min != r.neighbours.min ||
            p.neighbours.max != r.neighbours.max || p.dt_estimate != r.dt_estimate || p.particles != r.particles)
            return false;
    }
    return a.particles.nn_distance == b.particles.nn_distance && a.particles.neighbours == b.particles.neighbours;
}

// Times the re-check's preview after `edit` (applied to a copy of the model, alternating two forms
// so that every run is a change) against a whole new preview.
void figure(const char* name, const engine::CheckResult& first, int runs,
            const std::function<void(model::Model&, int)>& edit) {
    std::vector<double> followed, full;
    engine::CheckResult previous;
    previous.model = first.model;
    previous.preview = first.preview;
    for (int run = 0; run < runs; ++run) {
        model::Model now = previous.model;
        edit(now, run);
        auto start = Clock::now();
        auto after = engine::preview_after_edit(previous, now, false);
        followed.push_back(ms_since(start));
        start = Clock::now();
        auto whole = lint::compute_rules_preview(now, false, true);
        full.push_back(ms_since(start));
        if (!after || !whole || !same_values(*after, *whole)) {
            std::fprintf(stderr, "bench_preview_follow: %s: the preview differs from a whole new one\n", name);
            std::exit(1);
        }
        previous.model = std::move(now);
        previous.preview = after;
    }
    std::printf("  %-46s %9.1f ms  (whole preview %9.1f ms)\n", name, median(followed), median(full));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_preview_follow BIG_DECK [RUNS]\n");
        return 2;
    }
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
    try {
        engine::CheckOptions options;
        options.rules.keep_preview = true;
        const auto start = Clock::now();
        const engine::CheckResult first = engine::check_file(argv[1], options);
        std::printf("deck %s: %zu particles, checked in %.0f ms\n", argv[1], first.model.particles.size(),
                    ms_since(start));
        if (!first.preview || first.model.sections.empty()) {
            std::fprintf(stderr, "bench_preview_follow: no preview (no particles?)\n");
            return 1;
        }
        // The node in the middle of *NODE, as bench_incremental edits it.
        const std::size_t mid = first.model.nodes.x.size() / 2;
        figure("*NODE x edited (followed)", first, runs,
               [mid](model::Model& m, int run) { m.nodes.x[mid] = run % 2 ? -1.0e-3 : 1.0e-3; });
        figure("*SECTION_SPH HMAX edited (counts kept)", first, runs,
               [](model::Model& m, int run) { m.sections[0].hmax.value = run % 2 ? 2.0 : 2.5; });
        figure("*SECTION_SPH CSLH edited (counts again)", first, runs,
               [](model::Model& m, int run) { m.sections[0].cslh.value = run % 2 ? 1.2 : 1.3; });
        figure("*CONTROL_TIMESTEP TSSFAC edited", first, runs,
               [](model::Model& m, int run) { m.controls.tssfac.value = run % 2 ? 0.9 : 0.8; });
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_preview_follow: %s\n", e.what());
        return 1;
    }
    return 0;
}
