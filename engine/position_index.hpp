// The position index, "what is under this position": the block of a file line, the card line of a
// block, the card spec and decoded fields of that line (or, on a line typed since the last check, the
// card it would be read as), the field under a column and its columns, and the decoded card lines of
// a range of lines, for LS-DYNA and Radioss decks. Every editor feature asks here (completion,
// signature help, hover, inlay hints, semantic tokens, definition, code actions; engine/id_lookup.hpp
// for ids); nothing is indexed in advance, despite the name, so a request costs a walk of one block (a
// repeated card such as *NODE or *ELEMENT_SPH is found without walking its lines).
// position_index.cpp: blocks and card walks; position_index_card.cpp: the card and field at a
// position; position_index_range.cpp: the card lines of a range.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/keywords/schema.hpp"
#include "grammar/radioss/cards.hpp"
#include "grammar/raw_deck.hpp"
#include "model/card_decoder.hpp"
#include "model/radioss_card_decoder.hpp"

namespace sphdeck::engine {

// The block of `file` that `line` (1-based) stands in: the last block of the file whose keyword
// line is at or before `line`, when no other block of the file starts between them. nullptr
// before the file's first keyword.
const grammar::Block* block_at(const grammar::RawDeck& deck, grammar::FileId file, std::uint32_t line);

// The card line of `block` on file line `line`, or nullptr (the keyword line, a comment line).
grammar::CardLinePtr card_line_at(const grammar::RawDeck& deck, const grammar::Block& block, std::uint32_t line);

// The last line (1-based) a block covers in its file: its last card line, or the keyword line.
std::uint32_t block_last_line(const grammar::RawDeck& deck, const grammar::Block& block);

// One decoded LS-DYNA card line.
struct DynaCard {
    keywords::KeywordMatch match;
    const keywords::CardSpec* card = nullptr;
    grammar::CardLinePtr line = nullptr;
    std::vector<model::FieldValue> values;
};

// The keyword match of a block (nullopt: unknown keyword, unknown option, or a block read by
// the reader itself: *INCLUDE, *PARAMETER, *COMMENT, *END).
std::optional<keywords::KeywordMatch> decodable_match(const grammar::Block& block);

// Walks the card lines of an LS-DYNA block as the syntax pass does (model/deck_check.cpp:
// conditional, optional, repeated cards, repeat groups), calling `visit` for each decoded line
// until it returns false. Findings of the decoding are dropped (the check reported them).
using DynaCardVisitor = std::function<bool(const DynaCard&)>;
void walk_dyna_block(const grammar::RawDeck& deck, const grammar::Block& block, const DynaCardVisitor& visit);

// The decoded card of one line of an LS-DYNA block; nullopt for a line past the block's cards.
std::optional<DynaCard> dyna_card_at(const grammar::RawDeck& deck, const grammar::Block& block,
                                     grammar::CardLinePtr line);

// The card spec the next line of `block` after `before` would be read as (for completion on a
// line being typed); `before` null: the first card.
const keywords::CardSpec* dyna_card_after(const grammar::RawDeck& deck, const grammar::Block& block,
                                          grammar::CardLinePtr before);

// One decoded Radioss card line.
struct RadiossCard {
    const grammar::radioss::KeywordSpec* keyword = nullptr;
    const grammar::radioss::CardSpec* card = nullptr;  // nullptr on the title line
    bool title = false;
    int version = 0;
    bool engine = false;
    std::vector<model::RadiossValue> values;
};

// The Radioss keyword of a block (nullptr: unknown, or known and kept as is).
const grammar::radioss::KeywordSpec* radioss_keyword(const grammar::Block& block, std::size_t* prefix = nullptr);

// Whether the block stands in an engine deck (_0001.rad) rather than a starter deck.
bool radioss_engine_block(const grammar::RawDeck& deck, const grammar::Block& block);

// The card of one line of a Radioss block, as model/radioss_decoder.cpp reads it: the title
// line after the header, then the format's cards (a trailing repeated group cycles).
std::optional<RadiossCard> radioss_card_at(const grammar::RawDeck& deck, const grammar::Block& block,
                                           grammar::CardLinePtr line, int version);

// Walks every card line of a Radioss block (not the title line), as radioss_card_at reads them,
// until `visit` returns false.
using RadiossCardVisitor = std::function<bool(grammar::CardLinePtr, const RadiossCard&)>;
void walk_radioss_block(const grammar::RawDeck& deck, const grammar::Block& block, int version,
                        const RadiossCardVisitor& visit);

// The file an include line of `file` opened (an *INCLUDE file name line, a Radioss #include
// line), or nullopt.
std::optional<grammar::FileId> included_file(const grammar::SourceMap& sources, grammar::FileId file,
                                             std::uint32_t line);

// A `&name` parameter reference (LS-DYNA; Radioss also `[name]`) on a line of a file.
struct ParameterReference {
    std::string name;    // without '&'
    grammar::Span span;  // '&' and the name
};
// The reference under 1-based byte `column` of line `line`, or nullopt.
std::optional<ParameterReference> parameter_reference_at(const grammar::SourceMap& sources, grammar::FileId file,
                                                         std::uint32_t line, std::uint32_t column);
// The *PARAMETER definition whose name field is under the position, as a reference to itself
// (so hover, definition and references treat a definition's name like a use of it).
std::optional<ParameterReference> parameter_definition_at(const grammar::RawDeck& deck, grammar::FileId file,
                                                          std::uint32_t line, std::uint32_t column);
// Every reference in a line's text (for references of a parameter).
std::vector<ParameterReference> parameter_references(std::string_view text, grammar::FileId file, std::uint32_t line);

// ---- The card and field at a position (position_index_card.cpp) ----

// Columns of a field on its line: 1-based, `end` one past the last.
struct ColumnRange {
    std::uint32_t first = 0, end = 0;
};

// The fixed columns of field `index` of an LS-DYNA card in `format` (keywords::layout), nullopt
// past the layout.
std::optional<ColumnRange> dyna_field_columns(const keywords::CardSpec& card, grammar::CardFormat format,
                                              std::size_t index);
// The fixed columns of field `index` of a Radioss card, nullopt on an engine card, a free-format
// line (`text` with commas) or past the layout.
std::optional<ColumnRange> radioss_field_columns(const RadiossCard& card, std::string_view text, std::size_t index);

// The card line at a position of a block (not its keyword line): the card line the last check
// read, decoded, or on LS-DYNA decks a line typed since (or a comment line) with the card the next
// line after the card line above it would be read as.
struct CardAt {
    const grammar::Block* block = nullptr;
    grammar::CardLinePtr line = nullptr;            // nullptr: a line the last check did not read as a card
    std::uint32_t line_number = 0;                  // 1-based line of the block's file
    std::string_view text;                          // the line's text
    std::optional<DynaCard> dyna;                   // LS-DYNA: the decoded card line
    const keywords::CardSpec* dyna_card = nullptr;  // LS-DYNA: its card, or the card a typed line is read as
    std::optional<RadiossCard> radioss;             // Radioss: the decoded card line (the title line too)

