#include "model/card_decoder.hpp"
#include "grammar/undefined_parameter.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fmt/format.h>
#include <map>
#include <optional>

#include "grammar/number_cast.hpp"
#include "grammar/realign.hpp"
#include "grammar/tab_expansion.hpp"
#include "grammar/shifted_line.hpp"
#include "grammar/value.hpp"
#include "model/decimal_comma.hpp"
#include "text/line_rewrite.hpp"

namespace sphdeck::model {

using grammar::NumberStatus;
using keywords::FieldType;

namespace {
std::string shown_value(std::string_view text) {
    constexpr std::size_t limit = 40;
    return text.size() > limit ? std::string(text.substr(0, limit)) + "..." : std::string(text);
}
std::string number_text(double v) { return fmt::format("{:g}", v); }

// A fixed-format value glued to its neighbour across a field boundary explains a DK002/DK003:
// "     1.0E-3" in a 10-column field is read as "1.0E-" (the value runs on past the field), and
// "       9.99990000E+03" in a 20-column field leaves "3" at the start of the next field (the value
// before runs on into this one, and is itself read as 9.9999). Said only when the glued run of
// characters is a number.
// `text` is the card line being decoded: SourceMap::line_text would index lines lazily, which
// the threads of the bulk decoding must not do at once (a data race, seen as a crash).
std::string run_on_note(std::string_view text, const grammar::Span& at, std::string_view token) {
    if (!at.valid() || at.column < 1 || at.end_column <= at.column) return {};
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
    auto glued = [](char c) { return c != ' ' && c != '\t' && c != ','; };
    const std::size_t begin = at.column - 1, end = at.end_column - 1;  // 0-based [begin, end)
    if (end < text.size() && end > 0 && glued(text[end]) && glued(text[end - 1])) {
        std::size_t stop = end;
        while (stop < text.size() && glued(text[stop])) ++stop;
        const std::string whole = std::string(token) + std::string(text.substr(end, stop - end));
        if (grammar::parse_real(whole).status == NumberStatus::Ok)
            return fmt::format("'{}' runs on past column {}, so the field holds only '{}'", whole, end, token);
    }
    if (begin > 0 && begin < text.size() && glued(text[begin - 1]) && glued(text[begin])) {
        std::size_t from = begin, stop = begin;
        while (from > 0 && glued(text[from - 1])) --from;
        while (stop < text.size() && glued(text[stop])) ++stop;
        const std::string whole(text.substr(from, stop - from));
        if (grammar::parse_real(whole).status == NumberStatus::Ok)
            return fmt::format(
                "'{}' of the field before runs on into this one at column {}: the field before "
                "holds only '{}'",
                whole, begin + 1, text.substr(from, begin - from));
    }
    return {};
}
}  // namespace

bool exceeds_integer_range(double number) { return !(std::fabs(number) <= max_exact_integer); }

std::string integer_range_message(std::string_view field, double number) {
    return fmt::format("{} = {} is too large for an integer field (at most {} in magnitude)", field,
                       number_text(number), static_cast<long long>(max_exact_integer));
}

namespace {
// Whether a field's value is checked against choices or bounds (DK007): decode() and the plain path's layout.
bool checks_range(const keywords::FieldSpec& f) { return !f.choices.empty() || f.min || f.max; }
}  // namespace

void CardDecoder::report(const char* code, diag::Severity s, std::string message, grammar::Span span) {
    out_.push_back(diag::Diagnostic{code, s, std::move(message), span, {}});
}

namespace {

// What a card's layout is worked out from, to tell that the card at a cached address is still the same.
struct LayoutSource {
    std::uint16_t column = 0, width = 0;
    FieldType type = FieldType::Unused;
    // What CardLayout::plain_fields keep of the field besides its place.
    bool required = false, zero_is_default = false, checks_range = false;
    std::optional<double> default_value;
    bool operator==(const LayoutSource&) const = default;
};

LayoutSource source_of(const keywords::FieldSpec& f) {
    return {f.column, f.width, f.type, f.required, f.zero_is_default, checks_range(f), f.default_value};
}

struct CachedLayout {
    CardLayout layout;
    std::vector<LayoutSource> fields;
    std::uint16_t line_width = 0;
};

bool same_card(const CachedLayout& cached, const keywords::CardSpec& card) {
    return cached.line_width == card.line_width &&
           std::equal(cached.fields.begin(), cached.fields.end(), card.fields.begin(), card.fields.end(),
                      [](const LayoutSource& s, const keywords::FieldSpec& f) { return s == source_of(f); }) &&
           cached.layout.title_card ==
               (cached.layout.text_card && card.fields.size() == 1 && keywords::is_title_field(card.fields[0].name));
}

void lay_out(const keywords::CardSpec& card, grammar::CardFormat format, CachedLayout& c) {
    CardLayout& l = c.layout;
    l.positions = keywords::layout(card, format);
    l.types = grammar::field_types(card);
    l.significant = keywords::significant_width(card, format);
    // A card that starts with a long text field (title, heading) is never in free format.
    l.text_card = !card.fields.empty() && card.fields[0].type == FieldType::Text && card.fields[0].width >= 70;
    l.title_card = l.text_card && card.fields.size() == 1 && keywords::is_title_field(card.fields[0].name);
    l.plain = format == grammar::CardFormat::Standard &&
              std::all_of(card.fields.begin(), card.fields.end(), [](const keywords::FieldSpec& f) {
                  return f.type == FieldType::Integer || f.type == FieldType::Real || f.type == FieldType::Label ||
                         f.type == FieldType::Unused;
              });
    l.plain_fields.clear();
    l.fields_end = 0;
    l.contiguous = l.plain;
    if (l.plain)
        for (std::size_t i = 0; i < card.fields.size(); ++i) {
            const keywords::FieldSpec& f = card.fields[i];
            const grammar::FixedField& at = l.positions[i];
            l.contiguous = l.contiguous && at.start == l.fields_end;
            l.fields_end = std::max(l.fields_end, at.start + at.width);
            l.plain_fields.push_back({.start = at.start,
                                      .width = at.width,
                                      .real = f.type == FieldType::Real,
                                      .unused = f.type == FieldType::Unused,
                                      .required = f.required,
                                      .has_default = f.default_value.has_value(),
                                      .zero_is_default = f.zero_is_default,
                                      .checks_range = checks_range(f),
                                      .default_value = f.default_value.value_or(0.0)});
        }
    c.fields.clear();
    for (const keywords::FieldSpec& f : card.fields) c.fields.push_back(source_of(f));
    c.line_width = card.line_width;
}

}  // namespace

const CardLayout& card_layout(const keywords::CardSpec& card, grammar::CardFormat format) {
    // Node-based: an entry never moves. It is replaced only when another card took a dropped card's address.
    thread_local std::map<std::pair<std::uintptr_t, grammar::CardFormat>, CachedLayout> cache;
    auto [it, added] = cache.try_emplace({reinterpret_cast<std::uintptr_t>(&card), format});
    if (added || !same_card(it->second, card)) lay_out(card, format, it->second);
    return it->second.layout;
}

const CardLayout& CardDecoder::find_layout(const keywords::CardSpec& card, grammar::CardFormat format) {
    for (const Layout& l : layouts_)
        if (l.card == &card && l.format == format) {
            last_layout_ = static_cast<std::size_t>(&l - layouts_.data());
            return *l.layout;
        }
    layouts_.push_back({&card, format, &card_layout(card, format)});
    last_layout_ = layouts_.size() - 1;
    return *layouts_.back().layout;
}

void CardDecoder::decode(const grammar::Block& block, const grammar::CardLine& line, const keywords::CardSpec& card,
                         std::vector<FieldValue>& values) {
    decode_text(block, line, deck_.text(line), card, values);
}

void CardDecoder::decode_text(const grammar::Block& block, const grammar::CardLine& line, std::string_view text,
                              const keywords::CardSpec& card, std::vector<FieldValue>& values) {
    const std::size_t first_finding = out_.size();
    const CardLayout& layout = layout_of(card, block.format);
    const auto& positions_ = layout.positions;
    line_text_ = text;
    grammar::CutReport cut =
        grammar::cut_fields(text, line, positions_, layout.significant, fields_, !layout.text_card);
    glued_ = !cut.free_format && !layout.text_card && grammar::may_straddle(text, positions_);
    const std::size_t fields_end = positions_.empty() ? 0 : positions_.back().start + positions_.back().width;
    past_fields_ =
        !cut.free_format && !layout.text_card && layout.significant > fields_end && text.size() > fields_end &&
        text.substr(fields_end, layout.significant - fields_end).find_first_not_of(" \r") != std::string_view::npos;

    if (cut.has_tab) {
        std::size_t tab = text.find('\t');
        report("DK016", diag::Severity::Warning, "tab in a fixed-format card: columns become ambiguous",
               grammar::Span{line.file, line.line, static_cast<std::uint32_t>(tab + 1),
                             static_cast<std::uint32_t>(tab + 2)});
        if (auto expanded = grammar::expand_tabs_if_certain(text, positions_))
            out_.back().fixes.push_back(
                {"replace the tabs by the blanks an editor shows (tab stops every 8 columns)",
                 true,
                 {{grammar::Span{line.file, line.line, 1, static_cast<std::uint32_t>(text.size() + 1)},
                   std::move(*expanded)}}});
    }
    // A title or heading longer than its 80 (70) columns is cut in the solver's output and loses
    // nothing else: no value can slip out of a card that holds one text field. A file name (*INCLUDE)
    // is no title: cut, it names another file.
    if (cut.beyond.valid() && cut.extra_values == 0 && !layout.title_card) {
        report("DK006", diag::Severity::Warning,
               fmt::format("text past column {} is ignored by the solver", layout.significant), cut.beyond);
    }
    if (cut.extra_values > 0) {
        report("DK006", diag::Severity::Warning,
               fmt::format("{} value(s) beyond the card's {} fields are ignored", cut.extra_values, card.fields.size()),
               cut.beyond);
    }
    for (std::uint32_t i : cut.too_long) {
        // A number field holding no number is DK003, which names the value: one finding per field.
        const grammar::ValueToken token = grammar::classify_value(fields_[i].text);
        const FieldType type = card.fields[i].type;
        if (token.shape == grammar::ValueShape::Other && (type == FieldType::Integer || type == FieldType::Real))
            continue;
        report("DK005", diag::Severity::Error,
               fmt::format("free-format value '{}' is longer than its {}-column field {}", shown_value(token.text),
                           positions_[i].width, card.fields[i].name),
               fields_[i].span);
    }

    values.resize(card.fields.size());
    for (std::size_t i = 0; i < card.fields.size(); ++i) {
        const keywords::FieldSpec& spec = card.fields[i];
        FieldValue& v = values[i];
        // Member by member: a whole-struct reset compiled to a memset call per field (about 1% of
        // a big deck's check under callgrind).
        v.spec = &spec;
        v.span = fields_[i].span;
        v.valid = false;
        v.number = 0.0;
        grammar::ValueToken token =
            grammar::classify_value(fields_[i].text, spec.type == FieldType::Real ? grammar::ValueShape::Real
                                                                                  : grammar::ValueShape::Integer);
        v.text = token.text;
        v.explicit_value = token.shape != grammar::ValueShape::Blank;
        if (v.explicit_value && token.offset > 0 && !cut.free_format) {
            // Underline the value itself, not the blanks around it.
            v.span.column += static_cast<std::uint32_t>(token.offset);
            v.span.end_column = v.span.column + static_cast<std::uint32_t>(token.text.size());
        }
        switch (spec.type) {
            case FieldType::Unused: break;
            case FieldType::Text: check_text(block, spec, v); break;
            case FieldType::Label:
                // An id: a number, or since 971 R7.1 an alphanumeric label (lsdyna-format.md §10).
                if (token.shape == grammar::ValueShape::Other) {
                    v.valid = true;
                    break;
                }
                [[fallthrough]];
            case FieldType::Integer:
            case FieldType::Real:
                decode_number(block, spec, token, fields_[i], cut.free_format ? 0 : positions_[i].width, v);
                break;
        }
    }
    if (cut.free_format) check_decimal_comma(card, line, values, positions_, first_finding);
    if (out_.size() > first_finding) offer_realign(card, block.format, line, first_finding);
}

// A value that strays over its field's boundary is cut into text that is no number (DK002, DK003):
// the line with every value moved into the field holding most of its characters is their safe fix,
// offered only when that is certain (grammar/realign.hpp).
void CardDecoder::offer_realign(const keywords::CardSpec& card, grammar::CardFormat format,
                                const grammar::CardLine& line, std::size_t first_finding) {
    std::optional<std::optional<std::string>> realigned;
    for (std::size_t i = first_finding; i < out_.size(); ++i) {
        diag::Diagnostic& d = out_[i];
        if ((d.code != "DK002" && d.code != "DK003") || d.span.line != line.line || d.span.file != line.file) continue;
        if (!realigned) realigned = grammar::realign_card(line_text_, card, format);
        if (!*realigned) return;
        d.fixes.push_back({"move the values of the line into their fields",
                           true,
                           {text::whole_line_edit(line.file, line.line, line_text_.size(), **realigned)}});
    }
}

// `     0,002` for `     0.002`: a comma makes the whole line free format (LS-DYNA reads ENDTIM 0 and
// ENDCYC 2). Said when a comma sits between two digits and the line starts with the blanks of a
// fixed-format field (a free-format line is written from its first column, or with a blank after
// each comma). Runs on free-format lines only.
void CardDecoder::check_decimal_comma(const keywords::CardSpec& card, const grammar::CardLine& line,
                                      const std::vector<FieldValue>& values,
                                      std::span<const grammar::FixedField> positions, std::size_t first_finding) {
    const auto comma = find_decimal_comma(line_text_, positions);
    if (!comma) return;
    std::string reading;
    std::size_t shown_fields = 0;
    for (std::size_t i = 0; i < values.size() && i < card.fields.size() && shown_fields < 4; ++i) {
        const FieldValue& v = values[i];
        if (!v.explicit_value || card.fields[i].type == FieldType::Unused) continue;
        const grammar::RealValue r = grammar::parse_real(v.text);
        reading += fmt::format("{}{} {}", reading.empty() ? "" : ", ", card.fields[i].name,
                               r.status == NumberStatus::Ok ? number_text(r.value) : shown_value(v.text));
        ++shown_fields;
    }
    report_decimal_comma(*comma, line, "LS-DYNA", reading, out_, first_finding);
}

void CardDecoder::decode_number(const grammar::Block& block, const keywords::FieldSpec& spec,
                                const grammar::ValueToken& token, const grammar::Field& field,
                                std::uint32_t fixed_width, FieldValue& v) {
    const bool integer = spec.type != FieldType::Real;
    if (token.shape == grammar::ValueShape::Blank) {
        if (spec.default_value) {
            v.number = *spec.default_value;
            v.valid = true;
        } else if (spec.required) {
            report("DK008", diag::Severity::Error, fmt::format("{} is required and has no default", spec.name), v.span);
        }
        return;
    }
    if (token.shape == grammar::ValueShape::Parameter) {
        auto found = deck_.parameters.find(token.name, v.span.file, block.parameter_epoch);
        if (!found.parameter) {
            out_.push_back(
                grammar::undefined_parameter(deck_.parameters,
                                             grammar::reference_in_field(token, field.text, field.span, fixed_width),
                                             v.span, v.span.file, block.parameter_epoch));
            return;
        }
        // A reference differing from its definition only by case resolves silently: LS-DYNA reads
        // names case-insensitively (an R13.1.1 run resolved &TEnd to tEnd without a word).
        using grammar::ParameterType;
        if (found.parameter->type == ParameterType::Character && spec.type == FieldType::Label) {
            // A label field takes a character parameter: its text is the label (or the number) named.
            v.text = found.parameter->text;  // the deck's parameter table outlives the decoding
            const grammar::ValueToken label = grammar::classify_value(v.text);
            const grammar::IntegerValue n = grammar::to_integer(label);
            if (label.shape == grammar::ValueShape::Integer && n.status == NumberStatus::Ok)
                v.number = static_cast<double>(n.value);
            v.valid = true;
            return;
        }
        if (found.parameter->type == ParameterType::Character ||
            (integer && found.parameter->type == ParameterType::Real)) {
            report("DK013", diag::Severity::Error,
                   fmt::format("{} parameter '{}' used in {} field {}",
                               found.parameter->type == ParameterType::Character ? "character" : "real",
                               found.parameter->name, integer ? "integer" : "real", spec.name),
                   v.span);
            return;
        }
        v.number = token.negated ? -found.parameter->number : found.parameter->number;
        v.valid = true;
    } else if (integer) {
        grammar::IntegerValue n = grammar::to_integer(token);
        if (n.status == NumberStatus::Ok) {
            if (n.written_as_real)
                report("DK004", diag::Severity::Warning,
                       fmt::format("integer field {} written as real '{}'; read as {}", spec.name,
                                   shown_value(token.text), n.value),
                       v.span);
            v.number = static_cast<double>(n.value);
            v.valid = true;
        } else {
            report("DK002", diag::Severity::Error,
                   fmt::format("'{}' in integer field {} is not an integer", shown_value(token.text), spec.name),
                   v.span);
            if (auto note = run_on_note(line_text_, v.span, token.text); !note.empty())
                out_.back().notes.push_back({grammar::Span{}, std::move(note)});
            return;
        }
    } else {
        grammar::RealValue r = grammar::to_real(token);
        if (r.status != NumberStatus::Ok) {
            report("DK003", diag::Severity::Error,
                   fmt::format("'{}' in {} field {} is not a number", shown_value(token.text),
                               spec.pydyna_integer ? "integer" : "real", spec.name),
                   v.span);
            if (auto note = run_on_note(line_text_, v.span, token.text); !note.empty())
                out_.back().notes.push_back({grammar::Span{}, std::move(note)});
            return;
        }
        v.number = r.value;
        v.valid = true;
    }
    if (integer && exceeds_integer_range(v.number)) {
        report("DK007", diag::Severity::Error, integer_range_message(spec.name, v.number), v.span);
        v.valid = false;
        return;
    }
    if (v.number == 0.0 && spec.zero_is_default && spec.default_value) {
        v.number = *spec.default_value;  // the manual maps an explicit 0 to the default here
        return;
    }
    if (checks_range(spec)) check_range(spec, v);
}

void CardDecoder::check_text(const grammar::Block& block, const keywords::FieldSpec& spec, FieldValue& v) {
    v.valid = true;
    if (!v.explicit_value) {
        if (spec.required)
            report("DK008", diag::Severity::Error, fmt::format("{} is required and has no default", spec.name), v.span);
        return;
    }
    if (spec.text_choices.empty()) return;
    // A parameter may stand in any field: a character parameter's text is the word chosen; another
    // &name (a number, or a name sphdeck cannot resolve) is not judged against the words.
    std::string_view text = v.text;
    if (const grammar::ValueToken token = grammar::classify_value(v.text);
        token.shape == grammar::ValueShape::Parameter) {
        auto found = deck_.parameters.find(token.name, v.span.file, block.parameter_epoch);
        if (!found.parameter || found.parameter->type != grammar::ParameterType::Character) return;
        text = found.parameter->text;
    }
    for (std::string_view choice : spec.text_choices)
        if (choice.size() == text.size() && std::equal(choice.begin(), choice.end(), text.begin(), [](char a, char b) {
                return std::toupper(static_cast<unsigned char>(a)) == std::toupper(static_cast<unsigned char>(b));
            }))
            return;
    std::string allowed;
    for (std::string_view c : spec.text_choices) allowed += (allowed.empty() ? "" : ", ") + std::string(c);
    report("DK007", diag::Severity::Error,
           fmt::format("{} = '{}' is not one of {}", spec.name, shown_value(text), allowed), v.span);
}

void CardDecoder::check_range(const keywords::FieldSpec& spec, const FieldValue& v) {
    if (!spec.choices.empty()) {
        // Out of range for an integer is simply not one of the choices (no conversion: issue 32).
        const std::optional<long long> as_integer = grammar::checked_integer<long long>(v.number);
        if (v.number != std::trunc(v.number) || !as_integer || !spec.choice(*as_integer)) {
            std::string allowed;
            for (const auto& c : spec.choices) allowed += (allowed.empty() ? "" : ", ") + std::to_string(c.value);
            report("DK007", diag::Severity::Error,
                   fmt::format("{} = {} is not one of {}", spec.name, number_text(v.number), allowed), v.span);
        }
        return;
    }
    if ((spec.min && v.number < *spec.min) || (spec.max && v.number > *spec.max)) {
        report("DK007", diag::Severity::Error,
               fmt::format("{} = {} is outside [{}, {}]", spec.name, number_text(v.number),
                           spec.min ? number_text(*spec.min) : "-inf", spec.max ? number_text(*spec.max) : "inf"),
               v.span);
    }
}

}  // namespace sphdeck::model
