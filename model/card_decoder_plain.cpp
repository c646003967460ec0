// The lean path of CardDecoder for the lines that make up nearly all of a big deck: plain
// fixed-format number lines. Anything it does not take whole (a comma, a tab, '&', text past the
// significant width, a blank required field, a value outside the fast number forms or outside
// its field's range) is left to decode(), which reports it: findings stay those of decode().
// decode_plain fills FieldValues, read_row only the numbers; both walk the line with read_plain,
// so they take the same lines and read the same numbers.
#include <algorithm>
#include <cmath>
#include <optional>

#include "grammar/line_scan.hpp"
#include "grammar/number_cast.hpp"
#include "grammar/value_fast.hpp"
#include "model/card_decoder.hpp"

namespace sphdeck::model {

using keywords::FieldType;

namespace {
// Spaces only: a tab or '\r' inside a field sends the line to decode().
std::string_view trim_spaces(std::string_view s, std::size_t& offset) {
    std::size_t b = 0, e = s.size();
    while (b < e && s[b] == ' ') ++b;
    while (e > b && s[e - 1] == ' ') --e;
    offset = b;
    return {s.data() + b, e - b};
}

// text.substr(start, width) for start <= text.size(), without substr's check and throw (a call per
// field of two million lines).
std::string_view plain_field_text(std::string_view text, std::size_t start, std::size_t width) {
    return start < text.size() ? std::string_view(text.data() + start, std::min(width, text.size() - start))
                               : std::string_view{};
}

// What decode_number checks after the value: an integer beyond 2^53, choices and ranges.
bool in_plain_range(const keywords::FieldSpec& spec, double number) {
    if (!spec.choices.empty()) {
        const std::optional<long long> as_integer = grammar::checked_integer<long long>(number);
        return number == std::trunc(number) && as_integer && spec.choice(*as_integer);
    }
    return !(spec.min && number < *spec.min) && !(spec.max && number > *spec.max);
}

// Where a line ends when the deck's next card line is the line after it in the same file: just before the
// '\n' in front of that line (the readers split lines there), less a '\r'. Nothing when it is not.
// `start`: the line's first byte, in `file` or in a copy of it.
std::optional<std::size_t> known_length(std::string_view file, const grammar::CardLine& line,
                                        const grammar::CardLine* next, const char* start) {
    if (!next || next->file != line.file || next->line != line.line + 1 || next->offset <= line.offset ||
        next->offset > file.size())
        return std::nullopt;
    std::size_t length = next->offset - 1 - line.offset;
    if (start[length] != '\n') return std::nullopt;
    if (length > 0 && start[length - 1] == '\r') --length;
    return length;
}

// Nothing but blanks after the fields: text there (a second line joined to this one, DK037) is read by no field,
// and decode() notes it (CardDecoder::text_past_fields).
bool blank_past_fields(std::string_view text, const CardLayout& layout) {
    for (std::size_t i = layout.fields_end; i < text.size(); ++i)
        if (text[i] != ' ') return false;
    return true;
}

// One field as read: its text (trimmed, as written), the spaces before it, and its number.
struct ReadField {
    std::string_view text;
    std::uint32_t offset = 0;
    bool valid = false;
    double number = 0.0;
};

// Reads the fields of a plain line's text, handing each to `put(i, field)`; false at the first field that
// leaves the line to decode(). Inline in both callers: a call a line, none a field.
template <typename Put>
inline bool read_plain(const CardLayout& layout, const keywords::CardSpec& card, std::string_view text, Put&& put) {
    namespace fast = grammar::fast_number;
    const std::size_t count = card.fields.size();
    for (std::size_t i = 0; i < count; ++i) {
        const PlainField& f = layout.plain_fields[i];
        // The field's columns on this line (fewer at the line's end), then its value: the shapes a
        // preprocessor writes straight from the columns, any other through trim_spaces and the short readers.
        const std::string_view columns = plain_field_text(text, f.start, f.width);
        ReadField r;
        bool read = false;
        if (columns.size() == 8 && !f.real && !f.unused) {
            long long n = 0;
            const fast::FieldShape shape = fast::integer8(columns.data(), n, r.offset);
            if (shape == fast::FieldShape::Blank) {
                r.text = std::string_view(columns.data() + 8, 0), r.offset = 0;
                read = true;
            } else if (shape == fast::FieldShape::Number) {
                r.text = std::string_view(columns.data() + r.offset, 8 - r.offset), r.number = static_cast<double>(n);
                read = true;
            }
        } else if (columns.size() == 16 && f.real) {
            if (fast::e8_field16(columns.data(), r.number, r.offset)) {
                r.text = std::string_view(columns.data() + r.offset, 16 - r.offset);
                read = true;
            }
        }
        if (!read) {
            std::size_t offset = 0;
            r.text = trim_spaces(columns, offset);
            r.offset = static_cast<std::uint32_t>(offset);
        }
        if (r.text.empty()) {
            r.number = 0.0;
            if (!f.unused && f.has_default) r.valid = true, r.number = f.default_value;
            if (!f.unused && !f.has_default && f.required) return false;  // DK008
            put(i, r);
            continue;
        }
        if (f.unused) return false;  // text in an unused field: rare, decode() keeps it
        if (!read) {
            if (f.real) {
                if (!grammar::plain_real(r.text, r.number)) return false;
            } else {
                long long n = 0;
                if (!grammar::plain_integer(r.text, n)) return false;
                r.number = static_cast<double>(n);
                if (exceeds_integer_range(r.number)) return false;  // DK007
            }
        }
        r.valid = true;
        // The flags first: the tests of the number wait for its division only where a field asks for them.
        if (f.zero_is_default && f.has_default && r.number == 0.0) {
            r.number = f.default_value;
            put(i, r);
            continue;
        }
        if (f.checks_range && !in_plain_range(card.fields[i], r.number)) return false;  // DK007
        put(i, r);
    }
    return true;
}
}  // namespace

// Inline always in its two callers (below): a call a line showed in profiles.
[[gnu::always_inline]] inline std::optional<std::string_view> CardDecoder::plain_text(const CardLayout& layout,
                                                                                      const grammar::CardLine& line,
                                                                                      const grammar::CardLine* next,
                                                                                      std::string_view through_next) {
    // Free format (a comma), a tab, or text past the fields: decode() says what. A line whose end is known
    // needs its columns past the fields looked at only: a ',' or '\t' inside a field makes that field read
    // as no number, and the line goes to decode() all the same.
    if (!layout.plain) return std::nullopt;
    const std::string_view file = file_text(line.file);
    const bool held = next && next->offset > line.offset && through_next.size() == next->offset - line.offset;
    const char* const start = held ? through_next.data() : file.data() + line.offset;
    if (const std::optional<std::size_t> length =
            layout.contiguous ? known_length(file, line, next, start) : std::nullopt) {
        const std::string_view text(start, *length);
        if (text.size() > layout.significant) return std::nullopt;
        if (text.size() > layout.fields_end && !blank_past_fields(text, layout)) return std::nullopt;
        return text;
    }
    const grammar::ScannedLine scanned = grammar::scan_line(deck_, line);
    if (scanned.text.size() > layout.significant || scanned.comma_or_tab || !blank_past_fields(scanned.text, layout))
        return std::nullopt;
    return scanned.text;
}

bool CardDecoder::decode_plain(const grammar::Block& block, const grammar::CardLine& line,
                               const keywords::CardSpec& card, std::vector<FieldValue>& values,
                               const grammar::CardLine* next) {
    const CardLayout& layout = layout_of(card, block.format);
    const std::optional<std::string_view> text = plain_text(layout, line, next);
    if (!text) return false;
    values.resize(card.fields.size());
    return read_plain(layout, card, *text, [&](std::size_t i, const ReadField& r) {
        const PlainField& f = layout.plain_fields[i];
        FieldValue& v = values[i];
        v.spec = &card.fields[i];
        v.span = grammar::Span{line.file, line.line, f.start + 1, f.start + f.width + 1};
        if (r.offset > 0 && !r.text.empty()) {
            v.span.column += r.offset;
            v.span.end_column = v.span.column + static_cast<std::uint32_t>(r.text.size());
        }
        v.text = r.text;
        v.explicit_value = !r.text.empty();
        v.valid = r.valid;
        v.number = r.number;
    });
}

CardDecoder::RowRead CardDecoder::read_row(const grammar::Block& block, const grammar::CardLine& line,
                                           const keywords::CardSpec& card, PlainRow& row, const grammar::CardLine* next,
                                           std::string_view through_next) {
    if (card.fields.size() > PlainRow::max_fields) return RowRead::TooWide;
    const CardLayout& layout = layout_of(card, block.format);
    const std::optional<std::string_view> text = plain_text(layout, line, next, through_next);
    if (!text) return RowRead::NotPlain;
    row.count = static_cast<std::uint32_t>(card.fields.size());
    row.valid = 0, row.written = 0;
    const bool plain = read_plain(layout, card, *text, [&](std::size_t i, const ReadField& r) {
        row.number[i] = r.number;
        row.valid |= static_cast<std::uint32_t>(r.valid) << i;
        row.written |= static_cast<std::uint32_t>(!r.text.empty()) << i;
    });
    return plain ? RowRead::Read : RowRead::NotPlain;
}

}  // namespace sphdeck::model
