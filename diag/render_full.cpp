// The full renderer: a rustc/clang-style code frame with carets under the span.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iterator>

#include <fmt/format.h>

#include "diag/render_text.hpp"

namespace sphdeck::diag {

namespace {

constexpr std::size_t max_cells = 200;     // excerpt columns shown, the trailing "..." aside
constexpr std::size_t left_context = 60;   // columns kept before the span when a line is windowed
constexpr std::size_t right_context = 40;  // columns wanted after the span start before windowing
constexpr std::size_t tab_stop = 8;
constexpr std::string_view ellipsis = "...";

// One source line as displayed, and where its carets go (in display columns from the start of text).
struct Excerpt {
    std::string text;
    std::size_t caret_start = 0;
    std::size_t caret_width = 0;  // 0: the span starts outside the window
    bool truncated = false;       // the line goes on past the window
};

// Length of the printable UTF-8 character at s[i], or 0 for an invalid sequence, a C1 control or a
// character that moves or breaks text (bidi controls, line and paragraph separators).
std::size_t utf8_length(std::string_view s, std::size_t i) {
    auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char lead = byte(i);
    std::size_t n = 0;
    char32_t cp = 0;
    if (lead >= 0xC2 && lead <= 0xDF)
        n = 2, cp = lead & 0x1F;
    else if (lead >= 0xE0 && lead <= 0xEF)
        n = 3, cp = lead & 0x0F;
    else if (lead >= 0xF0 && lead <= 0xF4)
        n = 4, cp = lead & 0x07;
    if (n == 0 || i + n > s.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (byte(i + k) & 0x3F);
    }
    static constexpr char32_t smallest[] = {0, 0, 0xA0, 0x800, 0x10000};  // overlong forms, C1 controls
    if (cp < smallest[n] || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF) return 0;
    if ((cp >= 0x2028 && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069)) return 0;
    return n;
}

// Displays line[from...] (positions past the end are blank room for carets) until max_cells columns.
Excerpt render_window(std::string_view line, std::size_t from, std::size_t b0, std::size_t b1) {
    Excerpt e;
    std::size_t cell = 0;
    if (from > 0) e.text = ellipsis, cell = ellipsis.size();
    const std::size_t end = std::max(line.size(), b1);
    std::size_t p = from;
    for (std::size_t bytes = 1; p < end; p += bytes) {
        const bool real = p < line.size();
        const auto b = real ? static_cast<unsigned char>(line[p]) : ' ';
        const std::size_t width = b == '\t' ? tab_stop - cell % tab_stop : 1;
        const std::size_t utf8 = b >= 0x80 ? utf8_length(line, p) : 0;
        bytes = std::max<std::size_t>(utf8, 1);
        if (cell + width > max_cells) break;
        if (!real) {
        } else if (b == '\t') {
            e.text.append(width, ' ');
        } else if (b < 0x20 || b == 0x7F || (b >= 0x80 && utf8 == 0)) {
            e.text += '?';
        } else {
            e.text += line.substr(p, bytes);
        }
        if (p < b1 && p + bytes > b0) {
            if (e.caret_width == 0) e.caret_start = cell;
            e.caret_width = cell + width - e.caret_start;
        }
        cell += width;
    }
    e.truncated = p < line.size();
    if (e.truncated) e.text += ellipsis;
    return e;
}

// The excerpt of a line for columns [column, end_column): whole when it fits, else windowed.
Excerpt make_excerpt(std::string_view line, const text::Span& span) {
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::size_t b0 = span.column > 0 ? span.column - 1 : 0;
    const std::size_t b1 = std::max<std::size_t>(span.end_column > 0 ? span.end_column - 1 : 0, b0 + 1);
    Excerpt whole = render_window(line, 0, b0, b1);
    if (whole.caret_width > 0 && (!whole.truncated || whole.caret_start + right_context <= max_cells)) return whole;
    std::size_t from = b0, budget = left_context - ellipsis.size();
    while (from > 0) {
        const std::size_t cost = from - 1 < line.size() && line[from - 1] == '\t' ? tab_stop : 1;
        if (cost > budget) break;
        budget -= cost, --from;
    }
    while (from < b0 && from < line.size() && (static_cast<unsigned char>(line[from]) & 0xC0) == 0x80) ++from;
    Excerpt e = render_window(line, from, b0, b1);
    if (e.caret_width == 0) e.caret_width = 1;  // unreachable: the window starts before the span
    return e;
}

std::string_view severity_style(Severity s) {
    switch (s) {
        case Severity::Error: return "1;31";
        case Severity::Warning: return "1;33";
        case Severity::Info: return "1;36";
    }
    return "1";
}

constexpr std::string_view gutter_style = "34";
constexpr std::string_view bold = "1";

// Builds one diagnostic's frame; `width` is that of the widest line number shown.
struct Frame {
    const text::SourceMap& sources;
    bool colour;
    std::size_t width;
    std::string out;

