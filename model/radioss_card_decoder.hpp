// Decodes one Radioss card line (radioss-format.md §2): fixed cells of the deck's version, or
// comma-separated free format; engine lines list-directed (blanks or commas). Values typed with
// the shared value grammar; problems become diagnostics at the field (DK002-DK006, DK016,
// RAD025 for two numbers glued in one fixed cell).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/radioss/cards.hpp"
#include "grammar/raw_deck.hpp"
#include "model/radioss_lone_shifts.hpp"

namespace sphdeck::model {

class RadiossParameters;  // model/radioss_parameters.hpp

struct RadiossValue {
    const grammar::radioss::FieldSpec* spec = nullptr;
    grammar::Span span;           // the cell (the value itself when written)
    std::string_view text;        // trimmed text as written
    bool explicit_value = false;  // not blank
    bool valid = false;           // a number was read (Int, Real), or text (Text, Line)
    double number = 0.0;          // 0 when blank or invalid
};

class RadiossCardDecoder {
public:
    RadiossCardDecoder(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out) : deck_(deck), out_(out) {}

    // The deck's /PARAMETER table, for references in numeric cells (`[name]`, `&name`); without
    // it references stay unknown and unreported. `block` (index into RawDeck::blocks) is where
    // the lines being decoded stand: only parameters defined before it have a value there.
    void set_parameters(const RadiossParameters* parameters) { parameters_ = parameters; }
    void set_block(std::size_t block) { block_ = block; }
    // The next lines are cards of a generated layout read once: under a `#` comment line (the
    // field names of the CFG's COMMENT), a line is looked at for a shift even without a finding.

    // Decodes `line` against `card`. `version` sets the cell widths; `list_directed` reads engine
    // lines (tokens separated by blanks or commas); `newer` names a newer format that reads more
    // fields, for the message when text follows the last field; `trailing_checked` false reads
    // such text silently (KeywordSpec::trailing_checked).
    // `quiet_until` > 0: text between the card's last field and that column is read silently (a
    // generated layout's older format, which often ends before columns decks of its version fill).
    void decode(const grammar::CardLine& line, const grammar::radioss::CardSpec& card, int version, bool list_directed,
                std::vector<RadiossValue>& values, std::string_view newer = {}, bool trailing_checked = true,
                std::uint32_t quiet_until = 0);

    // The same for `text` read as a fixed-format line standing on `line` (the spans name it): a line the deck may
    // have meant, for a diagnosis that tries a mend (model/radioss_joined_title.hpp).
    void decode_text(const grammar::CardLine& line, std::string_view text, const grammar::radioss::CardSpec& card,
                     int version, std::vector<RadiossValue>& values);

    // DK029 for lines whose integers were all pushed into the next cells (model/radioss_lone_shifts.hpp):
    // decided once the whole deck is read.
    void report_lone_shifts() { lone_shifts_.report(out_); }

private:
    void decode_fixed(const grammar::CardLine& line, const grammar::radioss::CardSpec& card, int version,
                      std::vector<RadiossValue>& values, std::string_view newer, bool trailing_checked,
                      std::uint32_t quiet_until);
    void decode_tokens(const grammar::CardLine& line, const grammar::radioss::CardSpec& card,
                       std::vector<RadiossValue>& values);
    void read_value(RadiossValue& v, std::string_view field, bool fixed);
    void check_decimal_comma(const grammar::CardLine& line, std::string_view text,
                             const std::vector<RadiossValue>& values, std::span<const grammar::FixedField> positions,
                             std::size_t first_finding);
    void report(const char* code, diag::Severity s, std::string message, grammar::Span span);

    // Column positions of a card in a version, computed once: decoding runs per line.
    const std::vector<grammar::FixedField>& layout_of(const grammar::radioss::CardSpec& card, int version);

    const grammar::RawDeck& deck_;
    std::vector<diag::Diagnostic>& out_;
    const RadiossParameters* parameters_ = nullptr;
    std::size_t block_ = 0;
    std::optional<std::string_view> text_override_;  // decode_text's line
    RadiossLoneShifts lone_shifts_;
    std::vector<grammar::Field> fields_;
    struct Layout {
        const grammar::radioss::CardSpec* card = nullptr;
        int version = 0;
        std::vector<grammar::FixedField> positions;
    };
    std::vector<Layout> layouts_;
    std::size_t last_layout_ = 0;
};

// The columns of field `field` on card line `line` as the decoder cut it (fixed or free).
grammar::Span radioss_field_span(const grammar::RawDeck& deck, std::uint32_t line,
                                 const grammar::radioss::CardSpec& card, int version, std::size_t field);

}  // namespace sphdeck::model
