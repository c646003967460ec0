#include "edit/format_line.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "text/line_rewrite.hpp"

namespace sphdeck::edit {
namespace {

using grammar::FixedField;

bool blank(char c) { return c == ' '; }

std::string_view cell_of(std::string_view text, const FixedField& f) {
    if (f.start >= text.size()) return {};
    return text.substr(f.start, f.width);
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

bool has_blank(std::string_view s) { return s.find(' ') != std::string_view::npos; }

// A label that is a plain integer ("12", "-3") lines up like a number; a name keeps its place.
bool integer_text(std::string_view s) {
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool right_aligned(CellKind kind, std::string_view value) {
    return kind == CellKind::Number || (kind == CellKind::Label && integer_text(value));
}

// Writes `value` into `out` in the field `f`: right-aligned, or from the field's first column.
void place(std::string& out, const FixedField& f, std::string_view value, bool right) {
    text::write_in_field(out, f.start, f.width, value, right ? text::Align::Right : text::Align::Left);
}

LineLayout line_doubt(std::string_view why) { return {LineVerdict::Doubt, why}; }

}  // namespace

LineLayout layout_fixed_line(std::string_view text, std::span<const FixedField> slots, std::span<const CellKind> kinds,
                             std::string& out) {
    out.clear();
    if (text.find('\t') != std::string_view::npos) return line_doubt("a tab on the line");
    const std::size_t n = std::min(slots.size(), kinds.size());
    // Every non-blank character lies in a field: the solver ignores the rest, a reader may not.
    std::size_t covered = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const FixedField& f = slots[i];
        if (f.start > covered && f.start <= text.size() && !trim(text.substr(covered, f.start - covered)).empty())
            return line_doubt("text between fields");
        covered = std::max<std::size_t>(covered, std::size_t{f.start} + f.width);
    }
    if (covered < text.size() && !trim(text.substr(covered)).empty()) return line_doubt("text past the last field");

    for (std::size_t i = 0; i < n; ++i) {
        const FixedField& f = slots[i];
        const std::string_view cell = cell_of(text, f);
        const std::string_view value = trim(cell);
        if (value.empty()) continue;
        if (kinds[i] == CellKind::Unused) return line_doubt("text in an unused field");
        if (kinds[i] != CellKind::Text && has_blank(value)) return line_doubt("a blank inside a value");
        // Two runs of characters touching across a field boundary may be one value cut in two, unless the
        // right one fills its whole field (values packed full width touch legitimately: "160.0-1.5E-05").
        if (i + 1 < n && slots[i + 1].start == f.start + f.width && f.start + f.width < text.size()) {
            const std::string_view next = cell_of(text, slots[i + 1]);
            const bool touch = !blank(text[f.start + f.width - 1]) && !next.empty() && !blank(next.front());
            const bool next_full = next.size() == slots[i + 1].width && !has_blank(next);
            if (touch && !next_full) return line_doubt("a value across a field boundary");
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        const std::string_view cell = cell_of(text, slots[i]);
        const std::string_view value = trim(cell);
        if (value.empty()) continue;
        if (kinds[i] == CellKind::Text || !right_aligned(kinds[i], value))
            place(out, slots[i], cell, false);  // text keeps its own blanks
        else
            place(out, slots[i], value, true);
        text::trim_trailing_blanks(out);
    }
    return {out == text ? LineVerdict::Same : LineVerdict::Changed, {}};
}

bool already_laid_out(std::string_view text, std::span<const FixedField> slots, std::span<const CellKind> kinds) {
    if (text.empty() || blank(text.back())) return false;
    std::size_t at = 0;
    const std::size_t n = std::min(slots.size(), kinds.size());
    for (std::size_t i = 0; i < n && at < text.size(); ++i) {
        const FixedField& f = slots[i];
        for (; at < f.start && at < text.size(); ++at)
            if (!blank(text[at])) return false;  // between fields, or fields out of order
        if (at >= text.size()) break;
        const std::string_view cell = text.substr(f.start, f.width);
        at = f.start + cell.size();
        std::size_t first = 0;
        while (first < cell.size() && blank(cell[first])) ++first;
        if (first == cell.size()) continue;
        if (kinds[i] != CellKind::Number && !(kinds[i] == CellKind::Label && integer_text(cell.substr(first))))
            return false;
        if (cell.size() != f.width || has_blank(cell.substr(first))) return false;
    }
    return at >= text.size();
}

namespace {

// laid_out_length byte by byte: lines near their file's end, lines wider than the masks below.
std::optional<std::size_t> laid_out_length_bytes(std::string_view rest, std::span<const FixedField> slots,
                                                 std::span<const CellKind> kinds) {
    const std::size_t n = std::min(slots.size(), kinds.size());
    if (n == 0) return std::nullopt;
    // The line's end, as RawDeck::text finds it ("\r\n", or the file's end), looked for no further than
    // the last field's end: a longer line has text past it.
    const std::size_t last = std::size_t{slots[n - 1].start} + slots[n - 1].width;
    const std::size_t bound = std::min(rest.size(), last + 2);
    const void* nl = std::memchr(rest.data(), '\n', bound);
    std::size_t length = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - rest.data()) : rest.size();
    if (!nl && bound < rest.size()) return std::nullopt;
    if (length > 0 && rest[length - 1] == '\r') --length;
    if (length == 0 || length > last || rest[length - 1] == ' ') return std::nullopt;
    const char* s = rest.data();
    std::size_t at = 0;
    for (std::size_t i = 0; i < n && at < length; ++i) {
        const std::size_t start = slots[i].start, end = start + slots[i].width;
        if (start < at) return std::nullopt;  // fields out of order: not the layouts this is for
        for (; at < start && at < length; ++at)
            if (s[at] != ' ') return std::nullopt;  // between fields
        while (at < end && at < length && s[at] == ' ') ++at;
        if (at == end || at == length) continue;  // a blank field, or the line's end
        if (end > length) return std::nullopt;    // a value that ends before its field does
        const std::size_t first = at;
        for (; at < end; ++at)
            if (s[at] == ' ' || s[at] == ',' || s[at] == '\t') return std::nullopt;
        if (kinds[i] == CellKind::Number) continue;
        if (kinds[i] != CellKind::Label || !integer_text(rest.substr(first, end - first))) return std::nullopt;
    }
    if (at < length) return std::nullopt;  // text past the last field
    return length;
}

#if defined(__SSE2__)
// The same with the line's blanks, commas and tabs as bit masks, 16 bytes at a time (a *NODE line is 72
// bytes): each field then takes a few mask operations. nullopt where it cannot say (the caller tries bytes).
__extension__ using LineMask = unsigned __int128;
constexpr std::size_t mask_bytes = 128;

LineMask bits(std::size_t from, std::size_t to) {  // columns [from, to), to <= 127
    return from >= to ? 0 : ((LineMask{1} << to) - 1) & ~((LineMask{1} << from) - 1);
}

std::optional<std::optional<std::size_t>> laid_out_length_masks(std::string_view rest,
                                                                std::span<const FixedField> slots,
                                                                std::span<const CellKind> kinds) {
    const std::size_t n = std::min(slots.size(), kinds.size());
    if (n == 0 || rest.size() < mask_bytes) return std::nullopt;
    const std::size_t last = std::size_t{slots[n - 1].start} + slots[n - 1].width;
    if (last + 2 > mask_bytes) return std::nullopt;
    LineMask blanks = 0, marks = 0;
    std::size_t length = mask_bytes;
    const __m128i blank = _mm_set1_epi8(' '), newline = _mm_set1_epi8('\n'), comma = _mm_set1_epi8(','),
                  tab = _mm_set1_epi8('\t');
    for (std::size_t c = 0; c < mask_bytes; c += 16) {
        const __m128i chunk = _mm_loadu_si128(reinterpret_cast<const __m128i*>(rest.data() + c));
        blanks |= LineMask{static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(chunk, blank)))} << c;
        marks |= LineMask{static_cast<unsigned>(
                     _mm_movemask_epi8(_mm_or_si128(_mm_cmpeq_epi8(chunk, comma), _mm_cmpeq_epi8(chunk, tab))))}
                 << c;
        const auto ends = static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(chunk, newline)));
        if (ends != 0) {
            length = c + static_cast<std::size_t>(std::countr_zero(ends));
            break;
        }
    }
    const std::optional<std::size_t> no;
    if (length == mask_bytes) return no;  // longer than every field
    if (length > 0 && rest[length - 1] == '\r') --length;
    if (length == 0 || length > last || rest[length - 1] == ' ' || (marks & bits(0, length)) != 0) return no;
    std::size_t at = 0;
    for (std::size_t i = 0; i < n && at < length; ++i) {
        const std::size_t start = slots[i].start, end = start + slots[i].width;
        if (start < at) return std::nullopt;  // fields out of order: the bytes say
        const LineMask gap = bits(at, std::min(start, length));
        if ((blanks & gap) != gap) return no;  // between fields
        if (start >= length) break;
        const std::size_t stop = std::min(end, length);
        const LineMask field = bits(start, stop);
        const LineMask lead = (blanks & field) >> start;  // its blanks, from its first column
        const auto blank_run = static_cast<std::size_t>(std::countr_one(static_cast<std::uint64_t>(lead)));
        at = stop;
        if (start + blank_run == stop) continue;                  // a blank field, or the line's end
        if (end > length || (lead & (lead + 1)) != 0) return no;  // cut short, or a blank inside the value
        if (kinds[i] == CellKind::Number) continue;
        if (kinds[i] != CellKind::Label || !integer_text(rest.substr(start + blank_run, end - start - blank_run)))
            return no;
    }
    if (at < length) return no;  // text past the last field
    return std::optional<std::size_t>{length};
}
#endif

}  // namespace

