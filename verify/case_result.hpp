// What a verification case reports (verification.md §9): one row per gated quantity (value, reference,
// error, tolerance, PASS/FAIL), the runs behind it (§9.4: resolution, steps, wall time), a figure and
// notes for the Markdown summary.
#pragma once

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sphdeck::verify {

struct Check {
    enum class Bound { AtMost, AtLeast };  // pass when error <= tolerance, or error >= tolerance

    std::string quantity;             // "L1(rho) relative, 400 particles"
    double value = NAN;               // what the run gave
    std::optional<double> reference;  // the exact or experimental value; none when the value is itself an error
    double error = NAN;               // what is compared with the tolerance
    double tolerance = NAN;
    Bound bound = Bound::AtMost;
    // false: a reference row, reported with its error but not part of the verdict (the dam break's
    // experiments, whose lead comes from the gate's opening that no deck keyword models).
    bool gated = true;

    bool passed() const {
        if (!std::isfinite(error)) return false;  // a blown-up or undetected result never passes
        return bound == Bound::AtMost ? error <= tolerance : error >= tolerance;
    }
};

// One solver run of one deck (§9.4: what to record with each result).
struct RunRecord {
    std::string deck;  // file name within the deck folder
    std::size_t particles = 0;
    std::size_t steps = 0;
    double end_time = 0;  // simulated time reached
    double wall_seconds = 0;
    int threads = 0;
};

struct CaseResult {
    std::string name;   // "sod", "hydrostatic", "dambreak"
    std::string title;  // one line
    std::vector<RunRecord> runs;
    std::vector<Check> checks;
    std::vector<std::string> method;  // how the figures were obtained (Markdown bullet points)
    std::string svg;                  // the figure: solution against reference
    std::string details;              // Markdown after the method (radioss-waves: its per-cycle table), may be empty
    std::string failure;              // non-empty when the case could not run (unreadable deck, refused)

    bool ran() const { return failure.empty(); }
    // Every gated row passes (and there is one).
    bool passed() const {
        if (!ran()) return false;
        bool any_gated = false;
        for (const Check& c : checks) {
            if (!c.gated) continue;
            any_gated = true;
            if (!c.passed()) return false;
        }
        return any_gated;
    }
};

struct CaseOptions {
    std::filesystem::path decks;                     // the folder with the verification decks
    bool quick = false;                              // the coarse and short variants (`make test`)
    int threads = 0;                                 // OpenMP threads, 0: the default
    std::function<void(std::string_view)> progress;  // a line of progress ("running sod_2d_400.k"), may be empty
};

}  // namespace sphdeck::verify
