// The concise renderer (file:line:col: severity: message [CODE]) and helpers shared with the full one.
#include <iterator>

#include <fmt/format.h>

#include "diag/render_text.hpp"

namespace sphdeck::diag {

namespace detail {

bool has_location(const text::Span& span, const text::SourceMap& sources) {
    return span.valid() && span.file < sources.size();
}

std::string file_name(const text::SourceFile& file) {
    return printable(file.display_name.empty() ? file.path : file.display_name);
}

std::string location(const text::Span& span, const text::SourceMap& sources) {
    return fmt::format("{}:{}:{}", file_name(sources.file(span.file)), span.line, span.column);
}

std::string printable(std::string_view text) {
    std::string out(text);
    for (char& c : out) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7F) c = '?';
    }
    return out;
}

}  // namespace detail

std::string render_concise(const Diagnostic& d, const text::SourceMap& sources) {
    using namespace detail;
    std::string out;
    auto sink = std::back_inserter(out);
    const std::string where = has_location(d.span, sources) ? location(d.span, sources) : "sphdeck";
    fmt::format_to(sink, "{}: {}: {}", where, to_string(d.severity), printable(d.message));
    if (!d.code.empty()) fmt::format_to(sink, " [{}]", printable(d.code));
    out += '\n';
    for (const Note& note : d.notes) {
        if (has_location(note.span, sources))
            fmt::format_to(sink, "{}: note: {}\n", location(note.span, sources), printable(note.message));
    }
    return out;
}

}  // namespace sphdeck::diag
