// measure_command: run a command several times and report wall time, CPU time and peak memory.
//
//   measure_command RUNS -- CMD [ARGS...]
//
// Each run forks and execs CMD (PATH is searched) with stdout and stderr sent to /dev/null, waits with
// wait4() and prints one line per run: wall seconds, user and system CPU seconds, peak resident set
// size (ru_maxrss, in MB of 2^20 bytes) and how the run ended. The last two lines give the medians in a
// form scripts can parse:
//
//   median_user_seconds=0.340000 median_system_seconds=0.024000
//   median_seconds=0.412345 median_peak_rss_mb=153.2
//
// The CPU split is there because on a virtual machine the system time (the kernel zeroing the pages a
// process touches first) can move by a factor of ten between runs while the user time holds
// (bench/README.md, stop 67).
//
// Exit codes 0 and 1 count as success (`sphdeck check` exits 1 when it finds errors in the deck).
// A run that exits with 2 or more, or is killed by a signal, is a failure: it is reported, the
// remaining runs still happen, and measure_command exits 1. Usage errors exit 2.
//
// Linux note: ru_maxrss of a child that called exec includes the RSS it inherited from this process
// through fork (the kernel keeps the larger of the old and new peak), i.e. a few MB at most.
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <vector>

namespace {

struct Run {
    double seconds = 0;
    double user_seconds = 0, system_seconds = 0;
    double peak_rss_mb = 0;
    int status = 0;  // raw wait status
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Returns false if the process could not be started or waited for.
bool run_once(char** argv, Run& run) {
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) {
        std::fprintf(stderr, "measure_command: fork failed: %s\n", std::strerror(errno));
        return false;
    }
    if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        if (null >= 0) {
            dup2(null, STDOUT_FILENO);
            dup2(null, STDERR_FILENO);
            if (null > STDERR_FILENO) close(null);
        }
        execvp(argv[0], argv);
        // stderr is /dev/null now: report through the exit code, as shells do.
        _exit(errno == ENOENT ? 127 : 126);
    }
    int status = 0;
    rusage usage{};
    pid_t got;
    do {
        got = wait4(pid, &status, 0, &usage);
    } while (got < 0 && errno == EINTR);
    const auto stop = std::chrono::steady_clock::now();
    if (got < 0) {
        std::fprintf(stderr, "measure_command: wait4 failed: %s\n", std::strerror(errno));
        return false;
    }
    run.seconds = std::chrono::duration<double>(stop - start).count();
    const auto of = [](const timeval& t) {
        return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
    };
    run.user_seconds = of(usage.ru_utime), run.system_seconds = of(usage.ru_stime);
    run.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
    run.status = status;
    return true;
}

// Describes how the run ended; returns true for success (exit 0 or 1).
bool describe(int status, char* text, std::size_t size) {
    if (WIFEXITED(status)) {
        const int code = WEXITSTATUS(status);
        if (code <= 1) {
            std::snprintf(text, size, "exit %d", code);
            return true;
        }
        const char* hint = code == 127 ? " (command not found?)" : code == 126 ? " (cannot execute?)" : "";
        std::snprintf(text, size, "exit %d FAILED%s", code, hint);
        return false;
    }
    if (WIFSIGNALED(status)) {
        const int sig = WTERMSIG(status);
        std::snprintf(text, size, "killed by signal %d (%s) FAILED", sig, strsignal(sig));
        return false;
    }
    std::snprintf(text, size, "unknown wait status %d FAILED", status);
    return false;
}

int usage(const char* self) {
    std::fprintf(stderr, "usage: %s RUNS -- CMD [ARGS...]\n", self);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4 || std::string_view(argv[2]) != "--") return usage(argv[0]);
    int runs = 0;
    const std::string_view arg = argv[1];
    auto [end, ec] = std::from_chars(arg.data(), arg.data() + arg.size(), runs);
    if (ec != std::errc() || end != arg.data() + arg.size() || runs < 1) {
        std::fprintf(stderr, "measure_command: RUNS must be a positive integer, got '%s'\n", argv[1]);
        return 2;
    }
    char** command = argv + 3;

    std::vector<double> seconds, user, system, rss;
    int failures = 0;
    for (int i = 1; i <= runs; ++i) {
        Run run;
        if (!run_once(command, run)) return 1;
        char how[128];
        if (!describe(run.status, how, sizeof how)) ++failures;
        std::printf("run %d/%d: %.6f s (user %.3f s, system %.3f s), peak RSS %.1f MB, %s\n", i, runs, run.seconds,
                    run.user_seconds, run.system_seconds, run.peak_rss_mb, how);
        std::fflush(stdout);
        seconds.push_back(run.seconds);
        user.push_back(run.user_seconds), system.push_back(run.system_seconds);
        rss.push_back(run.peak_rss_mb);
    }
    std::printf("median_user_seconds=%.6f median_system_seconds=%.6f\n", median(user), median(system));
    std::printf("median_seconds=%.6f median_peak_rss_mb=%.1f\n", median(seconds), median(rss));
    if (failures > 0) {
        std::fprintf(stderr, "measure_command: %d of %d runs of '%s' failed\n", failures, runs, command[0]);
        return 1;
    }
    return 0;
}
