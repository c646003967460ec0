#include "grammar/radioss/id_kinds.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <vector>

#include "grammar/fields.hpp"

namespace sphdeck::grammar::radioss {
namespace {

// A header family and what its id does. `prefix`: any family that starts so (FUNCT_SMOOTH).
struct HeaderRow {
    std::string_view family;
    bool prefix;
    IdRole role;
};

// CFG data_hierarchy.cfg (radioss2026): TYPE FUNCT holds /FUNCT, /TABLE (table_0.cfg, table_1.cfg),
// /FUNCT_SMOOTH and /FUNCT_PYTHON, one id space (hm_read_table.F counts "/TABLE + /FUNCT" together);
// TYPE SYSTEM holds /SKEW and /FRAME. /MOVE_FUNCT is a SUBOBJECT of FUNCT: it scales and shifts the
// function of its id and defines none (hm_read_move_funct.F looks the id up among the functions). An
// /EOS and a /FAIL carry the id of their material (HEADER("/FAIL/BIQUAD/%d",mat_id)); element blocks
// the id of their part. /FUNC_2D (its own FUNC2D store, hm_read_func2d.F) is left out.
constexpr std::array<HeaderRow, 34> kHeaders{{
    {"PART", false, {"PART", true}},         {"PROP", false, {"PROP", true}},     {"MAT", false, {"MAT", true}},
    {"FUNCT", false, {"FUNCT", true}},       {"FUNCT_", true, {"FUNCT", true}},   {"TABLE", false, {"FUNCT", true}},
    {"MOVE_FUNCT", false, {"FUNCT", false}}, {"SENSOR", false, {"SENSOR", true}}, {"SKEW", false, {"SKEW", true}},
    {"FRAME", false, {"FRAME", true}},       {"SET", false, {"SET", true}},       {"SUBSET", false, {"SUBSET", true}},
    {"GRNOD", false, {"GRNOD", true}},       {"SURF", false, {"SURF", true}},     {"LINE", false, {"LINE", true}},
    {"GRPART", false, {"GRPART", true}},     {"GRSHEL", false, {"GRSHEL", true}}, {"GRSH3N", false, {"GRSH3N", true}},
    {"GRBRIC", false, {"GRBRIC", true}},     {"GRQUAD", false, {"GRQUAD", true}}, {"GRTRUS", false, {"GRTRUS", true}},
    {"GRBEAM", false, {"GRBEAM", true}},     {"GRSPRI", false, {"GRSPRI", true}}, {"EOS", false, {"MAT", false}},
    {"FAIL", false, {"MAT", false}},         {"SPHCEL", false, {"PART", false}},  {"BRICK", false, {"PART", false}},
    {"TETRA4", false, {"PART", false}},      {"TETRA10", false, {"PART", false}}, {"PENTA6", false, {"PART", false}},
    {"SHELL", false, {"PART", false}},       {"SH3N", false, {"PART", false}},    {"BEAM", false, {"PART", false}},
    {"SPRING", false, {"PART", false}},
}};

// The groups fill_igr.F makes from a /SET: IGRNOD, IGRSURF, IGRSLIN, IGRPART, IGRBRIC, IGRQUAD, IGRSH4N,
// IGRSH3N, IGRTRUSS, IGRBEAM, IGRSPRING.
constexpr std::array<std::string_view, 11> kGroups{"GRNOD",  "SURF",   "LINE",   "GRPART", "GRBRIC", "GRQUAD",
                                                   "GRSHEL", "GRSH3N", "GRTRUS", "GRBEAM", "GRSPRI"};

// A kind, the letter of its CFG type (the ATTRIBUTES type of the cells naming one, FieldSpec::link, from
// scripts/gen_radioss_layouts.py LINK_TYPES; 'T' the sets, which no cell links) and the headers defining it.
struct KindRow {
    std::string_view kind;
    char link;
    std::string_view defined_by;
};
constexpr std::array<KindRow, 10> kKinds{{
    {"FUNCT", 'F', "/FUNCT or /TABLE"},
    {"SENSOR", 'S', "/SENSOR"},
    {"SKEW", 'Y', "/SKEW or /FRAME"},  // CFG type SYSTEM
    {"FRAME", 'Y', "/SKEW or /FRAME"},
    {"GRNOD", 'G', "/GRNOD"},
    {"SURF", 'U', "/SURF"},
    {"MAT", 'M', "/MAT"},
    {"PROP", 'P', "/PROP"},
    {"PART", 'C', "/PART"},  // CFG type COMPONENT
    {"SET", 'T', "/SET"},
}};

// What a cell's name says where no link does: the text before "_ID", upper case, in the words of the
// header families. Element ids name elements the index does not follow.
struct NameAlias {
    std::string_view written, kind;
};
constexpr std::array<NameAlias, 10> kAliases{{
    {"FCT", "FUNCT"},
    {"TAB", "FUNCT"},
    {"TABLE", "FUNCT"},
    {"SENS", "SENSOR"},
    {"GRSH4N", "GRSHEL"},
    {"GRQD", "GRQUAD"},
    {"BRICK", ""},
    {"TETRA", ""},
    {"PENTA", ""},
    {"EL", ""},
}};
// Flags whose names look like ids: LAW116/LAW117's MAT_IDEL (element deletion), LAW120/TAPO's MAT_IDAM.
constexpr std::array<std::string_view, 2> kNotIds{"MAT_IDEL", "MAT_IDAM"};

bool all_digits(std::string_view s) {
    const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
    return !s.empty() && std::all_of(s.begin(), s.end(), digit);
}

}  // namespace

std::optional<IdRole> header_role(std::string_view family) {
    for (const HeaderRow& h : kHeaders)
        if (h.prefix ? family.substr(0, h.family.size()) == h.family : family == h.family) return h.role;
    return std::nullopt;
}

std::optional<HeaderId> header_id(std::string_view header) {
    const std::vector<std::string_view> segments = path_segments(header);
    if (segments.empty()) return std::nullopt;
    HeaderId out;
    out.family = trim_blanks(segments.front());
    out.role = header_role(out.family);
    bool dimension = out.family == "TABLE";  // /TABLE/<dimension 0 or 1>/<id>
    for (std::size_t k = 1; k < segments.size(); ++k) {
        const std::string_view s = trim_blanks(segments[k]);
        if (dimension && (s == "0" || s == "1")) {
            dimension = false;
            continue;
        }
        if (!all_digits(s)) continue;
        const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out.id);
        if (ec != std::errc()) return std::nullopt;
        out.begin = static_cast<std::size_t>(s.data() - header.data());
        out.end = out.begin + s.size();
        return out;
    }
    return std::nullopt;
}

