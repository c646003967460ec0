// Which OpenRadioss headers and card cells define or name which kind of id, declared once beside the
// layouts: read by the REF rules of generated cards (model/radioss_decoder.cpp notes the ids,
// lint/rules_radioss_id_links.cpp judges them), by `sphdeck keyword` and by the editor's id look-ups
// (engine/id_lookup.cpp: definition, references, hover, completion, semantic tokens), so they cannot
// disagree. The LS-DYNA counterpart is grammar/keywords/id_kinds.hpp.
//
// Kinds are header families: "PART", "PROP", "MAT", "FUNCT" (functions and tables), "SENSOR", "SKEW",
// "FRAME", "GRNOD", "SURF", "SET", "SUBSET", the other groups ("GRPART", "LINE", "GRSHEL"...), "NODE".
// Sources: the starter's CFG files (grammar/radioss/generated/README.md names the commit), their
// data_hierarchy.cfg TYPEs and HEADERs, and the starter's Fortran, cited per row in id_kinds.cpp.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "grammar/radioss/cards.hpp"

namespace sphdeck::grammar::radioss {

// What the id of a header does: defines an id of `kind` (/PROP/SPH/7 defines PROP 7) or names one
// (/EOS/GRUNEISEN/3 names MAT 3: the material the EOS belongs to).
struct IdRole {
    std::string_view kind;  // static storage
    bool defines = false;
};

// The role of a header family (its first segment: "PROP", "FUNCT_SMOOTH"), or nullopt.
std::optional<IdRole> header_role(std::string_view family);

// A header's id: the first segment of digits after the family (after /TABLE's dimension 0 or 1:
// HEADER("/TABLE/1/%d")), with its bytes in the header.
struct HeaderId {
    std::string_view family;  // "TABLE"
    std::optional<IdRole> role;
    long long id = 0;
    std::size_t begin = 0, end = 0;  // the id's bytes in the header
};
// nullopt when the header has no id segment (or one too long for an id).
std::optional<HeaderId> header_id(std::string_view header);

// The kind a generated cell names by its CFG link (FieldSpec::link: 'F' FUNCT, 'Y' SKEW, 'G' GRNOD, 'U' SURF,
// 'M' MAT, 'P' PROP, 'C' PART, 'S' SENSOR; 'T' SET), empty for 0.
std::string_view linked_kind(char link);
// The letter of a kind's CFG type: 'F' for FUNCT, 'Y' for SKEW and FRAME (one type, SYSTEM), 'T' for SET;
// 0 for kinds no generated cell links (GRPART, SUBSET...). The REF rules keep header ids under it.
char link_of(std::string_view kind);

// The kind of id a card cell names: its CFG link, else what its name says ("prop_ID" a PROP, "fct_IDP"
// a FUNCT, "Sens_ID1" a SENSOR): the hand-written tables, and generated cells the CFG types as no id
// (NODE_ID, GRPART_ID). Empty when the cell names none (reals, text, element ids, flags such as MAT_IDEL).
std::string kind_named_by(const FieldSpec& field);

// Whether ids of kinds `a` and `b` are one space: the same kind; SKEW and FRAME (the starter keeps both
// in ISKN and rejects an id used twice across them, hm_read_frm.F UDOUBLE); a group kind (GRNOD, SURF,
// LINE, GRPART, GRSHEL...) and SET, since the starter makes a group of each kind from a /SET of that
// id (fill_igr.F).
bool ids_meet(std::string_view a, std::string_view b);

// Whether a /SET of an id stands for a group of `kind` (fill_igr.F).
bool is_group(std::string_view kind);

// The headers that define ids of `kind`, for messages: "/FUNCT or /TABLE", "/SKEW or /FRAME".
std::string_view defined_by(std::string_view kind);

}  // namespace sphdeck::grammar::radioss