std::optional<std::size_t> laid_out_length(std::string_view rest, std::span<const FixedField> slots,
                                           std::span<const CellKind> kinds) {
#if defined(__SSE2__)
    if (const auto said = laid_out_length_masks(rest, slots, kinds)) return *said;
#endif
    return laid_out_length_bytes(rest, slots, kinds);
}

namespace {

bool digit(char c) { return c >= '0' && c <= '9'; }

// `s` from `at`: its run of digits; returns where it ends.
std::size_t digits_from(std::string_view s, std::size_t at) {
    while (at < s.size() && digit(s[at])) ++at;
    return at;
}

// [+-]digits, at most nine of them (no overflow, no range question of a ten-digit id).
bool plain_integer(std::string_view s) {
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
    return !s.empty() && s.size() <= 9 && digits_from(s, 0) == s.size();
}

// [+-](digits[.digits] | .digits)[(e|E)[+-]digits], the exponent at most three digits: no Fortran
// forms (1.0+3, 1.0D3), which a reader may remark on.
bool plain_real(std::string_view s) {
    std::size_t at = !s.empty() && (s.front() == '+' || s.front() == '-') ? 1 : 0;
    const std::size_t whole = digits_from(s, at);
    std::size_t end = whole, mantissa = whole - at;
    if (end < s.size() && s[end] == '.') {
        const std::size_t fraction = digits_from(s, end + 1);
        mantissa += fraction - end - 1;
        end = fraction;
    }
    if (mantissa == 0) return false;
    if (end < s.size() && (s[end] == 'e' || s[end] == 'E')) {
        std::size_t exponent = end + 1;
        if (exponent < s.size() && (s[exponent] == '+' || s[exponent] == '-')) ++exponent;
        const std::size_t stop = digits_from(s, exponent);
        if (stop == exponent || stop - exponent > 3) return false;
        end = stop;
    }
    return end == s.size();
}

}  // namespace

