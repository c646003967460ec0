#include "model/radioss_card_decoder.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fmt/format.h>

#include "grammar/fields.hpp"
#include "grammar/value.hpp"
#include "model/card_decoder.hpp"  // the integer range both decoders enforce
#include "model/decimal_comma.hpp"
#include "model/radioss_parameters.hpp"
#include "model/radioss_straddles.hpp"
#include "model/shift_diagnosis.hpp"

namespace sphdeck::model {

using grammar::NumberStatus;
using grammar::radioss::Cell;

namespace {

std::string shown_cell(std::string_view text) {
    constexpr std::size_t limit = 40;
    return text.size() > limit ? std::string(text.substr(0, limit)) + "..." : std::string(text);
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// The part of a zero before its exponent's digits ('.000000000E', '0.E+'): the head of a zero written across a
// cell's end, whose digits past the end change nothing (model/radioss_straddles.cpp judges what lies there).
bool zero_before_exponent(std::string_view s) {
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
    if (!s.empty() && (s.back() == '+' || s.back() == '-')) s.remove_suffix(1);
    if (s.size() < 2 || std::string_view("eEdD").find(s.back()) == std::string_view::npos) return false;
    s.remove_suffix(1);
    return s.find_first_not_of("0.") == std::string_view::npos && s.find('0') != std::string_view::npos &&
           s.find('.') == s.rfind('.');
}

// What the starter makes of a cell that is no number. Its reader scans the cell with sscanf (%lg, %d: hc_scan_double,
// reader/source/cfgkernel/UTILS/str_utils.cpp, a D exponent read as E), which reads the number the text begins with
// and ignores the rest ('25O' is 25), or reads none (meci_data_reader.cpp: an error message, and 0).
std::string starter_reading(std::string_view token, bool integer) {
    std::string text(token);
    if (const std::size_t d = text.find_first_of("dD"); d != std::string::npos) text[d] = text[d] == 'D' ? 'E' : 'e';
    char* end = nullptr;
    if (integer)
        (void)std::strtol(text.c_str(), &end, 10);
    else
        (void)std::strtod(text.c_str(), &end);
    const auto used = static_cast<std::size_t>(end - text.c_str());
    if (used == 0) return "the starter reads no number there (it reports the cell and takes 0)";
    std::string_view rest = token.substr(used);
    rest.remove_prefix(std::min(rest.find_first_not_of(" \t"), rest.size()));
    return fmt::format("the starter reads {} and ignores '{}'", token.substr(0, used), rest);
}

std::string_view trim_cell(std::string_view s, std::size_t* offset = nullptr) {
    std::size_t b = 0, e = s.size();
    while (b < e && is_space(s[b])) ++b;
    while (e > b && is_space(s[e - 1])) --e;
    if (offset) *offset = b;
    return s.substr(b, e - b);
}

bool numeric_cell(Cell c) { return c == Cell::Int || c == Cell::Real; }

// A chunk past the card's last field the starter accepts silently: blank or a zero
// (meci_data_reader.cpp walks the rest of the line in 10-character chunks).
bool harmless_chunk(std::string_view chunk) {
    std::string_view t = trim_cell(chunk);
    if (t.empty()) return true;
    grammar::RealValue v = grammar::parse_real(t);
    return v.status == NumberStatus::Ok && v.value == 0.0;
}

grammar::Span columns(const grammar::CardLine& line, std::size_t begin, std::size_t end) {
    return grammar::Span{line.file, line.line, static_cast<std::uint32_t>(begin + 1),
                         static_cast<std::uint32_t>(std::max(end, begin + 1) + 1)};
}

}  // namespace

void RadiossCardDecoder::report(const char* code, diag::Severity s, std::string message, grammar::Span span) {
    out_.push_back(diag::Diagnostic{code, s, std::move(message), span, {}});
}

void RadiossCardDecoder::decode(const grammar::CardLine& line, const grammar::radioss::CardSpec& card, int version,
                                bool list_directed, std::vector<RadiossValue>& values, std::string_view newer,
                                bool trailing_checked, std::uint32_t quiet_until) {
    if (list_directed)
        decode_tokens(line, card, values);
    else
        decode_fixed(line, card, version, values, newer, trailing_checked, quiet_until);
}

void RadiossCardDecoder::decode_text(const grammar::CardLine& line, std::string_view text,
                                     const grammar::radioss::CardSpec& card, int version,
                                     std::vector<RadiossValue>& values) {
    text_override_ = text;
    decode_fixed(line, card, version, values, {}, true, 0);
    text_override_.reset();
}

const std::vector<grammar::FixedField>& RadiossCardDecoder::layout_of(const grammar::radioss::CardSpec& card,
                                                                      int version) {
    if (!layouts_.empty() && layouts_[last_layout_].card == &card && layouts_[last_layout_].version == version)
        return layouts_[last_layout_].positions;  // repeated cards: the same layout line after line
    for (std::size_t k = 0; k < layouts_.size(); ++k)
        if (layouts_[k].card == &card && layouts_[k].version == version) {
            last_layout_ = k;
            return layouts_[k].positions;
        }
    layouts_.push_back({&card, version, grammar::radioss::layout(card, version)});
    last_layout_ = layouts_.size() - 1;
    return layouts_.back().positions;
}

namespace {
// Per field of `card`, whether the starter skips its columns.
std::vector<unsigned char> unused_mask(const grammar::radioss::CardSpec& card) {
    std::vector<unsigned char> out;
    for (const auto& f : card.fields) out.push_back(f.cell == Cell::Skip || f.cell == Cell::Skip20);
    return out;
}
}  // namespace

void RadiossCardDecoder::decode_fixed(const grammar::CardLine& line, const grammar::radioss::CardSpec& card,
                                      int version, std::vector<RadiossValue>& values, std::string_view newer,
                                      bool trailing_checked, std::uint32_t quiet_until) {
    const std::size_t found_before = out_.size();
    const std::vector<grammar::FixedField>& positions = layout_of(card, version);
    const std::uint32_t end =
        positions.empty() ? 0 : positions.back().start + std::min(positions.back().width, 1u << 20);
    const bool text_card = !card.fields.empty() && card.fields.front().cell == Cell::Line;
    const std::string_view text = text_override_ ? *text_override_ : deck_.text(line);
    const grammar::CutReport cut = grammar::cut_fields(text, line, positions, end, fields_, !text_card);

    if (cut.has_tab && !text_card) {
        const std::size_t tab = text.find('\t');
        report("DK016", diag::Severity::Warning, "tab in a fixed-format card: columns become ambiguous",
               columns(line, tab, tab + 1));
    } else if (!text_card && !cut.free_format && text.find('\t') != std::string_view::npos &&
               grammar::tab_pulls_values_off_fields(text, positions, unused_mask(card))) {
        const std::size_t tab = text.find('\t');
        report("DK016", diag::Severity::Warning,
               "tab in a fixed-format card where blanks were meant: the starter counts it as one column, so the "
               "values after it sit left of their cells' ends",
               columns(line, tab, tab + 1));
    }
    if (!trailing_checked) {
        // the starter reads past the last field silently for this keyword
    } else if (cut.free_format && cut.extra_values > 0 && quiet_until == 0) {
        report("DK006", diag::Severity::Warning,
               fmt::format("{} value(s) beyond the card's {} fields are ignored", cut.extra_values, card.fields.size()),
               cut.beyond);
    } else if (const std::uint32_t from = std::max(end, quiet_until); !cut.free_format && text.size() > from) {
        // The starter warns for each 10-character chunk past the last field that is not blank
        // or zero (reader messages 100213/100214); the first and last such chunks bound the span.
        std::size_t first = std::string_view::npos, last = 0;
        for (std::size_t at = from; at < text.size(); at += 10) {
            std::string_view chunk = text.substr(at, 10);
            if (harmless_chunk(chunk)) continue;
            std::size_t lead = 0;
            std::string_view t = trim_cell(chunk, &lead);
            if (first == std::string_view::npos) first = at + lead;
            last = at + lead + t.size();
        }
        if (first != std::string_view::npos) {
            std::string message =
                fmt::format("text after column {} is past the card's last field and is ignored", from);
            if (!newer.empty()) message += fmt::format(" ({}; the deck's Invers is {})", newer, version);
            report("DK006", diag::Severity::Warning, std::move(message), columns(line, first, last));
        }
    }

    values.resize(card.fields.size());
    for (std::size_t i = 0; i < card.fields.size(); ++i) {
        RadiossValue& v = values[i];
        v = RadiossValue{};
        v.spec = &card.fields[i];
        v.span = fields_[i].span;
        if (v.spec->cell == Cell::Skip || v.spec->cell == Cell::Skip20) continue;
        read_value(v, fields_[i].text, !cut.free_format);
    }
    if (cut.free_format && !text_card) check_decimal_comma(line, text, values, positions, found_before);
    if (!text_card && !cut.free_format && !cut.has_tab) {
        const std::string_view header = header_above(deck_, line, "#");
        if (out_.size() > found_before || glued_across_cells(text, positions) || !header.empty())
            diagnose_radioss_line(line, text, card, positions,
                                  block_ < deck_.blocks.size() ? std::string_view(deck_.blocks[block_].keyword)
                                                               : "its card",
                                  header, out_, found_before);
        if (out_.size() == found_before && block_ < deck_.blocks.size())
            lone_shifts_.note(line, text, card, positions, deck_.blocks[block_].keyword);
    }
}

// `  1,0E-6` for `  1.0E-6`: the starter reads a line with a comma as free format, the number cut in
// two (the same mistake as in LS-DYNA, model/decimal_comma.hpp).
void RadiossCardDecoder::check_decimal_comma(const grammar::CardLine& line, std::string_view text,
                                             const std::vector<RadiossValue>& values,
                                             std::span<const grammar::FixedField> positions,
                                             std::size_t first_finding) {
    const auto comma = find_decimal_comma(text, positions);
    if (!comma) return;
    std::string reading;
    std::size_t shown_fields = 0;
    for (const RadiossValue& v : values) {
        if (shown_fields == 4) break;
        if (!v.explicit_value || !v.spec || !numeric_cell(v.spec->cell)) continue;
        reading += fmt::format("{}{} {}", reading.empty() ? "" : ", ", v.spec->name, shown_cell(v.text));
        ++shown_fields;
    }
    report_decimal_comma(*comma, line, "the starter", reading, out_, first_finding);
}

// Engine data lines are read by Fortran list-directed input: tokens separated by blanks or commas.
void RadiossCardDecoder::decode_tokens(const grammar::CardLine& line, const grammar::radioss::CardSpec& card,
                                       std::vector<RadiossValue>& values) {
    const std::string_view text = deck_.text(line);
    values.assign(card.fields.size(), RadiossValue{});
    std::size_t i = 0, at = 0;
    for (std::size_t k = 0; k < card.fields.size(); ++k) {
        values[k].spec = &card.fields[k];
        values[k].span = columns(line, text.size(), text.size() + 1);
    }
    while (at < text.size() && i < card.fields.size()) {
        while (at < text.size() && (is_space(text[at]) || text[at] == ',')) {
            if (text[at] == ',' && at + 1 < text.size() && text[at + 1] == ',') ++i;  // ",," skips a value
            ++at;
        }
        if (at >= text.size() || i >= card.fields.size()) break;
        std::size_t stop = at;
        while (stop < text.size() && !is_space(text[stop]) && text[stop] != ',') ++stop;
        values[i].span = columns(line, at, stop);
        read_value(values[i], text.substr(at, stop - at), false);
        ++i;
        at = stop;
    }
}

void RadiossCardDecoder::read_value(RadiossValue& v, std::string_view field, bool fixed) {
    std::size_t offset = 0;
    std::string_view token = trim_cell(field, &offset);
    v.text = token;
    v.explicit_value = !token.empty();
    const std::uint32_t cell_columns = v.span.end_column - v.span.column;
    if (v.explicit_value && fixed) {
        v.span.column += static_cast<std::uint32_t>(offset);
        v.span.end_column = v.span.column + static_cast<std::uint32_t>(token.size());
    }
    const Cell cell = v.spec->cell;
    if (!numeric_cell(cell)) {
        v.valid = v.explicit_value;
        return;
    }
    if (!v.explicit_value) return;
    const bool integer = cell == Cell::Int;
    // Two numbers in one fixed cell: the starter keeps the first and drops the rest (RAD025).
    const std::size_t gap = token.find_first_of(" \t");
    if (fixed && gap != std::string_view::npos) {
        std::string_view head = token.substr(0, gap), rest = trim_cell(token.substr(gap));
        std::string_view second = rest.substr(0, rest.find_first_of(" \t"));
        grammar::RealValue a = grammar::parse_real(head), b = grammar::parse_real(second);
        // The tail of a zero written across the cell's start ("0000      .000000000" after
        // ".00000"; model/radioss_straddles.cpp) and an equal number: the value read is the one meant.
        // So is a zero's head left in the cell by a zero across its end ("0       .000000000E" before "00").
        const bool last_in_cell = trim_cell(rest.substr(second.size())).empty();
        const bool zero_across_end = a.status == NumberStatus::Ok && a.value == 0.0 && last_in_cell &&
                                     zero_before_exponent(second) && offset + token.size() == field.size() &&
                                     field.size() == cell_columns;
        const bool same =
            zero_across_end || (offset == 0 && a.status == NumberStatus::Ok && b.status == NumberStatus::Ok &&
                                a.value == 0.0 && b.value == 0.0 && last_in_cell);
        if (same) {
            token = head;
            v.text = head;
        } else if (a.status == NumberStatus::Ok && b.status == NumberStatus::Ok) {
            report("RAD025", diag::Severity::Error,
                   fmt::format("two numbers in the {}-column field {}: '{}'; the starter keeps {} and drops {}",
                               cell_columns, v.spec->name, shown_cell(token), head, second),
                   v.span);
            token = head;
            v.text = head;
        }
    }
    if (auto ref = radioss_parameter_reference(token)) {
        if (!parameters_) return;  // no table: the value stays unknown, no finding
        if (auto value = parameters_->value_of(*ref, block_, integer, v.spec->name, v.span, out_)) {
            v.number = integer ? std::trunc(*value) : *value;
            v.valid = !(integer && exceeds_integer_range(v.number));
            if (!v.valid) report("DK007", diag::Severity::Error, integer_range_message(v.spec->name, v.number), v.span);
        }
        return;
    }
    grammar::ValueToken t =
        grammar::classify_value(token, integer ? grammar::ValueShape::Integer : grammar::ValueShape::Real);
    if (t.shape == grammar::ValueShape::Parameter) return;  // not reached: references are read above
    if (integer) {
        grammar::IntegerValue n = grammar::to_integer(t);
        if (n.status != NumberStatus::Ok) {
            report("DK002", diag::Severity::Error,
                   fmt::format("'{}' in integer field {} is not an integer: {}", shown_cell(token), v.spec->name,
                               starter_reading(token, true)),
                   v.span);
            return;
        }
        if (n.written_as_real)
            report("DK004", diag::Severity::Warning,
                   fmt::format("integer field {} written as real '{}'; read as {}", v.spec->name, shown_cell(token),
                               n.value),
                   v.span);
        v.number = static_cast<double>(n.value);
        if (exceeds_integer_range(v.number)) {
            report("DK007", diag::Severity::Error, integer_range_message(v.spec->name, v.number), v.span);
            return;
        }
    } else {
        grammar::RealValue r = grammar::to_real(t);
        if (r.status != NumberStatus::Ok) {
            report("DK003", diag::Severity::Error,
                   fmt::format("'{}' in real field {} is not a number: {}", shown_cell(token), v.spec->name,
                               starter_reading(token, false)),
                   v.span);
            return;
        }
        v.number = r.value;
    }
    v.valid = true;
}

grammar::Span radioss_field_span(const grammar::RawDeck& deck, std::uint32_t index,
                                 const grammar::radioss::CardSpec& card, int version, std::size_t field) {
    if (index >= deck.lines.size()) return {};
    const grammar::CardLine& line = deck.lines[index];
    const grammar::Span whole{line.file, line.line, 1, deck.length(line) + 1};
    if (field >= card.fields.size()) return whole;
    std::vector<grammar::Field> fields;
    const auto positions = grammar::radioss::layout(card, version);
    const std::string_view text = deck.text(line);
    grammar::CutReport cut = grammar::cut_fields(text, line, positions, 1u << 30, fields);
    if (field >= fields.size()) return whole;
    grammar::Span s = fields[field].span;
    std::size_t offset = 0;
    std::string_view t = trim_cell(fields[field].text, &offset);
    if (!t.empty() && !cut.free_format) {
        s.column += static_cast<std::uint32_t>(offset);
        s.end_column = s.column + static_cast<std::uint32_t>(t.size());
    }
    return s;
}

}  // namespace sphdeck::model
