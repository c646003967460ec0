// A progress bar on stderr for long runs: drawn only when stderr is a terminal, only once the
// run has taken a moment (no flicker for quick ones), redrawn at most ten times a second, and
// erased when done so the output that follows starts on a clean line.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace sphdeck::cli {

class ProgressBar {
public:
    // `enabled` false: every call is a no-op. The default asks whether stderr is a terminal.
    explicit ProgressBar(std::string label, bool enabled = stderr_is_terminal());
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    // Reports progress (clamped to 0..1). Safe to call from several threads; calls that come
    // while another thread draws are dropped.
    void update(double fraction);
    // Erases the bar, if one was drawn. Called by the destructor too.
    void finish();

    bool enabled() const { return enabled_; }
    static bool stderr_is_terminal();

private:
    void draw(double fraction, double elapsed);

    std::string label_;
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
    std::mutex mutex_;
    double last_draw_ = -1.0;  // seconds since start
    bool drawn_ = false;
    std::atomic<bool> finished_{false};
};

}  // namespace sphdeck::cli
