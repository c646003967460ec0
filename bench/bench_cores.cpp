// What the machine itself gives on N threads, to read a program's parallel efficiency against:
// - compute: each thread runs the same fixed chain of floating-point work in registers (no memory), so
//   N threads ideally take the time of one. Below N x one thread: shared cores (SMT siblings sold
//   as cores), a lower clock with every core busy, or other tenants;
// - memory: a STREAM-like triad a = b + s c over arrays far larger than the caches, each thread on
//   its own slice (first touched by it), in GB/s: the bandwidth a pass over the particles meets.
//   bench_cores [threads...]   (default: 1 2 4 ... up to the cores)
// Each figure is the median of 5 repetitions.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <memory>
#include <vector>

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// About 0.25 s of dependent arithmetic on one core; the result is printed so nothing is optimised away.
double compute_seconds(int threads, double& sink) {
    constexpr long iterations = 5'000'000;
    double total = 0;
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel num_threads(threads) reduction(+ : total)
    {
        double a[8];
        for (int k = 0; k < 8; ++k) a[k] = 1.0 + 1e-3 * (omp_get_thread_num() + k);
        for (long i = 0; i < iterations; ++i)
            for (int k = 0; k < 8; ++k) a[k] = std::sqrt(a[k] * 1.0000001 + 1e-9);  // 8 independent chains
        for (int k = 0; k < 8; ++k) total += a[k];
    }
    sink += total;
    return seconds_since(t0);
}

double triad_gigabytes_per_second(int threads, std::size_t n, double* a, const double* b, const double* c) {
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + 1.5 * c[i];
    return 3.0 * sizeof(double) * static_cast<double>(n) / seconds_since(t0) / 1e9;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> counts;
    for (int k = 1; k < argc; ++k) counts.push_back(std::max(1, std::atoi(argv[k])));
    if (counts.empty())
        for (int t = 1; t <= omp_get_num_procs(); t *= 2) counts.push_back(t);
    constexpr std::size_t n = std::size_t{1} << 26;  // 512 MiB an array
    std::unique_ptr<double[]> a(new double[n]), b(new double[n]), c(new double[n]);
    double sink = 0;
    fmt::print("{} processors; compute: {} fixed chains per thread; triad over 3 x {} MiB\n", omp_get_num_procs(), 8,
               n * sizeof(double) >> 20);
    double one_compute = 0;
    for (int threads : counts) {
        // First touch by the threads that use the slices (the static schedule of the triad).
#pragma omp parallel for schedule(static) num_threads(threads)
        for (std::size_t i = 0; i < n; ++i) a[i] = 0, b[i] = 1, c[i] = 2;
        std::vector<double> compute, triad;
        for (int r = 0; r < 5; ++r) {
            compute.push_back(compute_seconds(threads, sink));
            triad.push_back(triad_gigabytes_per_second(threads, n, a.get(), b.get(), c.get()));
        }
        const double seconds = median(compute);
        if (threads == 1) one_compute = seconds;
        fmt::print("threads {:3}: compute {:.3f} s ({}), triad {:.1f} GB/s\n", threads, seconds,
                   one_compute > 0 ? fmt::format("{:.2f}x one thread's work rate, {:.0f}% of ideal",
                                                 threads * one_compute / seconds, 100 * one_compute / seconds)
                                   : std::string("no 1-thread figure"),
                   median(triad));
    }
    fmt::print("(checksum {:.3f})\n", sink + a[n / 2]);
    return 0;
}
