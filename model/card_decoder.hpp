// Decodes one card line through its schema: fields cut by the format rules, values typed,
// parameters substituted, defaults applied; every problem becomes a diagnostic at the field.
#pragma once

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/fields.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"
#include "grammar/value.hpp"

namespace sphdeck::model {

struct FieldValue {
    const keywords::FieldSpec* spec = nullptr;
    grammar::Span span;
    std::string_view text;        // trimmed text as written (the parameter reference for &name)
    bool explicit_value = false;  // written in the deck (not blank)
    bool valid = false;           // decoded to a value (explicit or default)
    double number = 0.0;          // I and F fields, after defaults and zero-means-default
};

// The numbers of a plain line as decode_plain reads them, without the spans and texts (CardDecoder::read_row):
// for the bulk walk, whose model takes numbers only.
struct PlainRow {
    static constexpr std::size_t max_fields = 8;
    double number[max_fields] = {};
    std::uint32_t count = 0;    // fields of the card
    std::uint32_t valid = 0;    // bit i: FieldValue::valid of field i
    std::uint32_t written = 0;  // bit i: FieldValue::explicit_value of field i
    bool is_valid(std::size_t i) const { return (valid >> i) & 1u; }
    bool is_written(std::size_t i) const { return (written >> i) & 1u; }
};

// The value a card condition compares (CardCondition::holds_with): the number read or defaulted,
// 0 for a blank field without default, NaN (equal to nothing) for a value that is not a number.
inline double condition_value(const FieldValue& v) {
    if (v.valid) return v.number;
    return v.explicit_value ? std::numeric_limits<double>::quiet_NaN() : 0.0;
}

// The largest integer an integer field may hold: the model keeps numbers as doubles and ids as
// long long, and beyond 2^53 neither holds the value exactly; converting a larger double (or NaN)
// to an integer is undefined. Both decoders report larger values (DK007) and leave them unused.
inline constexpr double max_exact_integer = 9007199254740992.0;  // 2^53
bool exceeds_integer_range(double number);                       // |number| > 2^53, or NaN
std::string integer_range_message(std::string_view field, double number);

// What decode_plain needs of one field, read once per card instead of from its FieldSpec on every line.
struct PlainField {
    std::uint32_t start = 0, width = 0;  // its columns (0-based)
    bool real = false;                   // F (else I or I/A, read as integers), when not unused
    bool unused = false;
    bool required = false;
    bool has_default = false;
    bool zero_is_default = false;  // with has_default
    bool checks_range = false;     // choices, min or max
    double default_value = 0.0;
};

// A card's widened columns in a format and what the decoders ask of them. A layout is a fact of the keyword
// tables, not of a deck: worked out once per thread and kept across decks (the fuzzer, the editor and a check of
// many decks read deck after deck through the same cards). Kept by the card's address and used only while the
// card there has the same fields (a card a caller made and dropped lends its layout to no other). The reference
// stays valid while the card lives.
struct CardLayout {
    std::vector<grammar::FixedField> positions;  // keywords::layout(card, format)
    std::vector<keywords::FieldType> types;      // one per field
    std::uint32_t significant = 80;              // keywords::significant_width(card, format)
    bool text_card = false;                      // starts with a long text field: never free format
    bool title_card = false;                     // a title or heading only: its tail past the last column is cosmetic
    bool plain = false;                          // standard widths and number fields only: decode_plain may take it
    std::vector<PlainField> plain_fields;        // when plain: one per field
    // When plain: the fields end at fields_end and leave no column before it between them (then a line whose
    // end is known needs no scan for ',' and '\t' before fields_end: a field holding one reads no number).
    std::uint32_t fields_end = 0;
    bool contiguous = false;
};
const CardLayout& card_layout(const keywords::CardSpec& card, grammar::CardFormat format);

class CardDecoder {
public:
    CardDecoder(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out) : deck_(deck), out_(out) {}

    // Fills `values` with one entry per field of `card` (Unused fields included, never checked).
    void decode(const grammar::Block& block, const grammar::CardLine& line, const keywords::CardSpec& card,
                std::vector<FieldValue>& values);
    // The same for `text` read as if it stood on `line` (the spans name that line): a line the deck may have
    // meant, for the diagnoses that try a mend before they name a cause (model/joined_lines.hpp).
    void decode_text(const grammar::Block& block, const grammar::CardLine& line, std::string_view text,
                     const keywords::CardSpec& card, std::vector<FieldValue>& values);

