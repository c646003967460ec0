#include "cli/progress_bar.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <fmt/format.h>
#include <unistd.h>

namespace sphdeck::cli {
namespace {
constexpr double show_after = 0.5;    // seconds before the first drawing
constexpr double redraw_every = 0.1;  // seconds between drawings
constexpr int bar_width = 30;
}  // namespace

bool ProgressBar::stderr_is_terminal() {
    const char* term = std::getenv("TERM");
    return isatty(STDERR_FILENO) == 1 && !(term && std::string_view(term) == "dumb");
}

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled), start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(double fraction) {
    if (!enabled_ || finished_.load(std::memory_order_relaxed)) return;
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed < show_after || elapsed - last_draw_ < redraw_every) return;
    last_draw_ = elapsed;
    draw(fraction >= 0.0 ? std::min(fraction, 1.0) : 0.0, elapsed);  // NaN (0/0) draws as 0: clamp keeps NaN
}

void ProgressBar::draw(double fraction, double elapsed) {
    const int filled = static_cast<int>(fraction * bar_width);
    std::string eta;
    if (fraction > 0.02 && fraction < 1.0) eta = fmt::format("  ~{:.0f} s left", elapsed * (1.0 - fraction) / fraction);
    fmt::print(stderr, "\r{} [{}{}] {:3.0f}%{}\x1b[K", label_, std::string(static_cast<std::size_t>(filled), '#'),
               std::string(static_cast<std::size_t>(bar_width - filled), '.'), fraction * 100.0, eta);
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressBar::finish() {
    if (!enabled_ || finished_.exchange(true)) return;
    std::lock_guard lock(mutex_);
    if (drawn_) {
        fmt::print(stderr, "\r\x1b[K");
        std::fflush(stderr);
    }
}

}  // namespace sphdeck::cli
