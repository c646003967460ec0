#include "grammar/keywords/id_kinds.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace sphdeck::keywords {
namespace {

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

using enum IdDefinition::Match;

// The manual's own-id field of each family. The order matters only where families overlap: none do.
constexpr std::array<IdDefinition, 20> kDefinitions{{
    {"*NODE", Options, "NID", "NODE"},
    {"*PART", Options, "PID", "PART"},
    {"*SECTION_", Prefix, "SECID", "SECTION"},
    {"*MAT_", Prefix, "MID", "MAT"},
    {"*EOS_", Prefix, "EOSID", "EOS"},
    {"*HOURGLASS", Prefix, "HGID", "HOURGLASS"},
    {"*SET_NODE", Options, "SID", "SET_NODE"},
    {"*SET_PART", Options, "SID", "SET_PART"},
    {"*SET_SEGMENT", Options, "SID", "SET_SEGMENT"},
    {"*SET_SOLID", Options, "SID", "SET_SOLID"},
    {"*SET_SHELL", Options, "SID", "SET_SHELL"},
    {"*SET_BEAM", Options, "SID", "SET_BEAM"},
    {"*SET_DISCRETE", Options, "SID", "SET_DISCRETE"},
    {"*DEFINE_CURVE", Prefix, "LCID", "DEFINE_CURVE"},
    {"*DEFINE_TABLE", Prefix, "TBID", "DEFINE_CURVE"},
    {"*DEFINE_FUNCTION", Prefix, "FID", "DEFINE_CURVE"},
    {"*DEFINE_BOX", Prefix, "BOXID", "DEFINE_BOX"},
    {"*DEFINE_VECTOR", Prefix, "VID", "DEFINE_VECTOR"},
    {"*DEFINE_COORDINATE", Prefix, "CID", "DEFINE_COORDINATE_SYSTEM"},
    {"*DEFINE_TRANSFORMATION", Prefix, "TRANID", "DEFINE_TRANSFORMATION"},
}};

// Fields of the hand-written tables that name an id, by name.
struct NamedKind {
    std::string_view field;
    std::string_view kind;
};
constexpr std::array<NamedKind, 19> kNamedKinds{{
    {"NID", "NODE"},
    {"SECID", "SECTION"},
    {"ISSPH", "SECTION"},
    {"MID", "MAT"},
    {"EOSID", "EOS"},
    {"HGID", "HOURGLASS"},
    {"PID", "PART"},
    {"IPID", "PART"},
    {"IPSPH", "PART"},
    {"BOXID", "DEFINE_BOX"},
    {"IBOXA", "DEFINE_BOX"},
    {"IBOXB", "DEFINE_BOX"},
    {"NSID", "SET_NODE"},
    {"NSIDEX", "SET_NODE"},
    {"LCID", "DEFINE_CURVE"},
    {"LCFLD", "DEFINE_CURVE"},
    {"DT2MSLC", "DEFINE_CURVE"},
    {"LCIDDR", "DEFINE_CURVE"},
    {"LCEPSMX", "DEFINE_CURVE"},
}};

// PID1..PID8 of *SET_PART_LIST: the name without its trailing digits.
std::string_view without_digits(std::string_view name) {
    while (!name.empty() && std::isdigit(static_cast<unsigned char>(name.back()))) name.remove_suffix(1);
    return name;
}

// Keywords of a defining family that define no id of it: they add to a material, or name parts.
constexpr std::array<std::string_view, 7> kDefineNone{"*MAT_ADD_",      "*PART_MODES",  "*PART_SENSOR",
                                                      "*PART_MOVE",     "*PART_ANNEAL", "*PART_ADAPTIVE_FAILURE",
                                                      "*PART_DUPLICATE"};

}  // namespace

bool IdDefinition::holds_for(std::string_view keyword) const {
    if (!starts_with(keyword, family)) return false;
    for (std::string_view none : kDefineNone)
        if (starts_with(keyword, none)) return false;
    return match == Prefix || keyword.size() == family.size() || keyword[family.size()] == '_';
}

std::span<const IdDefinition> id_definitions() { return kDefinitions; }

const IdDefinition* defining_field(std::string_view keyword, std::string_view field) {
    for (const IdDefinition& d : kDefinitions)
        if (d.field == field && d.holds_for(keyword)) return &d;
    return nullptr;
}

bool defines_kind(std::string_view keyword, std::string_view kind) {
    const std::string_view space = id_space(kind);
    return std::any_of(kDefinitions.begin(), kDefinitions.end(),
                       [&](const IdDefinition& d) { return d.kind == space && d.holds_for(keyword); });
}

std::string_view id_space(std::string_view kind) {
    return kind == "DEFINE_CURVE_OR_TABLE" ? std::string_view("DEFINE_CURVE") : kind;
}

std::string_view kind_named_by(std::string_view keyword, std::string_view field) {
    // *ELEMENT_SPH: NID is the particle's node, PID its part; NEND ends a range of nodes.
    if (keyword == "*ELEMENT_SPH" && field != "PID" && field != "NID") return {};
    const bool numbered = starts_with(keyword, "*SET_PART") || starts_with(keyword, "*SET_NODE");
    const std::string_view name = numbered ? without_digits(field) : field;
    for (const NamedKind& n : kNamedKinds)
        if (name == n.field) return n.kind;
    return {};
}

std::optional<IdRole> id_role(std::string_view keyword, const FieldSpec& field) {
    const bool integer = field.type != FieldType::Real || field.pydyna_integer;
    if (field.type == FieldType::Unused || !integer) return std::nullopt;
    if (const IdDefinition* d = defining_field(keyword, field.name)) return IdRole{d->kind, true};
    if (!field.refers_to.empty()) return IdRole{id_space(field.refers_to), false};
    const std::string_view kind = kind_named_by(keyword, field.name);
    if (kind.empty()) return std::nullopt;
    return IdRole{kind, false};
}

}  // namespace sphdeck::keywords
