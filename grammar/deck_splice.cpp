#include "grammar/deck_splice.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string_view>

#include "grammar/dyna/reader.hpp"
#include "grammar/earlier_text.hpp"
#include "grammar/read_deck.hpp"
#include "text/text_file.hpp"

namespace sphdeck::grammar {
namespace {

constexpr std::size_t compare_step = 4096;  // memcmp in steps, then byte by byte in the step that differs

std::size_t common_prefix(std::string_view a, std::string_view b) {
    const std::size_t n = std::min(a.size(), b.size());
    std::size_t at = 0;
    while (at + compare_step <= n && std::memcmp(a.data() + at, b.data() + at, compare_step) == 0) at += compare_step;
    while (at < n && a[at] == b[at]) ++at;
    return at;
}

// The common suffix, leaving the first `kept` bytes of both alone (the common prefix).
std::size_t common_suffix(std::string_view a, std::string_view b, std::size_t kept) {
    const std::size_t n = std::min(a.size(), b.size()) - kept;
    std::size_t at = 0;
    while (at + compare_step <= n && std::memcmp(a.data() + a.size() - at - compare_step,
                                                 b.data() + b.size() - at - compare_step, compare_step) == 0)
        at += compare_step;
    while (at < n && a[a.size() - 1 - at] == b[b.size() - 1 - at]) ++at;
    return at;
}

std::size_t count_newlines(std::string_view s) {
    std::size_t n = 0;
    for (const char *p = s.data(), *end = s.data() + s.size();
         (p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)))); ++p)
        ++n;
    return n;
}

// Physical lines of bytes [begin, end) of `text`, whole lines (a last line without '\n' counts).
std::uint32_t lines_in(std::string_view text, std::size_t begin, std::size_t end) {
    const std::size_t n = count_newlines(text.substr(begin, end - begin));
    const bool open_last = end == text.size() && end > begin && text[end - 1] != '\n';
    return static_cast<std::uint32_t>(n + (open_last ? 1 : 0));
}

// Keywords whose lines the reader acts on (includes, parameters, the *KEYWORD line's memory, comment
// text) or after which it reads nothing.
bool reader_acts_on(const std::string& keyword) {
    for (const char* special : {"*INCLUDE", "*PARAMETER", "*KEYWORD", "*COMMENT", "*RVE", "*END"})
        if (keyword.rfind(special, 0) == 0) return true;
    return keyword == "*";
}

void shift_span(text::Span& span, FileId file, std::uint32_t from_line, std::int64_t delta) {
    if (span.file == file && span.line >= from_line) span.line = static_cast<std::uint32_t>(span.line + delta);
}

bool touches(const text::Span& span, FileId file, std::uint32_t first, std::uint32_t end) {
    return span.file == file && span.line >= first && span.line < end;
}
}  // namespace