    // The field under 1-based byte `column` of a decoded line, blank part included
    // (engine/field_at_column.hpp); nullopt on a line typed since.
    std::optional<std::size_t> field_under(std::uint32_t column) const;
    // The LS-DYNA field slot a value typed before `column` goes in, from the layout alone: the commas
    // before it in free format, else the fixed slot holding it, or the slot of the value that ends at it.
    std::optional<std::size_t> typed_slot(std::uint32_t column) const;
    // The field the cursor before `column` types into (completion): on a decoded LS-DYNA line the
    // field of the character before while a value is typed, else the field under; a Radioss line the
    // field under, else the one before; a line typed since its typed_slot.
    std::optional<std::size_t> field_at_cursor(std::uint32_t column) const;
};

// Where the default of blank field `index` of a decoded fixed-format LS-DYNA line `text` would be
// read (inlay hints): its first column, when the line reaches it; nullopt in free format.
std::optional<std::uint32_t> blank_field_start(const DynaCard& card, grammar::CardFormat format, std::string_view text,
                                               std::size_t index);

// The card at line `line` (1-based) of `block`, nullopt when there is none (a keyword line, a line
// past the block's cards, a keyword the decoder does not read). `radioss`: the deck is an OpenRadioss
// deck (its format version is read from /BEGIN).
std::optional<CardAt> card_at(const grammar::RawDeck& deck, const grammar::Block& block, std::uint32_t line,
                              bool radioss);

// The value the solver uses for a decoded LS-DYNA field, and why, in words (markdown): as written,
// the default for a blank or for a zero that means it, an enum value's meaning.
std::string effective_value(const model::FieldValue& value);

// ---- The decoded card lines of a range (position_index_range.cpp) ----

struct LineRange {
    std::uint32_t first = 1;  // 1-based, inclusive
    std::uint32_t last = 0;   // 1-based, inclusive
    bool holds(std::uint32_t line) const { return line >= first && line <= last; }
};

// A bulk block: one repeated card line after another (nodes, particles, elements), where the
// values are many and alike. Judged from the schema (LS-DYNA) or the header (Radioss).
bool is_bulk_block(const grammar::Block& block, bool radioss);

// One card line as the decoders read it; exactly one of `dyna` and `radioss` is set.
struct DecodedLine {
    const grammar::Block* block = nullptr;
    grammar::CardLinePtr line = nullptr;
    const DynaCard* dyna = nullptr;
    const RadiossCard* radioss = nullptr;  // with `title` set on a Radioss title line
};
using DecodedLineVisitor = std::function<void(const DecodedLine&)>;

struct RangeWalkOptions {
    // Blocks with more card lines than this are left out (0: none left out).
    std::uint32_t max_block_lines = 0;
    // Bulk blocks are left out.
    bool skip_bulk = false;
};

// Calls `visit` for every decoded card line of `file` in `range`, in line order within a block. A
// big block of one repeated card (*NODE, *ELEMENT_SPH) is decoded only on the lines asked for, so a
// range costs what it shows, not what lies before it.
void visit_card_lines(const grammar::RawDeck& deck, bool radioss, grammar::FileId file, LineRange range,
                      const RangeWalkOptions& options, const DecodedLineVisitor& visit);

// The blocks of `file` that overlap `range` (keyword line to last card line).
std::vector<const grammar::Block*> blocks_in_range(const grammar::RawDeck& deck, grammar::FileId file, LineRange range);

}  // namespace sphdeck::engine
