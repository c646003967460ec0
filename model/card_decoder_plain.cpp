// The lean path of CardDecoder for the lines that make up nearly all of a big deck: plain
// fixed-format number lines. Anything it does not take whole (a comma, a tab, '&', text past the
// significant width, a blank required field, a value outside the fast number forms or outside
// its field's range) is left to decode(), which reports it: findings stay those of decode().
// decode_plain fills FieldValues, read_row only the numbers; both read a field with read_field (read_row
// the fast shapes in its own loop, through the same read_columns), so they take the same lines and read the
// same numbers.
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

// A blank field: its default where it has one (valid), else 0 (not valid). False for a required field
// without default, which decode() reports (DK008).
[[gnu::always_inline]] inline bool read_blank(const PlainField& f, bool& valid, double& number) {
    valid = !f.unused && f.has_default;
    number = valid ? f.default_value : 0.0;
    return f.unused || f.has_default || !f.required;
}

// What follows a number read in a field: zero means the default where the field says so, else the
// field's choices and range. False for a number out of range, which decode() reports (DK007).
// The flags first: the tests of the number wait for its division only where a field asks for them.
[[gnu::always_inline]] inline bool settle_number(const PlainField& f, const keywords::FieldSpec& spec, double& number) {
    if (f.zero_is_default && f.has_default && number == 0.0) {
        number = f.default_value;
        return true;
    }
    return !f.checks_range || in_plain_range(spec, number);
}

// The shapes a preprocessor writes, read straight from a whole field's columns: an I8 integer or a
// "%16.8e" real (grammar/value_fast.hpp). Blank or Number with `number` and `lead` (the spaces before the
// number); Other for anything else, which read_field reads.
[[gnu::always_inline]] inline grammar::fast_number::FieldShape read_columns(const PlainField& f, const char* columns,
                                                                            double& number, std::uint32_t& lead) {
    namespace fast = grammar::fast_number;
    if (f.width == 8 && !f.real && !f.unused) {
        long long n = 0;
        const fast::FieldShape shape = fast::integer8(columns, n, lead);
        number = static_cast<double>(n);
        return shape;
    }
    if (f.width == 16 && f.real && fast::e8_field16(columns, number, lead)) return fast::FieldShape::Number;
    return fast::FieldShape::Other;
}

// Field i of a plain line's text, any shape: the fast shapes from its columns, any other through
// trim_spaces and the short readers. False when the field leaves the line to decode().
bool read_field(const PlainField& f, const keywords::FieldSpec& spec, std::string_view text, ReadField& r) {
    namespace fast = grammar::fast_number;
    // The field's columns on this line (fewer at the line's end).
    const std::string_view columns = plain_field_text(text, f.start, f.width);
    fast::FieldShape shape = fast::FieldShape::Other;
    if (columns.size() == f.width) shape = read_columns(f, columns.data(), r.number, r.offset);
    if (shape == fast::FieldShape::Blank) r.text = std::string_view(columns.data() + columns.size(), 0), r.offset = 0;
    if (shape == fast::FieldShape::Number) r.text = std::string_view(columns.data() + r.offset, f.width - r.offset);
    if (shape == fast::FieldShape::Other) {
        std::size_t offset = 0;
        r.text = trim_spaces(columns, offset);
        r.offset = static_cast<std::uint32_t>(offset);
    }
    if (r.text.empty()) return read_blank(f, r.valid, r.number);
    if (f.unused) return false;  // text in an unused field: rare, decode() keeps it
    if (shape == fast::FieldShape::Other) {
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
    return settle_number(f, spec, r.number);
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
    for (std::size_t i = 0; i < card.fields.size(); ++i) {
        const PlainField& f = layout.plain_fields[i];
        ReadField r;
        if (!read_field(f, card.fields[i], *text, r)) return false;
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
    }
    return true;
}

CardDecoder::RowRead CardDecoder::read_row(const grammar::Block& block, const grammar::CardLine& line,
                                           const keywords::CardSpec& card, PlainRow& row, const grammar::CardLine* next,
                                           std::string_view through_next) {
    if (card.fields.size() > PlainRow::max_fields) return RowRead::TooWide;
    const CardLayout& layout = layout_of(card, block.format);
    const std::optional<std::string_view> text = plain_text(layout, line, next, through_next);
    if (!text) return RowRead::NotPlain;
    row.count = static_cast<std::uint32_t>(card.fields.size());
    // The fields whole on the line in the shapes a preprocessor writes are read here, in the loop; the fields
    // past the line's end are blank; any other goes through read_field (what decode_plain reads).
    namespace fast = grammar::fast_number;
    const std::size_t size = text->size();
    std::uint32_t valid = 0, written = 0;
    for (std::size_t i = 0; i < row.count; ++i) {
        const PlainField& f = layout.plain_fields[i];
        const std::uint32_t bit = std::uint32_t{1} << i;
        double& number = row.number[i];
        bool is_valid = false;
        if (f.start >= size) {  // past the line's end: blank
            if (!read_blank(f, is_valid, number)) return RowRead::NotPlain;
            valid |= is_valid ? bit : 0;
            continue;
        }
        if (f.start + f.width <= size) {
            std::uint32_t lead = 0;
            const fast::FieldShape shape = read_columns(f, text->data() + f.start, number, lead);
            if (shape == fast::FieldShape::Number) {
                if (!settle_number(f, card.fields[i], number)) return RowRead::NotPlain;
                valid |= bit, written |= bit;
                continue;
            }
            if (shape == fast::FieldShape::Blank) {
                if (!read_blank(f, is_valid, number)) return RowRead::NotPlain;
                valid |= is_valid ? bit : 0;
                continue;
            }
        }
        ReadField r;
        if (!read_field(f, card.fields[i], *text, r)) return RowRead::NotPlain;
        number = r.number;
        valid |= r.valid ? bit : 0;
        written |= r.text.empty() ? 0 : bit;
    }
    row.valid = valid, row.written = written;
    return RowRead::Read;
}

}  // namespace sphdeck::model