std::optional<SplicedDeck> splice_edit(const RawDeck& previous, SourceText text, const TextRevision* revision) {
    constexpr FileId file = 0;
    if (previous.sources.size() != 1 || previous.blocks.empty() || previous.lines.empty() ||
        !previous.parameters.definitions().empty() || format_of(previous) != DeckFormat::LsDyna)
        return std::nullopt;
    const SourceFile& old_file = previous.sources.file(file);
    const std::string_view before = old_file.text.view(), now = text.view();
    if (now.size() > std::numeric_limits<std::uint32_t>::max() ||
        detect_format(now, old_file.path) != DeckFormat::LsDyna || text::binary_or_empty(now.substr(0, 64 * 1024)))
        return std::nullopt;
    // Encrypted content: the reader's state there is its own.
    for (const diag::Diagnostic& d : previous.diagnostics)
        if (d.code == "DK022") return std::nullopt;

    // The changed bytes, widened to whole lines: [begin, old_end) of `before` is [begin, new_end) of `now`.
    // The editor may have patched the buffer `previous` read in place (`before` views the patched bytes
    // then): the bytes outside the change are read from `now`, which holds them too, and the replaced
    // ones from what it kept aside (grammar/earlier_text.hpp).
    const bool told = revision && revision->previous_data == before.data() && revision->previous_size == before.size();
    const bool patched = told && revision->replaced;
    if (patched ? before.data() != now.data() || !EarlierText::consistent(now, *revision)
                : before.data() == now.data() && (told || before.size() != now.size()))
        return std::nullopt;  // patched without being told how
    std::size_t prefix = 0, suffix = 0;
    if (told) {
        // Known from the editor's changes: at least these bytes are the same (fewer only widen the edit).
        const std::size_t shorter = std::min(before.size(), now.size());
        prefix = std::min(revision->same_prefix, shorter);
        suffix = std::min(revision->same_suffix, shorter - prefix);
    } else {
        prefix = common_prefix(before, now);
        suffix = common_suffix(before, now, prefix);
    }
    const std::size_t shift = now.size() - before.size();  // of the bytes after the edit (modulo 2^64)
    std::size_t begin = prefix;
    while (begin > 0 && now[begin - 1] != '\n') --begin;
    std::size_t old_end = now.find('\n', now.size() - suffix);
    old_end = old_end == std::string_view::npos ? before.size() : old_end + 1 - shift;
    const std::size_t new_end = old_end + shift;
    // The old bytes of the edit's lines, and the count of '\n' in the old text's bytes [begin, to).
    const std::string replaced =
        patched ? EarlierText(now, *revision).copy(begin, old_end) : std::string(before.substr(begin, old_end - begin));
    const auto old_newlines = [&](std::size_t to) {
        if (to <= old_end) return count_newlines(std::string_view(replaced).substr(0, to - begin));
        return count_newlines(replaced) + count_newlines(now.substr(old_end + shift, to - old_end));
    };

    // The card lines the edit replaced, and the physical line `begin` starts.
    const auto by_offset = [](const CardLine& l, std::size_t offset) { return l.offset < offset; };
    const auto first = std::lower_bound(previous.lines.begin(), previous.lines.end(), begin, by_offset);
    const auto last = std::lower_bound(first, previous.lines.end(), old_end, by_offset);
    std::uint32_t first_line = 0;  // the physical line at `begin`
    if (first != previous.lines.end())
        first_line = first->line - static_cast<std::uint32_t>(old_newlines(first->offset));
    else  // the lines before `begin` are the same in both texts
        first_line =
            (first - 1)->line +
            static_cast<std::uint32_t>(count_newlines(now.substr((first - 1)->offset, begin - (first - 1)->offset)));
    const bool open_last = old_end == before.size() && !replaced.empty() && replaced.back() != '\n';
    const auto old_lines = static_cast<std::uint32_t>(count_newlines(replaced) + (open_last ? 1 : 0));
    const std::uint32_t new_lines = lines_in(now, begin, new_end);
    const std::uint32_t after = first_line + old_lines;  // the first physical line past the edit (old numbering)

    // The block the edit falls in: no keyword line among the replaced lines, and one the reader does not act on.
    const auto host_end = std::upper_bound(previous.blocks.begin(), previous.blocks.end(), first_line,
                                           [](std::uint32_t line, const Block& b) { return line < b.span.line; });
    if (host_end == previous.blocks.begin()) return std::nullopt;  // before the first keyword: stray lines
    if (host_end != previous.blocks.end() && host_end->span.line < after) return std::nullopt;
    const Block& host = *(host_end - 1);
    if (host.span.line >= first_line) return std::nullopt;  // the edit starts on its keyword line
    const auto host_index = static_cast<std::size_t>(host_end - previous.blocks.begin()) - 1;
    const auto first_index = static_cast<std::uint32_t>(first - previous.lines.begin());
    const auto last_index = static_cast<std::uint32_t>(last - previous.lines.begin());
    if (reader_acts_on(host.keyword) || first_index < host.first_line || last_index > host.first_line + host.line_count)
        return std::nullopt;
    for (const diag::Diagnostic& d : previous.diagnostics)
        if (touches(d.span, file, first_line, after)) return std::nullopt;

    // The new lines read on their own under a keyword the reader does not act on: one block, no finding.
    std::string piece = "*SPLICED\n";
    const std::size_t lead = piece.size();
    piece.append(now.substr(begin, new_end - begin));
    const RawDeck read = dyna::read_buffer(std::move(piece), old_file.display_name);
    if (read.blocks.size() != 1 || !read.diagnostics.empty() || read.stats.lines != 1 + new_lines) return std::nullopt;

    SplicedDeck out;
    out.changed = {file,
                   begin,
                   old_end,
                   new_end,
                   first_index,
                   last_index,
                   static_cast<std::uint32_t>(first_index + read.lines.size()),
                   first_line,
                   after,
                   first_line + new_lines,
                   host_index,
                   std::move(replaced)};
    RawDeck& deck = out.deck;
    SourceFile source;
    source.path = old_file.path;
    source.display_name = old_file.display_name;
    source.parent = old_file.parent;
    source.include_line = old_file.include_line;
    source.depth = old_file.depth;
    source.text = std::move(text);
    deck.sources.add(std::move(source));

    const std::int64_t byte_shift = static_cast<std::int64_t>(new_end) - static_cast<std::int64_t>(old_end);
    const std::int64_t line_shift = static_cast<std::int64_t>(new_lines) - static_cast<std::int64_t>(old_lines);
    const std::int64_t count_shift =
        static_cast<std::int64_t>(read.lines.size()) - static_cast<std::int64_t>(last_index - first_index);
    deck.lines.append(previous.lines, 0, first_index);
    deck.lines.append(read.lines, 0, read.lines.size(),
                      CardLines::Move{first_line - 2, static_cast<std::uint32_t>(begin - lead), true, file});
    // The lines after the edit, moved by what the edit added (modulo 2^32: a negative shift wraps back
    // into range); runs stay runs, so a bulk block costs no loop over its lines.
    deck.lines.append(previous.lines, last_index, previous.lines.size(),
                      CardLines::Move{static_cast<std::uint32_t>(line_shift), static_cast<std::uint32_t>(byte_shift)});

    deck.blocks = previous.blocks;
    deck.blocks[host_index].line_count = static_cast<std::uint32_t>(host.line_count + count_shift);
    for (std::size_t b = host_index + 1; b < deck.blocks.size(); ++b) {
        deck.blocks[b].first_line = static_cast<std::uint32_t>(deck.blocks[b].first_line + count_shift);
        shift_span(deck.blocks[b].span, file, after, line_shift);
    }
    deck.parameters = previous.parameters;
    deck.keyword_arguments = previous.keyword_arguments;
    shift_span(deck.keyword_arguments.span, file, after, line_shift);
    deck.diagnostics = previous.diagnostics;
    for (diag::Diagnostic& d : deck.diagnostics) {
        shift_span(d.span, file, after, line_shift);
        for (diag::Note& note : d.notes) shift_span(note.span, file, after, line_shift);
        for (diag::Fix& fix : d.fixes)
            for (diag::TextEdit& edit : fix.edits) shift_span(edit.span, file, after, line_shift);
    }
    deck.stats = previous.stats;
    deck.stats.bytes = now.size();
    deck.stats.lines = static_cast<std::size_t>(static_cast<std::int64_t>(previous.stats.lines) + line_shift);
    deck.stats.cards = static_cast<std::size_t>(static_cast<std::int64_t>(previous.stats.cards) + count_shift);
    return out;
}

}  // namespace sphdeck::grammar
