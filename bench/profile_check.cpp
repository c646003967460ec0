// Where the time of `sphdeck check` goes, phase by phase, in one process (issue 30 item 1):
// reading, decoding into the model, the rules' id indexes, the geometry preview and its parts
// (grid binning, nearest neighbours, neighbour counts), then each rule family. Wall and CPU
// seconds per phase (threads: OMP_NUM_THREADS; the share is of the CPU seconds) and the peak RSS
// reached after it in the first run.
//   profile_check DECK [REPEATS = 3]     (prints the median of REPEATS for every phase)
// The preview's parts are timed again on their own, on the model's positions of the first part
// (exact for the benchmark deck: one part, particles in node order); their sum is not the preview.
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "grammar/line_chunks.hpp"
#include "grammar/read_deck.hpp"
#include "lint/rule_context.hpp"
#include "lint/rules.hpp"
#include "model/model_builder.hpp"
#include "preproc/nearest_neighbours.hpp"
#include "preproc/neighbour_grid.hpp"
#include "preproc/preview.hpp"

using namespace sphdeck;

namespace {

double peak_mb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;
}

double cpu_now() {  // process CPU seconds (every thread): on one thread, the time a busy machine inflates least
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Phase {
    std::vector<double> seconds, cpu;
    double peak = 0;
};

std::vector<std::string> order;
std::map<std::string, Phase> phases;

template <typename F>
auto timed(const std::string& name, F&& f) {
    if (!phases.count(name)) order.push_back(name);
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_now();
    auto finish = [&] {
        Phase& p = phases[name];
        p.cpu.push_back(cpu_now() - c0);
        p.seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        if (p.seconds.size() == 1) p.peak = peak_mb();  // the first run's: later ones start higher
    };
    if constexpr (std::is_void_v<decltype(f())>) {
        f();
        finish();
    } else {
        auto r = f();
        finish();
        return r;
    }
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// What the model's bulk columns and the deck's card lines hold (issue 40 item 2), once.
void print_holdings(const grammar::RawDeck& deck, const model::Model& m) {
    const model::Nodes& n = m.nodes;
    const model::Particles& p = m.particles;
    const double nodes = static_cast<double>(n.id.bytes() + (n.x.size() + n.y.size() + n.z.size()) * sizeof(double));
    const double particles = static_cast<double>(p.node.bytes() + p.part.bytes() + p.mass.size() * sizeof(double) +
                                                 p.volume.size() + p.line.runs() * 24);
    // Card lines stored one by one, and runs of regular ones (a bulk block's: grammar/card_lines.hpp).
    const double lines = static_cast<double>(deck.lines.stored_lines() * sizeof(grammar::CardLine) +
                                             deck.lines.runs() * sizeof(grammar::CardLinesBody::Run));
    const double count = static_cast<double>(std::max<std::size_t>(1, p.size()));
    std::printf(
        "model: nodes %.1f MB, particles %.1f MB: %.1f bytes a particle with its node; card lines %.1f MB "
        "(%.1f bytes a particle)\n",
        nodes / 1e6, particles / 1e6, (nodes + particles) / count, lines / 1e6, lines / count);
}

void one_check(const std::string& path) {
    timed("read line by line (as before issue 40)", [&] {
        grammar::set_line_chunk_bytes(grammar::read_line_by_line);
        const std::size_t lines = grammar::read_deck(path).lines.size();  // the deck goes at once
        grammar::set_line_chunk_bytes(0);
        return lines;
    });
    grammar::RawDeck deck = timed("read (lines, includes)", [&] { return grammar::read_deck(path); });
    std::vector<diag::Diagnostic> out = deck.diagnostics;
    model::Model m = timed("decode + model", [&] { return model::build_model(deck, out); });
    if (phases["decode + model"].seconds.size() == 1) print_holdings(deck, m);
    lint::RuleOptions options;
    lint::RuleContext c(m, deck, options, out);
    timed("geometry preview (all of it)", [&] { c.preview = lint::compute_rules_preview(m); });
    timed("rules: references REF", [&] { lint::check_references(c); });
    timed("rules: control SPH", [&] { lint::check_control_sph(c); });
    timed("rules: section SPH", [&] { lint::check_section_sph(c); });
    timed("rules: particles SPH110-112", [&] { lint::check_sph_particles(c); });
    timed("rules: materials", [&] { lint::check_sph_materials(c); });
    timed("rules: ISPH", [&] { lint::check_isph(c); });
    timed("rules: densities", [&] { lint::check_densities(c); });
    timed("rules: dimension", [&] { lint::check_sph_dimension(c); });
    timed("rules: preview rules (SPH090, 113-118)", [&] { lint::check_preview(c); });
    c.preview.reset();
    timed("rules: id indexes (node index, particle->node)", [&] { (void)c.particle_nodes(); });

    // The preview's parts on their own (the first part's positions, in node order).
    const std::span<const double> x = m.nodes.x, y = m.nodes.y, z = m.nodes.z;
    if (x.size() < 2) return;
    const double spacing = preproc::estimated_spacing(x, y, z);
    timed("  preview part: grid binning (cell = spacing)",
          [&] { return preproc::NeighbourGrid(x, y, z, spacing).size(); });
    timed("  preview part: nearest neighbours (grid included)",
          [&] { return preproc::nearest_neighbours_grid(x, y, z).distance.size(); });
    const std::vector<std::uint32_t> group(x.size(), 0);
    const double support[] = {2.4 * spacing}, tolerance[] = {1e-9 * spacing};
    timed("  preview part: neighbour counts (grid included)", [&] {
        return preproc::count_neighbours(x, y, z, preproc::GroupedRadii{group, support, tolerance}).count.size();
    });
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: profile_check DECK [REPEATS]\n");
        return 2;
    }
    const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
    for (int r = 0; r < repeats; ++r) one_check(argv[1]);
    double total = 0, total_cpu = 0;
    for (const std::string& name : order)
        if (name.rfind("  ", 0) != 0) total += median(phases[name].seconds), total_cpu += median(phases[name].cpu);
    std::printf("%-50s %9s %9s %7s %10s\n", "phase (median of runs)", "wall s", "cpu s", "share", "peak MB");
    for (const std::string& name : order) {
        const double s = median(phases[name].seconds), c = median(phases[name].cpu);
        std::printf("%-50s %9.4f %9.4f %6.1f%% %10.1f\n", name.c_str(), s, c,
                    name.rfind("  ", 0) == 0 ? 0.0 : 100 * c / total_cpu, phases[name].peak);
    }
    std::printf("%-50s %9.4f %9.4f\n", "sum of the phases above (parts excluded)", total, total_cpu);
    return 0;
}