bool plain_laid_out(std::string_view text, std::span<const FixedField> slots, std::span<const CellKind> kinds,
                    std::uint64_t integer_fields) {
    if (text.find_first_of(",\t&") != std::string_view::npos || !already_laid_out(text, slots, kinds)) return false;
    const std::size_t n = std::min(slots.size(), kinds.size());
    for (std::size_t i = 0; i < n && slots[i].start < text.size(); ++i) {
        const std::string_view value = trim(cell_of(text, slots[i]));
        if (value.empty()) continue;
        const bool integer = i >= 64 || ((integer_fields >> i) & 1u) != 0 || kinds[i] == CellKind::Label;
        if (!plain_integer(value) && (integer || !plain_real(value))) return false;
    }
    return true;
}

LineLayout free_to_fixed(std::string_view text, std::span<const FixedField> slots, std::span<const CellKind> kinds,
                         std::string& out) {
    out.clear();
    if (text.find('\t') != std::string_view::npos) return line_doubt("a tab on the line");
    std::vector<grammar::Field> fields;
    const grammar::CutReport report = grammar::cut_fields(text, grammar::CardLine{}, slots, 1u << 30, fields, true);
    if (!report.free_format) return {LineVerdict::Same, {}};
    if (report.extra_values > 0 || !report.too_long.empty()) return line_doubt("more values than fields, or too long");
    const std::size_t n = std::min({slots.size(), kinds.size(), fields.size()});
    for (std::size_t i = 0; i < n; ++i) {
        const std::string_view value = trim(fields[i].text);
        if (value.empty()) continue;
        if (kinds[i] == CellKind::Unused) return line_doubt("text in an unused field");
        if (value.size() > slots[i].width) return line_doubt("a value longer than its field");
        if (value.find('(') != std::string_view::npos || (kinds[i] != CellKind::Text && has_blank(value)))
            return line_doubt("a value that is not one number");
        place(out, slots[i], value, right_aligned(kinds[i], value));
    }
    text::trim_trailing_blanks(out);
    return {LineVerdict::Changed, {}};
}

}  // namespace sphdeck::edit
