#include "edit/unified_diff.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "text/apply_edits.hpp"
#include "text/line_index.hpp"

namespace sphdeck::edit {
namespace {

constexpr std::uint32_t context_lines = 3;

// One old line and what it becomes (its line break kept; a replacement may add lines).
struct ChangedLine {
    std::uint32_t line = 0;
    std::string new_text;
};

std::vector<ChangedLine> changed_lines(std::string_view text, const text::LineIndex& lines,
                                       const text::PlacedEdits& placed) {
    std::vector<ChangedLine> changed;
    for (std::size_t i = 0; i < placed.edits.size();) {
        const std::uint32_t line = placed.edits[i].line;
        const std::size_t line_begin = lines.begin(line), line_end = lines.end(line);
        std::string new_text;
        std::size_t copied_to = line_begin;
        for (; i < placed.edits.size() && placed.edits[i].line == line; ++i) {
            new_text.append(text.substr(copied_to, placed.edits[i].begin - copied_to));
            new_text.append(*placed.edits[i].replacement);
            copied_to = placed.edits[i].end;
        }
        new_text.append(text.substr(copied_to, line_end - copied_to));
        if (new_text != text.substr(line_begin, line_end - line_begin)) changed.push_back({line, std::move(new_text)});
    }
    return changed;
}

// Appends `body` as diff lines with `prefix`, saying so when the file's last line has no line break.
void append_lines(std::string& out, char prefix, std::string_view body) {
    while (!body.empty()) {
        const auto newline = body.find('\n');
        const auto line = body.substr(0, newline == std::string_view::npos ? body.size() : newline + 1);
        out += prefix;
        out.append(line);
        if (line.back() != '\n') out += "\n\\ No newline at end of file\n";
        body.remove_prefix(line.size());
    }
}

std::uint32_t count_lines(std::string_view body) {
    return static_cast<std::uint32_t>(std::count(body.begin(), body.end(), '\n') +
                                      (!body.empty() && body.back() != '\n' ? 1 : 0));
}

std::string hunk_header(std::uint32_t old_start, std::uint32_t old_count, std::uint32_t new_start,
                        std::uint32_t new_count) {
    // As diff -u: a range of one line is written without its count, an empty range starts one line earlier.
    const auto range = [](std::uint32_t start, std::uint32_t count) {
        if (count == 1) return fmt::format("{}", start);
        return fmt::format("{},{}", count == 0 ? start - 1 : start, count);
    };
    return fmt::format("@@ -{} +{} @@\n", range(old_start, old_count), range(new_start, new_count));
}

// One change as diff prints it: old lines [first, end) removed (none when first == end: an insertion
// before line `first`) and `added` put in their place.
struct Change {
    std::uint32_t first = 0, end = 0;
    std::string_view added;
};

// A changed line as the smallest change diff would find: when the old line survives whole among its new
// lines (a line inserted above or below it), the new lines around it are insertions and the line stays.
void append_changes(std::vector<Change>& changes, std::uint32_t line, std::string_view old_text,
                    std::string_view new_text) {
    for (std::size_t at = 0; at < new_text.size();) {
        const auto newline = new_text.find('\n', at);
        const std::size_t next = newline == std::string_view::npos ? new_text.size() : newline + 1;
        if (new_text.substr(at, next - at) == old_text) {
            if (at > 0) changes.push_back({line, line, new_text.substr(0, at)});
            if (next < new_text.size()) changes.push_back({line + 1, line + 1, new_text.substr(next)});
            return;
        }
        at = next;
    }
    changes.push_back({line, line + 1, new_text});
}

}  // namespace

std::string unified_diff(std::string_view path, std::string_view text, const std::vector<diag::TextEdit>& edits) {
    const text::LineIndex lines(text);
    const auto changed = changed_lines(text, lines, text::place_edits(text, edits));
    if (changed.empty()) return {};
    const auto old_line = [&](std::uint32_t line) {
        return text.substr(lines.begin(line), lines.end(line) - lines.begin(line));
    };
    std::vector<Change> changes;
    for (const auto& line : changed) append_changes(changes, line.line, old_line(line.line), line.new_text);
    // The last line of the index is an empty remainder when the text ends with a line break.
    const std::uint32_t last_line = lines.count() - (lines.begin(lines.count()) == text.size() ? 1 : 0);
    // An absolute path without its leading '/', as git writes one: "a/tmp/deck.k", not "a//tmp/deck.k".
    const std::string_view shown = !path.empty() && path.front() == '/' ? path.substr(1) : path;
    std::string out = fmt::format("--- a/{}\n+++ b/{}\n", shown, shown);
    std::int64_t line_delta = 0;  // lines added so far less lines removed
    for (std::size_t first = 0; first < changes.size();) {
        std::size_t last = first;  // changes with at most twice the context between them share a hunk
        while (last + 1 < changes.size() && changes[last + 1].first <= changes[last].end + 2 * context_lines) ++last;
        const std::uint32_t from = changes[first].first > context_lines ? changes[first].first - context_lines : 1;
        const std::uint32_t to = std::min(changes[last].end - 1 + context_lines, last_line);  // last old line shown
        std::string body;
        std::uint32_t old_count = 0, new_count = 0;
        std::uint32_t line = from;
        const auto context_until = [&](std::uint32_t stop) {
            for (; line < stop && line <= to; ++line, ++old_count, ++new_count) append_lines(body, ' ', old_line(line));
        };
        for (std::size_t c = first; c <= last;) {
            // Changes that touch (one's old lines end where the next's begin) print as diff prints one
            // change: every removed line, then every added one.
            std::size_t run_end = c + 1;
            while (run_end <= last && changes[run_end].first == changes[run_end - 1].end) ++run_end;
            context_until(changes[c].first);
            for (; line < changes[run_end - 1].end; ++line, ++old_count) append_lines(body, '-', old_line(line));
            for (; c < run_end; ++c) {
                append_lines(body, '+', changes[c].added);
                new_count += count_lines(changes[c].added);
            }
        }
        context_until(to + 1);
        // diff -u starts an empty side's range one line before the hunk's first line
        const std::uint32_t new_from = static_cast<std::uint32_t>(from + line_delta);
        out += hunk_header(from, old_count, new_from, new_count);
        out += body;
        line_delta += static_cast<std::int64_t>(new_count) - old_count;
        first = last + 1;
    }
    return out;
}

}  // namespace sphdeck::edit
