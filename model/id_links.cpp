#include "model/id_links.hpp"

#include <array>
#include <cmath>

#include "grammar/keywords/id_kinds.hpp"

namespace sphdeck::model {
namespace {

bool link_starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }
bool contains(std::string_view s, std::string_view p) { return s.find(p) != std::string_view::npos; }

// The kinds whose definitions sphdeck knows; element ids (*ELEMENT_SOLID is not read) and the rest
// are skipped.
constexpr std::array<std::string_view, 17> followed_kinds = {"PART",
                                                             "SECTION",
                                                             "MAT",
                                                             "HOURGLASS",
                                                             "NODE",
                                                             "SET_PART",
                                                             "SET_NODE",
                                                             "SET_SEGMENT",
                                                             "SET_SOLID",
                                                             "SET_BEAM",
                                                             "SET_DISCRETE",
                                                             "DEFINE_BOX",
                                                             "DEFINE_CURVE",
                                                             "DEFINE_CURVE_OR_TABLE",
                                                             "DEFINE_VECTOR",
                                                             "DEFINE_COORDINATE_SYSTEM",
                                                             "DEFINE_TRANSFORMATION"};

// Solvers with their own id spaces (*ICFD_PART, *CESE_PART, *ICFD_SECTION, *MESH_VOLUME...): their
// parts and sections are not *PART's, so pydyna's PART links there cannot be judged against *PART.
bool own_id_space(std::string_view keyword) {
    for (std::string_view p : {"*ICFD_", "*CESE_", "*DUALCESE_", "*EM_", "*MESH_", "*CHEMISTRY_", "*LSO_", "*IGA_",
                               "*STOCHASTIC_", "*RVE_", "*INCLUDE", "*PERTURBATION_"})
        if (link_starts_with(keyword, p)) return true;
    return false;
}

// Keywords whose generated layout does not match every version's: pydyna's *FREQUENCY_DOMAIN_FRF has
// a card (N11, N11TYP) before the damping card that decks of other versions lack (pydyna's own test
// deck nvh/frf_solid.k), so its LCDAM would be read from the next card.
bool layout_varies(std::string_view keyword) { return keyword == "*FREQUENCY_DOMAIN_FRF"; }

const FieldValue* value_named(const std::vector<FieldValue>& card, std::string_view name) {
    for (const FieldValue& v : card)
        if (v.spec->name == name) return &v;
    return nullptr;
}

// *CONTACT_ SURFA / SURFB (the manual's SSID / MSID) name what SURFATYP / SURFBTYP say
// (*CONTACT, card 1: 0 segment set, 1 shell element set, 2 part set, 3 part, 4 node set, 5 all,
// 6 part set to exclude, 7 branch): only the kinds sphdeck reads are followed. Node-to-surface
// contacts take nodes on side A, so a SURFATYP 0 there is not a segment set.
std::string_view contact_kind(std::string_view keyword, std::string_view field, const std::vector<FieldValue>& card,
                              std::string_view& why) {
    const bool side_a = field == "SURFA";
    if (!side_a && field != "SURFB") return {};
    if (!side_a && contains(keyword, "SINGLE_SURFACE")) return {};  // SURFB is not used
    const FieldValue* type = value_named(card, side_a ? "SURFATYP" : "SURFBTYP");
    // Outside the listed types (1e20 in a fuzzed deck) it names nothing, and must not reach the cast.
    if (!type || !type->valid || type->number != std::floor(type->number) || type->number < 0 || type->number > 7)
        return {};
    static constexpr std::array<std::string_view, 5> a_why = {"SURFATYP 0", "", "SURFATYP 2", "SURFATYP 3",
                                                              "SURFATYP 4"};
    static constexpr std::array<std::string_view, 5> b_why = {"SURFBTYP 0", "", "SURFBTYP 2", "SURFBTYP 3",
                                                              "SURFBTYP 4"};
    const auto t = static_cast<long long>(type->number);
    std::string_view kind;
    if (t == 0 && !(side_a && contains(keyword, "NODE"))) kind = "SET_SEGMENT";
    if (t == 2) kind = "SET_PART";
    if (t == 3) kind = "PART";
    if (t == 4) kind = "SET_NODE";
    if (!kind.empty()) why = (side_a ? a_why : b_why)[static_cast<std::size_t>(t)];
    return kind;
}

// Fields pydyna does not link though the manual leaves no doubt: LCID of prescribed motions and
// loads is a curve (or a *DEFINE_FUNCTION, which the curve definitions include) when positive. Their
// kind is the one their name gives (keywords::kind_named_by); elsewhere an unlinked field is not judged.
std::string_view missing_link(std::string_view keyword, std::string_view field) {
    if (field != "LCID") return {};
    for (std::string_view p : {"*BOUNDARY_PRESCRIBED_MOTION", "*LOAD_NODE", "*LOAD_SEGMENT", "*LOAD_BODY_"})
        if (link_starts_with(keyword, p)) return keywords::kind_named_by(keyword, field);
    return {};
}

// The kinds whose definitions the model reads itself (model/extract.cpp) and the REF rules take from it:
// a field naming one inside a block of its defining family (*PART_MODES' PID) is followed as a reference.
bool model_reads(std::string_view kind) {
    return kind == "PART" || kind == "SECTION" || kind == "MAT" || kind == "NODE";
}

// A field of the same card whose name says it is a type or an option may change what kind of
// entity an id names (*AIRBAG_PARTICLE STYPE1: part or part set, *INITIAL_VELOCITY_GENERATION STYP):
// pydyna's one link per field cannot say, so such links to parts, sets and nodes are not followed.
bool card_has_type_field(const std::vector<FieldValue>& card) {
    for (const FieldValue& v : card)
        if (contains(v.spec->name, "TYP") || v.spec->name == "OPT" || v.spec->name == "OPTION") return true;
    return false;
}

}  // namespace

