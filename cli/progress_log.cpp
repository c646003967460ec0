#include "cli/progress_log.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

namespace sphdeck::cli {

ProgressLog::ProgressLog(bool enabled, double every_seconds)
    : enabled_(enabled), every_(every_seconds), start_(std::chrono::steady_clock::now()) {}

void ProgressLog::update(std::size_t step, double time, double end_time, double dt, std::size_t particles) {
    if (!enabled_) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed - last_ < every_ || (last_ == 0.0 && elapsed < every_)) return;
    last_ = elapsed;
    const double fraction = end_time > 0 ? std::min(1.0, time / end_time) : 1.0;
    std::string left = "unknown";
    if (fraction > 0 && std::isfinite(fraction)) left = fmt::format("{:.0f} s", elapsed * (1.0 - fraction) / fraction);
    fmt::print(stderr, "run: step {}, t = {:.4g} of {:.4g} ({:.0f}%), dt = {:.3g}, {} particles, about {} left\n", step,
               time, end_time, 100.0 * fraction, dt, particles, left);
    std::fflush(stderr);
}

}  // namespace sphdeck::cli
