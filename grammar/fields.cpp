#include "grammar/fields.hpp"

#include <optional>
#include <algorithm>
#include <cstring>
#include <tao/pegtl.hpp>

namespace sphdeck::grammar {
namespace {

namespace pegtl = tao::pegtl;

// Free format: values separated by commas; a parenthesised group may hold commas itself.
// Groups do not nest on purpose: data fields hold no expressions, and a line of a million
// '(' must not recurse a million deep.
namespace free_rules {
struct plain : pegtl::not_one<',', '(', ')', '\n'> {};
struct group : pegtl::seq<pegtl::one<'('>, pegtl::star<pegtl::not_one<')', '\n'>>, pegtl::opt<pegtl::one<')'>>> {};
struct token : pegtl::star<pegtl::sor<group, plain, pegtl::one<')'>>> {};
struct line : pegtl::seq<pegtl::list<token, pegtl::one<','>>, pegtl::eof> {};
struct has_top_level_comma : pegtl::seq<token, pegtl::one<','>> {};
}  // namespace free_rules

template <typename Rule>
struct token_action : pegtl::nothing<Rule> {};
template <>
struct token_action<free_rules::token> {
    template <typename FieldInput>
    static void apply(const FieldInput& in, std::vector<std::string_view>& tokens) {
        tokens.push_back(in.string_view());
    }
};

using FieldInput = pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf, const char*>;

std::uint32_t widened_width(std::uint32_t width, CardFormat format) {
    switch (format) {
        case CardFormat::I10: return std::max<std::uint32_t>(width, 10);
        case CardFormat::Long: return std::max<std::uint32_t>(width, 20);
        case CardFormat::Standard: return width;
    }
    return width;
}

Span column_span(const CardLine& line, std::size_t begin, std::size_t end) {
    return Span{line.file, line.line, static_cast<std::uint32_t>(begin + 1), static_cast<std::uint32_t>(end + 1)};
}

std::string_view trimmed_cell(std::string_view text, const FixedField& f) {
    if (f.start >= text.size()) return {};
    std::string_view cell = text.substr(f.start, f.width);
    while (!cell.empty() && (cell.front() == ' ' || cell.front() == '\t')) cell.remove_prefix(1);
    while (!cell.empty() && (cell.back() == ' ' || cell.back() == '\t' || cell.back() == '\r')) cell.remove_suffix(1);
    return cell;
}

// Whether a tab makes the line ambiguous: read with each tab as one column (the solver) and with
// tabs expanded to the next multiple of 8 (an editor), some field holds another value, or a value
// moves past the last field. A tab before a value that stays in its cell either way ("\t1.0" in a
// 10-column field) shifts nothing.
bool tab_moves_a_value(std::string_view text, std::span<const FixedField> positions) {
    thread_local std::string expanded;
    expanded.clear();
    for (char c : text) {
        if (c != '\t') {
            expanded += c;
            continue;
        }
        expanded.append(8 - expanded.size() % 8, ' ');
    }
    std::uint32_t last_end = 0;
    for (const FixedField& f : positions) {
        if (trimmed_cell(text, f) != trimmed_cell(expanded, f)) return true;
        last_end = std::max(last_end, f.start + std::min<std::uint32_t>(f.width, 1u << 30));
    }
    const FixedField rest{last_end, 1u << 30};
    return trimmed_cell(text, rest) != trimmed_cell(expanded, rest);
}

bool blank_char(char c) { return c == ' ' || c == '\t' || c == '\r'; }

}  // namespace

// A tab typed where a run of blanks was: the values after it move left by the blanks it replaced.
// Evidence that the author meant blanks: every value before the tab ends exactly at its field's end
// (the line is right-aligned, as generators and LS-PrePost write it) and some value after it does not.
bool tab_pulls_values_off_fields(std::string_view text, std::span<const FixedField> positions,
                                 std::span<const unsigned char> unused) {
    const auto tab = text.find('\t');
    if (tab == std::string_view::npos || positions.empty()) return false;
    constexpr std::size_t none = static_cast<std::size_t>(-1);
    std::size_t field_index = none;  // of the last field_end_of that found one
    const auto field_end_of = [&](std::size_t last) -> std::optional<std::size_t> {  // last: a value's last byte
        for (std::size_t k = 0; k < positions.size(); ++k) {
            const FixedField& f = positions[k];
            if (last >= f.start && last < std::size_t{f.start} + f.width) {
                field_index = k;
                return std::size_t{f.start} + f.width;
            }
        }
        field_index = none;
        return std::nullopt;
    };
    // A value after the tab that now spans two fields, or shares its field with another: what is read
    // changed. A value that merely sits inside its field, off its end ("1\t1.0"), is read as written.
    bool before = false, misread = false;
    std::optional<std::size_t> last_field_after;
    for (std::size_t i = 0; i < text.size();) {
        if (blank_char(text[i])) {
            ++i;
            continue;
        }
        std::size_t end = i;
        while (end < text.size() && !blank_char(text[end])) ++end;
        const auto field_end = field_end_of(end - 1);
        if (end <= tab) {
            if (!field_end || *field_end != end) return false;  // not a right-aligned line: no evidence
            before = true;
        } else {
            const auto start_end = field_end_of(i);
            if (!field_end || !start_end || *start_end != *field_end)
                misread = true;  // across a boundary
            else if (last_field_after && *last_field_after == *field_end)
                misread = true;  // two in one field
            else if (field_index != none && field_index < unused.size() && unused[field_index])
                misread = true;  // lost
            last_field_after = field_end;
        }
        i = end;
    }
    return before && misread;
}

namespace {

// Tabs only before the first value ("\t   1.0e-3   2.0").
bool only_leading_tabs(std::string_view text) {
    std::size_t first = 0;
    while (first < text.size() && blank_char(text[first])) ++first;
    return text.find('\t', first) == std::string_view::npos;
}

// Read with each tab as one column (as the solver reads it), every value lies inside one field and
// no field holds two values: the line reads as its author laid it out, whatever an editor shows.
bool values_in_their_cells(std::string_view text, std::span<const FixedField> positions) {
    std::size_t previous_cell = positions.size();
    for (std::size_t i = 0; i < text.size();) {
        if (blank_char(text[i])) {
            ++i;
            continue;
        }
        const std::size_t begin = i;
        while (i < text.size() && !blank_char(text[i])) ++i;
        std::size_t cell = positions.size();
        for (std::size_t k = 0; k < positions.size(); ++k)
            if (begin >= positions[k].start && begin - positions[k].start < positions[k].width) cell = k;
        if (cell == positions.size()) return false;  // in a gap or past the fields
        if (i - positions[cell].start > positions[cell].width || cell == previous_cell) return false;
        previous_cell = cell;
    }
    return true;
}

}  // namespace

std::string_view to_string(CardFormat f) {
    switch (f) {
        case CardFormat::Standard: return "standard";
        case CardFormat::I10: return "i10";
        case CardFormat::Long: return "long";
    }
    return "standard";
}

std::string_view trim_blanks(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

bool is_blank(std::string_view s) {
    for (char c : s)
        if (c != ' ' && c != '\t' && c != '\r') return false;
    return true;
}

void widen(std::span<const FixedField> standard, CardFormat format, std::vector<FixedField>& out) {
    out.clear();
    out.reserve(standard.size());
    std::uint32_t standard_end = 0, position = 0;
    for (const FixedField& f : standard) {
        if (f.start > standard_end) position += widened_width(f.start - standard_end, format);  // an unused gap
        std::uint32_t w = widened_width(f.width, format);
        out.push_back({format == CardFormat::Standard ? f.start : position, w});
        position = (format == CardFormat::Standard ? f.start : position) + w;
        standard_end = f.start + f.width;
    }
}

std::uint32_t significant_width(std::span<const FixedField> widened_fields, CardFormat format) {
    std::uint32_t end = widened_fields.empty() ? 0 : widened_fields.back().start + widened_fields.back().width;
    return std::max<std::uint32_t>(end, format == CardFormat::Long ? 160 : 80);
}

bool is_free_format(std::string_view text) {
    if (!std::memchr(text.data(), ',', text.size())) return false;
    FieldInput in(text.data(), text.data() + text.size(), "line");
    return pegtl::parse<free_rules::has_top_level_comma>(in);
}

CutReport cut_fields(std::string_view text, const CardLine& line, std::span<const FixedField> positions,
                     std::uint32_t significant, std::vector<Field>& out, bool allow_free) {
    CutReport report;
    out.clear();

    if (allow_free && is_free_format(text)) {
        report.free_format = true;
        thread_local std::vector<std::string_view> tokens;
        tokens.clear();
        FieldInput in(text.data(), text.data() + text.size(), "line");
        pegtl::parse<free_rules::line, token_action>(in, tokens);
        for (std::size_t i = 0; i < tokens.size(); ++i) {
            std::size_t begin = static_cast<std::size_t>(tokens[i].data() - text.data());
            Span span = column_span(line, begin, begin + std::max<std::size_t>(tokens[i].size(), 1));
            if (i >= positions.size()) {
                if (!is_blank(tokens[i])) {
                    if (report.extra_values++ == 0) report.beyond = span;
                    report.beyond.end_column = span.end_column;
                }
                continue;
            }
            // The token-length rule: a free value may not be longer than its fixed field.
            std::string_view value = tokens[i];
            while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
            while (!value.empty() && (value.back() == ' ' || value.back() == '\r')) value.remove_suffix(1);
            if (value.size() > positions[i].width) report.too_long.push_back(static_cast<std::uint32_t>(i));
            out.push_back({tokens[i], span});
        }
        for (std::size_t i = out.size(); i < positions.size(); ++i)
            out.push_back({{}, column_span(line, text.size(), text.size() + 1)});
        return report;
    }

    // Only a tab before a value shifts columns; tabs after the last value are trailing blanks.
    std::size_t end = text.size();
    while (end > 0 && (text[end - 1] == ' ' || text[end - 1] == '\t' || text[end - 1] == '\r')) --end;
    report.has_tab = end > 0 && std::memchr(text.data(), '\t', end) != nullptr && tab_moves_a_value(text, positions) &&
                     !(only_leading_tabs(text.substr(0, end)) && values_in_their_cells(text.substr(0, end), positions));
    for (const FixedField& f : positions) {
        std::string_view field = f.start < text.size() ? text.substr(f.start, f.width) : std::string_view{};
        out.push_back({field, column_span(line, f.start, f.start + f.width)});
    }
    std::uint32_t limit = significant;
    if (text.size() > limit && !is_blank(text.substr(limit))) {
        std::size_t first = limit;
        while (first < text.size() && (text[first] == ' ' || text[first] == '\t')) ++first;
        std::size_t last = text.size();
        while (last > first && (text[last - 1] == ' ' || text[last - 1] == '\r')) --last;
        report.beyond = column_span(line, first, last);
    }
    return report;
}

}  // namespace sphdeck::grammar

namespace sphdeck::grammar {

std::string_view RawDeck::text(const CardLine& l) const {
    const std::string_view file = sources.file(l.file).text;
    const char* begin = file.data() + l.offset;
    const std::size_t rest = file.size() - l.offset;
    const void* newline = std::memchr(begin, '\n', rest);
    std::size_t length = newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - begin) : rest;
    if (length > 0 && begin[length - 1] == '\r') --length;
    return std::string_view(begin, length);
}

}  // namespace sphdeck::grammar
