// The position index, "what is under this position": the block of a file line, the card line of a
// block, and the card spec and decoded fields of that line, for LS-DYNA and Radioss decks. The editor's
// features (hover, completion, definition, code actions) ask here (engine/id_lookup.hpp for ids); nothing is
// indexed in advance, despite the name, so a request costs a walk of one block (a repeated card such as *NODE or
// *ELEMENT_SPH is found without walking its lines).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
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
const grammar::CardLine* card_line_at(const grammar::RawDeck& deck, const grammar::Block& block, std::uint32_t line);

// The last line (1-based) a block covers in its file: its last card line, or the keyword line.
std::uint32_t block_last_line(const grammar::RawDeck& deck, const grammar::Block& block);

// One decoded LS-DYNA card line.
struct DynaCard {
    keywords::KeywordMatch match;
    const keywords::CardSpec* card = nullptr;
    const grammar::CardLine* line = nullptr;
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
                                     const grammar::CardLine& line);

// The card spec the next line of `block` after `before` would be read as (for completion on a
// line being typed); `before` null: the first card.
const keywords::CardSpec* dyna_card_after(const grammar::RawDeck& deck, const grammar::Block& block,
                                          const grammar::CardLine* before);

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
                                           const grammar::CardLine& line, int version);

// Walks every card line of a Radioss block (not the title line), as radioss_card_at reads them,
// until `visit` returns false.
using RadiossCardVisitor = std::function<bool(const grammar::CardLine&, const RadiossCard&)>;
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

}  // namespace sphdeck::engine