std::string_view linked_kind(char link) {
    for (const KindRow& k : kKinds)
        if (link && k.link == link) return k.kind;
    return {};
}

char link_of(std::string_view kind) {
    for (const KindRow& k : kKinds)
        if (k.kind == kind) return k.link;
    return 0;
}

std::string kind_named_by(const FieldSpec& field) {
    if (field.cell != Cell::Int) return {};
    if (field.link) return std::string(linked_kind(field.link));
    const std::string_view name = field.name;
    const std::size_t at = name.rfind("_ID");
    if (at == std::string_view::npos || at == 0) return {};
    if (std::find(kNotIds.begin(), kNotIds.end(), name) != kNotIds.end()) return {};
    std::string prefix(name.substr(0, at));
    for (char& c : prefix) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (const NameAlias& a : kAliases)
        if (prefix == a.written) return std::string(a.kind);
    return prefix;
}

bool is_group(std::string_view kind) { return std::find(kGroups.begin(), kGroups.end(), kind) != kGroups.end(); }

bool ids_meet(std::string_view a, std::string_view b) {
    if (a == b) return true;
    const auto system = [](std::string_view k) { return k == "SKEW" || k == "FRAME"; };
    if (system(a) && system(b)) return true;
    return (a == "SET" && is_group(b)) || (is_group(a) && b == "SET");
}

std::string_view defined_by(std::string_view kind) {
    for (const KindRow& k : kKinds)
        if (k.kind == kind) return k.defined_by;
    return {};
}

}  // namespace sphdeck::grammar::radioss
