// Progress of a long run where no progress bar can be drawn (a CI log, nohup, a pipe): one line every
// few seconds on stderr with the step, the time reached, the time step, the particles and the time left.
#pragma once

#include <chrono>
#include <cstddef>

namespace sphdeck::cli {

class ProgressLog {
public:
    explicit ProgressLog(bool enabled, double every_seconds = 5.0);
    // Prints a line when `every_seconds` have passed since the last one (the first after that long too).
    void update(std::size_t step, double time, double end_time, double dt, std::size_t particles);

private:
    bool enabled_;
    double every_;
    std::chrono::steady_clock::time_point start_;
    double last_ = 0.0;  // seconds since start of the last line
};

}  // namespace sphdeck::cli
