// Whole-run reports: the machine-readable formats (JSON, SARIF) describe every deck of a run in
// one document, so they collect the decks' findings first and render once at the end.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "text/source_map.hpp"

namespace sphdeck::diag {

// The counts `sphdeck check` prints in its summary line.
struct RunSummary {
    std::size_t files = 0, keywords = 0, cards = 0, particles = 0;
    Counts counts;
    double seconds = 0;
    bool complete = true;  // false when a deck could not be read
};

class Report {
public:
    virtual ~Report() = default;
    // Adds one deck's findings; the spans point into `sources`, which need not outlive the call.
    virtual void add(const text::SourceMap& sources, const std::vector<Diagnostic>& diagnostics) = 0;
    // The whole document, ending in a newline.
    virtual std::string finish(const RunSummary& summary) const = 0;
};

// A file's path for tools that open it: relative to the working directory when the file lies
// below it, else absolute; '/' separators. In-memory decks keep their name.
std::string tool_path(const text::SourceFile& file);

}  // namespace sphdeck::diag
