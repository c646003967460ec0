// Preview benchmark: a 3D jittered lattice of 1,000,000 particles built in memory; the INI 0
// preview (grid, nearest neighbours, h0, neighbour counts) five times, each time and the median,
// and the peak RSS; then the INI 1 / INI 0 time ratio at 20,000 particles.
//   bench_preview [particles-per-side = 100]
// Goal (issue): INI 0 preview of 1e6 particles in at most 2 s on one core (median of 5).
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "preproc/preview.hpp"

using namespace sphdeck;

namespace {

// nx * ny * nz particles on a lattice of spacing dx, each moved by up to +-jitter * dx per axis.
model::Model lattice(int nx, int ny, int nz, double dx, double jitter) {
    model::Model m;
    m.controls.sph.idim = model::Dimension::ThreeD;
    model::Section s;
    s.id = "1", s.keyword = "*SECTION_SPH", s.sph = true;
    m.sections.push_back(s);
    model::Part p;
    p.id = "1", p.section = model::Id("1"), p.material = model::Id("1");
    m.parts.push_back(p);
    model::Material mat;
    mat.id = "1", mat.keyword = "*MAT_NULL", mat.density = 1000.0;
    m.materials.push_back(mat);
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-jitter * dx, jitter * dx);
    const std::size_t n = static_cast<std::size_t>(nx) * ny * nz;
    m.nodes.id.reserve(n), m.nodes.x.reserve(n), m.nodes.y.reserve(n), m.nodes.z.reserve(n);
    long long id = 1;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i, ++id) {
                m.nodes.id.push_back(id);
                m.nodes.x.push_back(i * dx + u(rng)), m.nodes.y.push_back(j * dx + u(rng)),
                    m.nodes.z.push_back(k * dx + u(rng));
                m.particles.node.push_back(id), m.particles.part.push_back(1);
                m.particles.mass.push_back(1000.0 * dx * dx * dx), m.particles.volume.push_back(0);
                m.particles.line.push_back(0);
            }
    return m;
}

double cpu_now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Wall-clock seconds of one preview; `cpu` gets the process CPU seconds (one thread: the time on
// one core, which a busy machine inflates less than the wall clock).
double seconds(const model::Model& m, model::IniMode mode, preproc::Preview* keep = nullptr, double* cpu = nullptr) {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_now();
    preproc::Preview p = preproc::compute_preview(m, {.ini = mode, .progress = {}});
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (cpu) *cpu = cpu_now() - c0;
    if (keep) *keep = std::move(p);
    return s;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

int main(int argc, char** argv) {
    const int side = argc > 1 ? std::atoi(argv[1]) : 100;
    const int runs = 5;
    const model::Model big = lattice(side, side, side, 0.002, 0.1);
    std::printf("INI 0 preview, 3D jittered lattice, %zu particles (jitter +-10%% of the spacing):\n",
                big.particles.size());
    std::vector<double> times, cpu_times;
    preproc::Preview p;
    for (int r = 0; r < runs; ++r) {
        double cpu = 0;
        times.push_back(seconds(big, model::IniMode::BucketSort, &p, &cpu));
        cpu_times.push_back(cpu);
        std::printf("  run %d: %.3f s (CPU %.3f s)\n", r + 1, times.back(), cpu);
    }
    const preproc::PartPreview& part = p.parts.at(0);
    std::printf("  median: %.3f s, CPU %.3f s (goal <= 2 s)\n", median(times), median(cpu_times));
    std::printf("  part 1: spacing %.4g, h0 %.4g, neighbours min/median/max %.0f/%.0f/%.0f\n", part.spacing, part.h0,
                part.neighbours.min, part.neighbours.median, part.neighbours.max);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("  peak RSS: %.1f MB\n", usage.ru_maxrss / 1024.0);

    const model::Model small = lattice(40, 25, 20, 0.002, 0.1);
    std::vector<double> t0, t1;
    for (int r = 0; r < runs; ++r) {
        t0.push_back(seconds(small, model::IniMode::BucketSort));
        t1.push_back(seconds(small, model::IniMode::Global));
    }
    std::printf("%zu particles: INI 0 %.4f s, INI 1 %.4f s (medians of %d): INI 1 / INI 0 = %.1f\n",
                small.particles.size(), median(t0), median(t1), runs, median(t1) / median(t0));
    return 0;
}
