#include "lint/rules_references_links.hpp"

#include <charconv>
#include <fmt/format.h>
#include <map>
#include <string>
#include <unordered_set>

#include "grammar/fields.hpp"
#include "grammar/keywords/id_kinds.hpp"

namespace sphdeck::lint {
namespace {

bool references_links_starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

// The ids a kind's defining keywords give, read from the first field of their first card (after
// the title line of _TITLE), as raw_first_id reads unknown sections and materials: the keywords
// may be hand-written, generated or unknown alike.
using Definitions = DefinedIds;

// The first field of a card line as an integer; nullopt when it is not one.
std::optional<long long> first_integer(std::string_view text, grammar::CardFormat format) {
    std::string_view field =
        text.substr(0, std::min<std::size_t>(text.size(), format == grammar::CardFormat::Long ? 20 : 10));
    if (grammar::is_free_format(text)) field = text.substr(0, text.find(','));
    while (!field.empty() && (field.front() == ' ' || field.front() == '\t')) field.remove_prefix(1);
    while (!field.empty() && (field.back() == ' ' || field.back() == '\t' || field.back() == '\r'))
        field.remove_suffix(1);
    long long n = 0;
    auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), n);
    if (ec != std::errc() || end != field.data() + field.size()) return std::nullopt;
    return n;
}

// Kinds of which one block may define several (one per card line): every line's first integer
// counts, which may take a coordinate for an id but never misses a definition.
bool several_per_block(std::string_view kind) {
    return kind == "DEFINE_VECTOR" || kind == "DEFINE_COORDINATE_SYSTEM" || kind == "HOURGLASS" || kind == "DEFINE_BOX";
}

Definitions definitions_of(const grammar::RawDeck& deck, std::string_view kind) {
    Definitions d;
    for (const grammar::Block& b : deck.blocks) {
        if (!keywords::defines_kind(b.keyword, kind)) continue;
        grammar::CardLinePtr line = deck.begin_lines(b);
        line += keywords::title_lines(b.keyword);
        if (line >= deck.end_lines(b)) continue;
        if (auto id = first_integer(deck.text(*line), b.format))
            d.ids.insert(*id);
        else
            d.unreadable = true;
        if (several_per_block(kind))
            for (++line; line < deck.end_lines(b); ++line)
                if (auto id = first_integer(deck.text(*line), b.format)) d.ids.insert(*id);
    }
    return d;
}

template <typename T>
Definitions ids_of(const std::vector<T>& items) {
    Definitions d;
    for (const T& item : items) {
        long long n = 0;
        auto [end, ec] = std::from_chars(item.id.data(), item.id.data() + item.id.size(), n);
        if (ec == std::errc() && end == item.id.data() + item.id.size())
            d.ids.insert(n);
        else if (!item.id.empty())
            d.unreadable = true;
    }
    return d;
}

// Keywords that make parts of their own (SPH parts of adaptive solids, duplicated parts): a part id no
// *PART defines may be theirs. Not *DEFINE_SPH_MESH_BOX/_SURFACE: their SPHPID/IPID is filled with particles
// but is a *PART of its own with its *SECTION_SPH (pydyna's isph.k defines parts 4-6 so), and REF002 judges
// the part sets of such decks too; a *CONSTRAINED_RIGID_BODIES naming no part there is reported (issue 37).
bool deck_makes_parts(const grammar::RawDeck& deck) {
    for (const grammar::Block& b : deck.blocks)
        for (std::string_view p : {"*DEFINE_ADAPTIVE_SOLID_TO_SPH", "*PART_DUPLICATE", "*ALE_STRUCTURED_MESH",
                                   "*DEFINE_PARTICLE_BLAST", "*ELEMENT_SEATBELT"})
            if (references_links_starts_with(b.keyword, p)) return true;
    return false;
}

// *INCLUDE_TRANSFORM offsets the ids of the file it reads (IDNOFF, IDPOFF, IDFOFF...), which
// sphdeck does not apply: ids named across files cannot be matched.
bool ids_offset(const grammar::RawDeck& deck) {
    for (const grammar::Block& b : deck.blocks)
        if (references_links_starts_with(b.keyword, "*INCLUDE_TRANSFORM")) return true;
    return false;
}

struct KindWords {
    std::string_view code;
    std::string_view what;     // "curve"
    std::string_view defined;  // "*DEFINE_CURVE, *DEFINE_TABLE or *DEFINE_FUNCTION"
};

