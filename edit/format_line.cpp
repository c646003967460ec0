#include "edit/format_line.hpp"

#include <algorithm>
#include <cstring>

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
