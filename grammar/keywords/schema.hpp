// Card schemas as data: per keyword its cards, per field its columns, type, default and range.
// These tables drive decoding, validation, `sphdeck keyword` and (later) editor hovers, so a
// field's width or default is written exactly once, here.
//
// Every member has a default member initializer so the tables can use C++20 designated
// initializers and leave out what does not apply without -Wmissing-field-initializers noise.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/fields.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::keywords {

enum class FieldType : std::uint8_t {
    Integer,  // I
    Real,     // F
    Text,     // A
    Label,    // I/A: an id that may also be an alphanumeric label (971 R7.1+)
    Unused,   // columns the manual leaves unused: kept so long/I10 offsets stay right
};

std::string_view to_string(FieldType t);  // "I", "F", "A", "I/A", "-"

struct EnumChoice {
    long long value = 0;
    std::string_view meaning = {};
    std::string_view since = {};  // edition that introduced the value ("R11.1"); empty: always / unknown
};

struct FieldSpec {
    std::string_view name = {};  // as in the manual
    std::uint16_t column = 1;    // 1-based first column, standard format
    std::uint16_t width = 10;    // standard format
    FieldType type = FieldType::Integer;
    std::optional<double> default_value = {};    // nullopt: no default
    bool zero_is_default = false;                // an explicit 0 means "use the default"
    bool required = false;                       // blank is an error (DK008)
    std::vector<EnumChoice> choices = {};        // empty: any value (subject to min/max)
    std::optional<double> min = {}, max = {};    // inclusive range
    std::string_view doc = {};                   // one line
    std::vector<std::string_view> aliases = {};  // other names of the field (MEMORY: "NMNEIGH")
    std::string_view since = {};                 // edition that introduced the field; empty: always / unknown
    // For Text fields: the default text ("MECH"; default_value stays empty) and the allowed
    // words (case-insensitive; empty: any text).
    std::string_view default_text = {};
    std::vector<std::string_view> text_choices = {};
    // Generated layouts: what the id in this field names ("PART", "SET_NODE", "DEFINE_CURVE"),
    // from pydyna's links (integer fields only); empty: not an id, or not known. Followed by the REF
    // rules (model/id_links.hpp).
    std::string_view refers_to = {};
    // Generated layouts: an integer in pydyna's layout, checked as a number only (type Real; pydyna
    // types some manual F fields int). Findings still call it an integer field.
    bool pydyna_integer = false;

    bool is_named(std::string_view n) const;      // name or alias, case-insensitive
    const EnumChoice* choice(long long v) const;  // nullptr when v is not one of the choices
};

// Whether a field of this name (any case) is a title or heading: text naming its entity (a part's HEADING,
// a _TITLE option's TITLE), never a value. The card decoder keeps its tail, the editor shows it as the
// entity's name, `sphdeck diff` names blocks by their ids instead.
bool is_title_field(std::string_view field_name);

// The title lines before a keyword's first card as written: 1 when its name carries the _TITLE option,
// else 0. For readers of a block's raw lines (the first id of a definition) that decode no cards.
std::size_t title_lines(std::string_view keyword);

// How often a card occurs in its block.
enum class CardRepeat : std::uint8_t {
    Once,      // exactly one line, mandatory
    Optional,  // one line that may be omitted (only trailing cards)
    Repeated,  // one line per item until the next keyword (nodes, particles, set ids)
};

std::string_view to_string(CardRepeat r);  // "once", "optional", "repeated"

// A comparison of a field value of an earlier card of the same block (lsdyna-format.md §12).
enum class Compare : std::uint8_t { Less, LessEqual, Equal, NotEqual, GreaterEqual, Greater };

std::string_view to_string(Compare c);  // "<", "<=", "==", "!=", ">=", ">"

