#include "diag/render_github.hpp"

#include <fmt/format.h>

#include "diag/render_text.hpp"
#include "diag/report.hpp"

namespace sphdeck::diag {
namespace {

const char* command(Severity s) {
    switch (s) {
        case Severity::Error: return "error";
        case Severity::Warning: return "warning";
        case Severity::Info: return "notice";
    }
    return "error";
}

std::string escaped(std::string_view text, bool property) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '%': out += "%25"; break;
            case '\r': out += "%0D"; break;
            case '\n': out += "%0A"; break;
            case ':': out += property ? "%3A" : ":"; break;
            case ',': out += property ? "%2C" : ","; break;
            default: out += c;
        }
    }
    return out;
}

}  // namespace

std::string github_escape_data(std::string_view text) { return escaped(text, false); }
std::string github_escape_property(std::string_view text) { return escaped(text, true); }

std::string render_github(const Diagnostic& d, const text::SourceMap& sources) {
    std::string properties;
    if (detail::has_location(d.span, sources)) {
        properties = fmt::format("file={},line={},col={},endColumn={},",
                                 github_escape_property(tool_path(sources.file(d.span.file))), d.span.line,
                                 d.span.column, std::max(d.span.end_column, d.span.column + 1));
    }
    properties += "title=" + github_escape_property(d.code);
    std::string message = d.message;
    for (const Note& note : d.notes) {
        message += "\nnote: ";
        if (detail::has_location(note.span, sources)) message += detail::location(note.span, sources) + ": ";
        message += note.message;
    }
    return fmt::format("::{} {}::{}\n", command(d.severity), properties, github_escape_data(message));
}

}  // namespace sphdeck::diag
