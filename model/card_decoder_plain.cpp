// The lean path of CardDecoder for the lines that make up nearly all of a big deck: plain
// fixed-format number lines. Anything it does not take whole (a comma, a tab, '&', text past the
// significant width, a blank required field, a value outside the fast number forms or outside
// its field's range) is left to decode(), which reports it: findings stay those of decode().
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
}  // namespace

bool CardDecoder::decode_plain(const grammar::Block& block, const grammar::CardLine& line,
                               const keywords::CardSpec& card, std::vector<FieldValue>& values) {
    const CardLayout& layout = layout_of(card, block.format);
    if (!layout.plain) return false;
    // Free format (a comma), a tab, or text past the significant width: decode() says what.
    const grammar::ScannedLine scanned = grammar::scan_line(deck_, line);
    const std::string_view text = scanned.text;
    if (text.size() > layout.significant || scanned.comma_or_tab) return false;
    values.resize(card.fields.size());
    for (std::size_t i = 0; i < card.fields.size(); ++i) {
        const keywords::FieldSpec& spec = card.fields[i];
        const grammar::FixedField& at = layout.positions[i];
        FieldValue& v = values[i];
        std::size_t offset = 0;
        const std::string_view field = trim_spaces(plain_field_text(text, at.start, at.width), offset);
        v.spec = &spec;
        v.span = grammar::Span{line.file, line.line, at.start + 1, at.start + at.width + 1};
        v.text = field;
        v.explicit_value = !field.empty();
        v.valid = false;
        v.number = 0.0;
        if (field.empty()) {
            if (spec.type == FieldType::Unused) continue;
            if (!spec.default_value) {
                if (spec.required) return false;  // DK008
                continue;
            }
            v.number = *spec.default_value;
            v.valid = true;
            continue;
        }
        if (spec.type == FieldType::Unused) return false;  // text in an unused field: rare, decode() keeps it
        if (offset > 0) {
            v.span.column += static_cast<std::uint32_t>(offset);
            v.span.end_column = v.span.column + static_cast<std::uint32_t>(field.size());
        }
        if (spec.type == FieldType::Real) {
            if (!grammar::plain_real(field, v.number)) return false;
        } else {
            long long n = 0;
            if (!grammar::plain_integer(field, n)) return false;
            v.number = static_cast<double>(n);
            if (exceeds_integer_range(v.number)) return false;  // DK007
        }
        v.valid = true;
        if (v.number == 0.0 && spec.zero_is_default && spec.default_value) {
            v.number = *spec.default_value;
            continue;
        }
        if ((!spec.choices.empty() || spec.min || spec.max) && !in_plain_range(spec, v.number)) return false;  // DK007
    }
    return true;
}

}  // namespace sphdeck::model