std::string_view followed_kind(std::string_view keyword, const keywords::FieldSpec& field,
                               const std::vector<FieldValue>& card, std::string_view& why) {
    why = {};
    if (own_id_space(keyword) || layout_varies(keyword)) return {};
    if (link_starts_with(keyword, "*CONTACT_") && !link_starts_with(keyword, "*CONTACT_2D") &&
        !link_starts_with(keyword, "*CONTACT_ENTITY"))
        if (std::string_view kind = contact_kind(keyword, field.name, card, why); !kind.empty()) return kind;
    std::string_view kind = field.refers_to.empty() ? missing_link(keyword, field.name) : field.refers_to;
    if (kind.empty() || (!model_reads(kind) && keywords::defines_kind(keyword, kind))) return {};
    // The data card of *PART_INERTIA, *PART_CONTACT...: the part's own SECID and MID, which REF003
    // and REF004 check with the part (model/extract.cpp reads *PART_ variants as parts).
    if (link_starts_with(keyword, "*PART") && (kind == "SECTION" || kind == "MAT" || kind == "HOURGLASS")) return {};
    const bool entity = !link_starts_with(kind, "DEFINE_") && kind != "HOURGLASS";  // parts, sets, nodes...
    if (!field.refers_to.empty() && entity && card_has_type_field(card)) return {};
    // Element connectivity (millions of lines) is the mesher's, and *SET_ lists are checked by
    // REF001/REF002 where sphdeck reads them.
    if (kind == "NODE" && (link_starts_with(keyword, "*ELEMENT_") || link_starts_with(keyword, "*SET_"))) return {};
    for (std::string_view k : followed_kinds)
        if (k == kind) return k;
    return {};
}

void IdLinkCollector::on_card(const keywords::KeywordMatch& match, const std::vector<FieldValue>& values) {
    // Bounded: a deck naming more distinct ids than this keeps the first ones only.
    constexpr std::size_t max_references = 100000;
    const std::string_view keyword = match.schema->name;
    for (const FieldValue& v : values) {
        // Most fields of a bulk card (element ids, coordinates) link nothing: leave before any
        // string work, since this runs for every line of every generated keyword.
        const std::string_view name = v.spec->name;
        if (v.spec->refers_to.empty() && name != "LCID" && name != "SURFA" && name != "SURFB") continue;
        if (!v.explicit_value || !v.valid || v.number <= 0 || v.number != std::floor(v.number) ||
            v.number > max_exact_integer)
            continue;
        std::string_view why;
        const std::string_view kind = followed_kind(keyword, *v.spec, values, why);
        if (kind.empty()) continue;
        const auto id = static_cast<long long>(v.number);
        auto [it, fresh] = seen_.try_emplace({kind, id}, references_.size());
        if (!fresh) {
            ++references_[it->second].count;
            continue;
        }
        if (references_.size() >= max_references) {
            seen_.erase(it);
            continue;
        }
        references_.push_back({kind, id, v.span, keyword, v.spec->name, why, 1});
    }
}

}  // namespace sphdeck::model
