// Which fields define or name which kind of id, declared once beside the layouts: read by the REF rules
// (model/id_links.cpp, lint/rules_references_links.cpp) and by the editor's id look-ups (engine/id_lookup.cpp:
// definition, references, hover, completion, semantic tokens), so the two cannot disagree. Kinds are
// spelled like the generated layouts' links (FieldSpec::refers_to): "PART", "SECTION", "MAT", "EOS",
// "HOURGLASS", "SET_NODE", "SET_PART", "DEFINE_CURVE", "DEFINE_BOX"...
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "grammar/keywords/schema.hpp"

namespace sphdeck::keywords {

// A keyword family whose blocks define ids of a kind: the id in `field`, the first field of the first card
// (after a _TITLE line): *PART's PID, *SECTION_'s SECID, *DEFINE_CURVE's LCID.
struct IdDefinition {
    // How `family` matches a keyword: `Options`, the keyword itself or with options (*SET_PART,
    // *SET_PART_LIST, *SET_PART_ADD...); `Prefix`, any keyword that starts so (*MAT_, *DEFINE_CURVE...).
    enum class Match { Options, Prefix };
    std::string_view family;
    Match match;
    std::string_view field;
    std::string_view kind;

    bool holds_for(std::string_view keyword) const;  // whether `keyword` is of this family
};

// Every family that defines ids. *MAT_ADD_ blocks add to material MID and define none; neither do the
// *PART_ keywords that name parts made elsewhere (*PART_MODES, *PART_SENSOR, *PART_MOVE, *PART_ANNEAL,
// *PART_ADAPTIVE_FAILURE: PID on their first card, no heading; *PART_DUPLICATE).
std::span<const IdDefinition> id_definitions();

// The family row when `field` of `keyword` (canonical schema name) holds the block's own id, else nullptr.
const IdDefinition* defining_field(std::string_view keyword, std::string_view field);

// Whether blocks of `keyword` (any name written in a deck) define ids of `kind` (or of its id space).
bool defines_kind(std::string_view keyword, std::string_view kind);

// The id space of a kind: pydyna's DEFINE_CURVE_OR_TABLE names the ids of DEFINE_CURVE (tables and
// functions share the curves' ids); every other kind is its own.
std::string_view id_space(std::string_view kind);

// The kind a field names by its name where the layout does not link it (the hand-written tables; pydyna's
// layouts say it in FieldSpec::refers_to): SECID a section, LCID a curve, NSID a node set; PID1..PID8 of
// *SET_PART_LIST name parts. *ELEMENT_SPH names its node (NID) and part (PID) only. Empty when none.
std::string_view kind_named_by(std::string_view keyword, std::string_view field);

// What a field of `keyword` (canonical schema name) does with ids: defines one of `kind` (the field that
// holds a block's own id, defining_field) or names one (the layout's link, refers_to, in its id space; else
// kind_named_by). Integer fields only, pydyna's integers read as reals included (*DEFINE_TABLE TBID,
// *DEFINE_VECTOR VID: FieldSpec::pydyna_integer). nullopt when the field is no id.
struct IdRole {
    std::string_view kind;
    bool defines = false;
};
std::optional<IdRole> id_role(std::string_view keyword, const FieldSpec& field);

}  // namespace sphdeck::keywords