// A card that is read only when the condition holds: *MAT_ELASTIC card 1.1 when E < 0.
// A blank field compares through its default (0 when it has none).
struct CardCondition {
    std::string_view field = {};  // name of a field of an earlier card of the block
    Compare compare = Compare::Equal;
    double value = 0.0;
    std::vector<double> any_of = {};  // non-empty: holds when the value is one of these (compare unused)
    // Generated layouts only: conditions naming several fields (pydyna's "abs(self.dof) in [9, 10, 11]
    // or self.vad == 4"). The whole holds when this test and every `all_of` hold, or any `or_else` holds.
    std::vector<CardCondition> all_of = {};
    std::vector<CardCondition> or_else = {};

    bool holds(double field_value) const;  // this test alone, on `field`'s value
    // The whole condition; `value_of(name)` gives a field's value as read (0 when not read).
    template <typename ValueOf>
    bool holds_with(const ValueOf& value_of) const {
        bool all = holds(value_of(field));
        for (const CardCondition& c : all_of) all = all && c.holds_with(value_of);
        if (all) return true;
        for (const CardCondition& c : or_else)
            if (c.holds_with(value_of)) return true;
        return false;
    }
};

struct CardSpec {
    std::string_view name = {};  // "Card 1", "Card 2", "Title"...
    std::vector<FieldSpec> fields = {};
    CardRepeat repeat = CardRepeat::Once;
    std::optional<CardCondition> present_if = {};  // nullopt: always present
    std::uint16_t line_width = 80;                 // significant columns in standard format
    std::string_view since = {};                   // edition that introduced the card
    std::string_view doc = {};
    // Generated layouts only: from this card on the layout is not known (an undecidable condition,
    // a count read from values), so the rest of the block is not checked and nothing is reported.
    bool unknown_layout = false;

    const FieldSpec* field(std::string_view name) const;  // by name or alias, case-insensitive
};

// What a keyword option (a `_`-joined suffix of the keyword name, lsdyna-format.md §11) does.
struct OptionSpec {
    std::string_view suffix = {};                // without '_': "TITLE", "ELLIPSE"
    std::vector<std::string_view> aliases = {};  // old spellings: "TENSOR" for ELLIPSE
    std::vector<CardSpec> cards_before = {};     // read before the base cards (title, id card)
    std::vector<CardSpec> cards_after = {};      // read after the base cards
    // Number of trailing base cards that cards_after replace: *SET_NODE_LIST_GENERATE reads
    // ranges instead of the id list.
    std::uint8_t replaces_last = 0;
    std::string_view doc = {};  // what the option changes, also when it adds no card (_VOLUME)

    bool is_named(std::string_view s) const;  // suffix or alias, case-insensitive
};

struct KeywordSchema {
    std::string_view name = {};                  // canonical, upper case with '*': "*CONTROL_SPH"
    std::vector<std::string_view> aliases = {};  // "*MAT_009", "*CONTROL_TIME_STEP"
    std::vector<CardSpec> cards = {};
    bool unique = false;  // may appear once per deck (DK018)
    std::string_view doc = {};
    std::vector<OptionSpec> options = {};
    // > 0: the last `repeat_group` base cards repeat together, in order, until the next keyword
    // (*PART: heading card + data card per part). Cards inside the group are marked Once.
    std::uint8_t repeat_group = 0;
    bool free_text = false;  // data lines are free text, never split into fields (*COMMENT)
    // From the table generated from pydyna's layouts (grammar/keywords/generated/), not hand-written:
    // its cards are cut and type-checked, but it is not read into the model.
    bool generated = false;

    const OptionSpec* option(std::string_view suffix) const;  // suffix or alias
};

// Field widths in a given format (lsdyna-format.md §6): I10 widens fields narrower than 10
// to 10, long widens fields narrower than 20 to 20; offsets are recomputed cumulatively and a
// gap between two fields widens like an unused field of the same width would. In long format a
// trailing text field of 70 or more columns that ends at column 80 (a title, file name, path or
// expression) runs to column 160 ("A80 name, path and expression fields may be 160").
// The format rules live in grammar/fields.hpp; a slot is a widened FixedField.
using FieldSlot = grammar::FixedField;
std::vector<FieldSlot> layout(const CardSpec& card, grammar::CardFormat format);

