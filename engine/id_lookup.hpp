// Id look-ups for the editor: the id a field defines or names (a *PART's PID, a part's SECID, the id of
// a Radioss /PROP header), the uses of an id and its definitions, so that definition, references, hover
// and completion can follow them. No index is built (model/id_index.hpp is the index of node and particle
// ids): each question walks the deck's blocks again. Which fields define or name which kind of id is
// declared once, read by the REF rules too: grammar/keywords/id_kinds.hpp for LS-DYNA (kinds spelled like
// the generated layouts' links: "PART", "SECTION", "MAT", "SET_NODE", "DEFINE_CURVE"...),
// grammar/radioss/id_kinds.hpp for OpenRadioss (kinds are header families: "PART", "PROP", "MAT", "FUNCT",
// "SENSOR", "SKEW", "GRNOD", "SURF", "SET"...).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/keywords/schema.hpp"
#include "grammar/radioss/cards.hpp"
#include "grammar/raw_deck.hpp"
#include "engine/check.hpp"
#include "model/card_decoder.hpp"
#include "model/radioss_card_decoder.hpp"

namespace sphdeck::engine {

struct IdRole {
    std::string kind;
    bool defines = false;
};

// The id role of an LS-DYNA field of a keyword (canonical schema name), or nullopt (keywords::id_role).
std::optional<IdRole> dyna_id_role(std::string_view keyword, const keywords::FieldSpec& field);
// The id role of a Radioss card field ("prop_ID" names a PROP), or nullopt (grammar::radioss::kind_named_by).
std::optional<IdRole> radioss_id_role(const grammar::radioss::FieldSpec& field);

// Whether ids of kind `a` and kind `b` are one space: the same kind; for Radioss also SKEW and FRAME, and
// a group kind (GRNOD, GRPART, SURF, LINE...) and SET (grammar::radioss::ids_meet). LS-DYNA kinds meet
// themselves only: their spaces are folded when the role is read (keywords::id_space).
bool ids_meet(std::string_view a, std::string_view b);

// The id a decoded field holds ("7", a label), empty when blank, zero or unreadable.
std::string id_text(const model::FieldValue& value);
std::string id_text(const model::RadiossValue& value);

// One place an id stands.
struct IdUse {
    std::string kind;
    std::string id;
    grammar::Span span;
    bool defines = false;
    const grammar::Block* block = nullptr;  // the block it stands in
    std::string title;                      // for a definition: the part heading, the block's title
};

// Every id use of the deck outside its bulk blocks (*NODE, *ELEMENT_SPH, /NODE, /SPHCEL):
// one walk of the other blocks, decoding their cards again.
std::vector<IdUse> collect_ids(const CheckResult& deck);

// The id use under a position (1-based line, byte column) of `file`, bulk lines included.
std::optional<IdUse> id_at(const CheckResult& deck, grammar::FileId file, std::uint32_t line, std::uint32_t column);

// The definitions of id `id` of `kind` (usually one; a duplicated id gives more): a walk of the
// blocks of the defining families only (LS-DYNA), or of the block headers (Radioss).
std::vector<IdUse> find_definitions(const CheckResult& deck, const std::string& kind, const std::string& id);
// Every definition of `kind` (of id `*id` when given), the same walk; none for NODE.
std::vector<IdUse> definitions_of(const CheckResult& deck, const std::string& kind, const std::string* id = nullptr);

// The *ELEMENT_SPH lines that name part (kind PART) or node (NODE) `id`, as PID or NID field
// spans: a scan of the particle arrays, decoding only the lines that match; at most `limit`.
// Empty for other kinds and for Radioss decks (/SPHCEL names its part in the header).
std::vector<grammar::Span> particle_spans(const CheckResult& deck, const std::string& kind, const std::string& id,
                                          std::size_t limit);

// A short description of a definition: "*SECTION_SPH 3, line 40" (+ its title when known), in the
// deck's bytes (an editor makes it valid UTF-8).
std::string describe(const CheckResult& deck, const IdUse& definition);

}  // namespace sphdeck::engine
