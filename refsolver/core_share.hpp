// Threads for a run that was not given a thread count (RunOptions::threads == 0), chosen from the
// cores other processes leave free, and chosen again while the run goes (issue 18, item 3).
// Why: every step has a dozen OpenMP regions with static schedules and libgomp spin-waits at their
// barriers, so with one of two cores taken by another process a 2-thread step waits at each barrier
// for the thread that shares its core, a scheduler time slice at a time: 9x slower than one thread
// alone (bench_refsolver, "loaded machine"). One thread on the free core loses nothing.
// How: over a window of steps, the busy time of the cores this process may run on (/proc/stat) minus
// this process's own CPU time (getrusage) is the load of the others; the free cores are the allowed
// cores (sched_getaffinity) minus that load. Neither read disturbs the run; off Linux, or when /proc
// is unreadable, the governor keeps the OpenMP default.
#pragma once

#include <chrono>
#include <vector>

namespace sphdeck::refsolver {

class CoreShare {
public:
    // `most`: the largest thread count to use (omp_get_max_threads, i.e. OMP_NUM_THREADS).
    explicit CoreShare(int most);
    // The thread count for the next steps: the one chosen at the last full window (a window is
    // `window_seconds` of wall time), capped by `most`, at least 1; 1 before the first window ends.
    int threads();
    // Free cores from a load of the others, for the tests: cores - others, rounded down after a
    // margin of a quarter core (a core half taken still stalls a static schedule).
    static int free_cores(int cores, double others, int most);

    static constexpr double window_seconds = 0.25;

private:
    struct Sample {
        std::chrono::steady_clock::time_point wall;
        double busy = 0;  // seconds the allowed cores were not idle, summed over them
        double own = 0;   // this process's CPU seconds
        bool valid = false;
    };
    Sample sample() const;
    int most_;
    int current_;
    std::vector<int> cpus_;  // the cores this process may run on
    Sample last_;
};

}  // namespace sphdeck::refsolver