    // The bulk path of *NODE and *ELEMENT_SPH lines: a plain fixed-format line (standard widths,
    // numbers in their columns, nothing to report) is decoded straight from its columns; any
    // other line goes through decode(). `values` come out as decode() would fill them.
    // Whether the line decode() read last may hold a value pushed across a field end
    // (grammar::may_straddle): a line for the shift diagnosis although nothing was reported.
    bool glued() const { return glued_; }
    // The line decode() last read holds text between its last field and the card's last significant
    // column: read by no field, silently (a line shifted right pushes its last value there).
    bool text_past_fields() const { return past_fields_; }

    // True when the line took the plain path (its values depend on its text alone). `next`: the deck's card
    // line after `line`, when there is one (its start tells where `line` ends, without a scan).
    bool decode_bulk(const grammar::Block& block, const grammar::CardLine& line, const keywords::CardSpec& card,
                     std::vector<FieldValue>& values, const grammar::CardLine* next = nullptr) {
        if (decode_plain(block, line, card, values, next)) return true;
        decode(block, line, card, values);
        return false;
    }

    // The plain path alone, numbers only: Read when decode_bulk would take the line on its plain path, with
    // the valid, explicit_value and number of each of its FieldValues; NotPlain when it would not (decode()
    // then reads it); TooWide for a card of more fields than a PlainRow holds (decode_bulk decides).
    // `through_next`: the file's bytes from the line's start to `next`'s, when the caller holds them (read
    // through a text::TextWindow): the line is read from them rather than from the file's text.
    enum class RowRead : std::uint8_t { Read, NotPlain, TooWide };
    RowRead read_row(const grammar::Block& block, const grammar::CardLine& line, const keywords::CardSpec& card,
                     PlainRow& row, const grammar::CardLine* next = nullptr, std::string_view through_next = {});

private:
    // The text of a line the plain path may take (nothing: decode() reads it).
    std::optional<std::string_view> plain_text(const CardLayout& layout, const grammar::CardLine& line,
                                               const grammar::CardLine* next, std::string_view through_next = {});
    bool decode_plain(const grammar::Block& block, const grammar::CardLine& line, const keywords::CardSpec& card,
                      std::vector<FieldValue>& values, const grammar::CardLine* next);
    // `field`: the text the value was cut from; `fixed_width`: its width in a fixed-format line, 0 in
    // free format (a parameter name that fills a fixed field may have been cut by it).
    void decode_number(const grammar::Block& block, const keywords::FieldSpec& spec, const grammar::ValueToken& token,
                       const grammar::Field& field, std::uint32_t fixed_width, FieldValue& v);
    void check_decimal_comma(const keywords::CardSpec& card, const grammar::CardLine& line,
                             const std::vector<FieldValue>& values, std::span<const grammar::FixedField> positions,
                             std::size_t first_finding);
    void offer_realign(const keywords::CardSpec& card, grammar::CardFormat format, const grammar::CardLine& line,
                       std::size_t first_finding);
    void check_text(const grammar::Block& block, const keywords::FieldSpec& spec, FieldValue& v);
    void check_range(const keywords::FieldSpec& spec, const FieldValue& v);
    void report(const char* code, diag::Severity s, std::string message, grammar::Span span);

    std::string_view line_text_;
    bool glued_ = false;
    bool past_fields_ = false;  // the line decode() works on, for the notes that quote it

    // The layouts this decoder used (card_layout's, looked up once per card: decoding runs per line).
    struct Layout {
        const keywords::CardSpec* card = nullptr;
        grammar::CardFormat format = grammar::CardFormat::Standard;
        const CardLayout* layout = nullptr;
    };
    const CardLayout& layout_of(const keywords::CardSpec& card, grammar::CardFormat format) {
        if (!layouts_.empty() && layouts_[last_layout_].card == &card && layouts_[last_layout_].format == format)
            return *layouts_[last_layout_].layout;  // repeated cards: the same layout line after line
        return find_layout(card, format);
    }
    const CardLayout& find_layout(const keywords::CardSpec& card, grammar::CardFormat format);

    // The text of a file of the deck, looked up once for the lines of one file (a look-up a line showed).
    std::string_view file_text(text::FileId file) {
        if (!text_file_ || *text_file_ != file) text_file_ = file, file_text_ = deck_.sources.file(file).text;
        return file_text_;
    }

    const grammar::RawDeck& deck_;
    std::vector<diag::Diagnostic>& out_;
    std::optional<text::FileId> text_file_;
    std::string_view file_text_;
    std::vector<Layout> layouts_;
    std::size_t last_layout_ = 0;
    std::vector<grammar::Field> fields_;
};

}  // namespace sphdeck::model
