#include "diag/diagnostic.hpp"

#include <algorithm>
#include <tuple>

namespace sphdeck::diag {

std::string_view to_string(Severity s) {
    switch (s) {
        case Severity::Info: return "info";
        case Severity::Warning: return "warning";
        case Severity::Error: return "error";
    }
    return "error";
}

bool parse_severity(std::string_view word, Severity& out) {
    if (word == "info" || word == "note") {
        out = Severity::Info;
        return true;
    }
    if (word == "warning") {
        out = Severity::Warning;
        return true;
    }
    if (word == "error") {
        out = Severity::Error;
        return true;
    }
    return false;
}

Counts count(const std::vector<Diagnostic>& diagnostics) {
    Counts c;
    for (const auto& d : diagnostics) {
        switch (d.severity) {
            case Severity::Error: ++c.errors; break;
            case Severity::Warning: ++c.warnings; break;
            case Severity::Info: ++c.infos; break;
        }
    }
    return c;
}

void sort_by_location(std::vector<Diagnostic>& diagnostics) {
    std::stable_sort(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return std::tie(a.span.file, a.span.line, a.span.column, a.code) <
               std::tie(b.span.file, b.span.line, b.span.column, b.code);
    });
}

}  // namespace sphdeck::diag