// The columns to write a value in (the formatter, a fix that rewrites a line): the layout, except that a
// field whose width the sources dispute is narrowed to the width every reader takes. *ELEMENT_SPH's NEND is
// read in columns 33-42 (pydyna, LS-PrePost) but the manual's I8 ends it at 40 (DK023): a number
// right-aligned to column 42 would read as another one there.
std::vector<FieldSlot> layout_to_write(std::string_view keyword, const CardSpec& card, grammar::CardFormat format);

// Last significant column of a card in a format: the card's line width (80) in standard format;
// in I10 format at least the end of the widened layout (10 fields of 10 reach 100); in long
// format at least 160, more when the widened layout ends later (10 fields of 20 reach 200).
std::uint32_t significant_width(const CardSpec& card, grammar::CardFormat format);

// ---- Lookup ---------------------------------------------------------------------------------

// A keyword name as written, split into its schema and options.
struct KeywordMatch {
    const KeywordSchema* schema = nullptr;
    std::vector<const OptionSpec*> options;  // in the order written
    // Suffix tokens that are not options of the schema, as views into the name passed to
    // find_keyword. A match with unknown options is usually a different keyword that the tables
    // do not know (*CONTROL_SPH_INCOMPRESSIBLE): callers should treat it as unknown (DK001).
    std::vector<std::string_view> unknown_options;

    bool has(std::string_view suffix) const;  // option given (suffix or alias)
};

// Case-insensitive, with or without the leading '*', surrounding blanks and a trailing format
// suffix ('+', '-', '%') ignored. Resolves aliases (*MAT_009, *CONTROL_TIME_STEP, *SET_NODE) and
// tries the longest base name first, so *DEFINE_BOX_SPH is its own keyword, while
// *SECTION_SPH_ELLIPSE_TITLE is *SECTION_SPH + ELLIPSE + TITLE. nullopt: no base name matches.
std::optional<KeywordMatch> find_keyword(std::string_view full_name);

// Every schema, in table order (grouped by family).
std::span<const KeywordSchema> all_keywords();

// Up to `max` known keyword names (canonical or alias spelling, hand-written or generated, with or
// without one option) closest to `name` by typing distance (grammar/similar_names.hpp), one per
// keyword, best first, for "did you mean". Empty when nothing is close.
std::vector<std::string_view> similar_keywords(std::string_view name, std::size_t max = 3);

// The known keyword `name` most likely stands for, upper case with '*': the author's option tokens are
// kept when the typo is in the base name (*SECTON_SPH_TITLE -> *SECTION_SPH_TITLE), and the
// suggestion is always a name the tables know as a whole. nullopt when nothing is close.
std::optional<std::string> suggest_keyword(std::string_view name);

// `suggestion` written as the author wrote `written_name`: all lower case stays lower case.
std::string keyword_replacement(std::string_view written_name, std::string_view suggestion);

// LS-DYNA keywords without a layout in either table (grammar/keywords/known_without_layout.cpp, with
// the manual's word for each): real, so never unknown; their cards are not checked. Sorted.
std::span<const std::string_view> known_without_layout();
bool is_known_without_layout(std::string_view upper_name);

// The card sequence of a matched keyword in reading order: option cards_before (title, id),
// then the base cards (less those an option replaces), then option cards_after.
std::vector<const CardSpec*> cards_for(const KeywordMatch& match);

// How many cards at the end of cards_for(match) repeat as a group until the next keyword: the
// schema's repeat_group plus the cards_after of its options (they join the group); 0: none.
std::size_t repeat_group_size(const KeywordMatch& match);

}  // namespace sphdeck::keywords
