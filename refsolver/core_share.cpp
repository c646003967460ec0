#include "refsolver/core_share.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#if defined(__linux__)
#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace sphdeck::refsolver {

int CoreShare::free_cores(int cores, double others, int most) {
    const double free = static_cast<double>(cores) - std::max(0.0, others);
    const int n = static_cast<int>(std::floor(free + 0.25));
    return std::clamp(n, 1, std::max(1, most));
}

// The first window runs on one thread: a 2-thread window on a loaded machine costs up to 9x, one
// thread on an idle one 2x.
CoreShare::CoreShare(int most) : most_(std::max(1, most)), current_(1) {
#if defined(__linux__)
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0)
        for (int c = 0; c < CPU_SETSIZE; ++c)
            if (CPU_ISSET(c, &set)) cpus_.push_back(c);
    last_ = sample();
#endif
}

CoreShare::Sample CoreShare::sample() const {
    Sample s;
    s.wall = std::chrono::steady_clock::now();
#if defined(__linux__)
    if (cpus_.empty()) return s;
    std::ifstream f("/proc/stat");
    const double tick = static_cast<double>(sysconf(_SC_CLK_TCK));
    if (!f || !(tick > 0)) return s;
    std::string line;
    std::size_t found = 0;
    while (std::getline(f, line)) {
        // "cpuN user nice system idle iowait irq softirq steal ...": busy = all but idle and iowait.
        if (line.size() < 4 || line.compare(0, 3, "cpu") != 0 || !std::isdigit(static_cast<unsigned char>(line[3])))
            continue;
        std::istringstream in(line.substr(3));
        int cpu = -1;
        in >> cpu;
        if (!std::binary_search(cpus_.begin(), cpus_.end(), cpu)) continue;
        double v[8] = {};
        for (double& x : v) in >> x;
        s.busy += (v[0] + v[1] + v[2] + v[5] + v[6] + v[7]) / tick;
        ++found;
    }
    rusage u{};
    if (found == 0 || getrusage(RUSAGE_SELF, &u) != 0) return s;
    s.own = double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
    s.valid = true;
#endif
    return s;
}

int CoreShare::threads() {
    if (most_ == 1 || cpus_.empty()) return current_;
    const auto now = std::chrono::steady_clock::now();
    const double wall = std::chrono::duration<double>(now - last_.wall).count();
    if (wall < window_seconds) return current_;
    const Sample s = sample();
    if (s.valid && last_.valid) {
        // Others' load in cores; the kernel's ticks lag the rusage clock by up to a tick a core.
        const double others = ((s.busy - last_.busy) - (s.own - last_.own)) / wall;
        const int cores = std::min(static_cast<int>(cpus_.size()), most_);
        current_ = free_cores(static_cast<int>(cpus_.size()), others, cores);
    }
    last_ = s;
    return current_;
}

}  // namespace sphdeck::refsolver