KindWords words_for(std::string_view kind) {
    if (kind == "PART") return {"REF002", "part", "*PART"};
    if (kind == "SECTION") return {"REF003", "section", "*SECTION_"};
    if (kind == "MAT") return {"REF004", "material", "*MAT_"};
    if (kind == "NODE") return {"REF001", "node", "*NODE"};
    if (kind == "SET_PART") return {"REF008", "part set", "*SET_PART"};
    if (kind == "SET_NODE") return {"REF008", "node set", "*SET_NODE"};
    if (kind == "SET_SEGMENT") return {"REF008", "segment set", "*SET_SEGMENT"};
    if (kind == "SET_SOLID") return {"REF008", "solid set", "*SET_SOLID"};
    if (kind == "SET_BEAM") return {"REF008", "beam set", "*SET_BEAM"};
    if (kind == "SET_DISCRETE") return {"REF008", "discrete set", "*SET_DISCRETE"};
    if (kind == "DEFINE_BOX") return {"REF009", "box", "*DEFINE_BOX"};
    if (kind == "DEFINE_VECTOR") return {"REF009", "vector", "*DEFINE_VECTOR"};
    if (kind == "DEFINE_COORDINATE_SYSTEM") return {"REF009", "coordinate system", "*DEFINE_COORDINATE_"};
    if (kind == "DEFINE_TRANSFORMATION") return {"REF009", "transformation", "*DEFINE_TRANSFORMATION"};
    if (kind == "HOURGLASS") return {"REF009", "hourglass", "*HOURGLASS"};
    return {"REF009", "curve", "*DEFINE_CURVE, *DEFINE_TABLE or *DEFINE_FUNCTION"};  // DEFINE_CURVE(_OR_TABLE)
}

}  // namespace

bool deck_may_define(const grammar::RawDeck& deck, std::string_view kind, long long id) {
    const Definitions d = definitions_of(deck, kind);
    return d.unreadable || d.ids.count(id) > 0;
}

DefinedIds defined_ids(const grammar::RawDeck& deck, std::string_view kind) { return definitions_of(deck, kind); }

void check_followed_references(RuleContext& c, std::set<model::Id>& boxes) {
    const auto& references = c.model.id_references;
    if (references.empty() || ids_offset(c.deck)) return;
    const bool parts_made = deck_makes_parts(c.deck);
    std::map<std::string_view, Definitions> known;
    auto definitions = [&](std::string_view kind) -> const Definitions& {
        auto it = known.find(kind);
        if (it != known.end()) return it->second;
        Definitions d;
        if (kind == "PART")
            d = ids_of(c.model.parts);
        else if (kind == "SECTION")
            d = ids_of(c.model.sections);
        else if (kind == "MAT") {
            d = ids_of(c.model.materials);
            // Thermal materials (*MAT_THERMAL_..., the TMID of a part) are not in model.materials.
            for (const grammar::Block& b : c.deck.blocks)
                if (references_links_starts_with(b.keyword, "*MAT_THERMAL_") &&
                    c.deck.begin_lines(b) < c.deck.end_lines(b)) {
                    grammar::CardLinePtr line = c.deck.begin_lines(b) + keywords::title_lines(b.keyword);
                    if (line >= c.deck.end_lines(b)) continue;
                    if (auto id = first_integer(c.deck.text(*line), b.format))
                        d.ids.insert(*id);
                    else
                        d.unreadable = true;
                }
        } else if (kind != "NODE")
            d = definitions_of(c.deck, keywords::id_space(kind));
        return known.emplace(kind, std::move(d)).first->second;
    };
    std::set<std::string_view> hinted;  // kinds with the "defines none" note already given
    for (const model::IdReference& r : references) {
        if (r.kind == "DEFINE_BOX") boxes.insert(std::to_string(r.id));
        if (r.kind == "PART" && parts_made) continue;
        bool defined = false;
        if (r.kind == "NODE") {
            defined = c.node_index().find(r.id).has_value();
        } else {
            const Definitions& d = definitions(r.kind);
            if (d.unreadable) continue;
            defined = d.ids.count(r.id) > 0;
        }
        if (defined) continue;
        const KindWords w = words_for(r.kind);
        std::string decided = r.why.empty() ? "" : fmt::format(" ({})", r.why);
        std::string more = r.count > 1 ? fmt::format("; named {} times", r.count) : "";
        auto& d = c.report(w.code, r.span,
                           fmt::format("{} {}{} names {} {}, which no {} defines{}", r.keyword, r.field, decided,
                                       w.what, r.id, w.defined, more));
        const bool none = r.kind == "NODE" ? c.model.nodes.id.empty() : definitions(r.kind).ids.empty();
        if (none && hinted.insert(r.kind).second)
            d.notes.push_back(
                {{}, fmt::format("the deck defines no {}: a fragment of a model (a missing include?)", w.defined)});
    }
}

}  // namespace sphdeck::lint