    std::string paint(std::string_view style, std::string_view text) const {
        return colour ? fmt::format("\x1b[{}m{}\x1b[0m", style, text) : std::string(text);
    }
    void gutter(std::string_view mark, std::string_view rest) {
        fmt::format_to(std::back_inserter(out), "{:{}} {}{}\n", "", width, paint(gutter_style, mark), rest);
    }
    void equals_note(std::string_view message) { gutter("=", fmt::format(" {}: {}", paint(bold, "note"), message)); }

    void excerpt(const text::Span& span, std::string_view caret_style) {
        const Excerpt e = make_excerpt(sources.line_text(span.file, span.line), span);
        fmt::format_to(std::back_inserter(out), "{:{}}{} {}\n", "", width, paint(gutter_style, "-->"),
                       detail::location(span, sources));
        gutter("|", "");
        const std::string number = paint(gutter_style, fmt::format("{:>{}} |", span.line, width));
        fmt::format_to(std::back_inserter(out), "{}{}{}\n", number, e.text.empty() ? "" : " ", e.text);
        gutter("|", fmt::format(" {:{}}{}", "", e.caret_start, paint(caret_style, std::string(e.caret_width, '^'))));
    }
    void include_chain(text::FileId id) {
        for (std::size_t level = 0; level < sources.size(); ++level) {
            const text::SourceFile& file = sources.file(id);
            if (file.parent >= sources.size()) break;  // also no_file
            equals_note(
                fmt::format("included from {}:{}", detail::file_name(sources.file(file.parent)), file.include_line));
            id = file.parent;
        }
    }
};

std::size_t gutter_width(const Diagnostic& d, const text::SourceMap& sources) {
    std::uint32_t widest = 0;
    if (detail::has_location(d.span, sources)) widest = d.span.line;
    for (const Note& note : d.notes)
        if (detail::has_location(note.span, sources)) widest = std::max(widest, note.span.line);
    return fmt::formatted_size("{}", widest);
}

}  // namespace

std::string render_full(const Diagnostic& d, const text::SourceMap& sources, const RenderOptions& options) {
    using detail::printable;
    Frame f{sources, options.colour, gutter_width(d, sources), {}};
    f.out += f.paint(severity_style(d.severity), to_string(d.severity));
    if (!d.code.empty()) f.out += f.paint(bold, fmt::format("[{}]", printable(d.code)));
    f.out += fmt::format(": {}\n", printable(d.message));
    if (detail::has_location(d.span, sources)) {
        f.excerpt(d.span, severity_style(d.severity));
        f.include_chain(d.span.file);
    }
    for (const Note& note : d.notes) {
        if (!detail::has_location(note.span, sources)) {
            f.equals_note(printable(note.message));
            continue;
        }
        f.out += fmt::format("{}: {}\n", f.paint(bold, "note"), printable(note.message));
        f.excerpt(note.span, gutter_style);
    }
    return std::move(f.out);
}

bool colour_wanted(int file_descriptor) {
    const char* no_color = std::getenv("NO_COLOR");
    if (no_color != nullptr && *no_color != '\0') return false;
    return isatty(file_descriptor) == 1;
}

}  // namespace sphdeck::diag
