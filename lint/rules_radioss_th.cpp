// RAD042: the ids a /TH selection names, resolved against the entity kind its keyword names, as
// the starter's reader does (starter/source/output/th/hm_read_thgrou.F of OpenRadioss, AGPL-3.0):
// nodes through USR2SYS (error 78, "NODE ID=... DOES NOT EXIST"), elements through SET_USRTOS in
// hm_read_thgrne.F (error 69, "TH ELEMENT SELECTION ID=... DOES NOT EXIST"), parts in
// hm_read_thgrpa.F (warning 1610), interfaces, rigid walls and accelerometers in hm_read_thgrki.F
// (warning 257, "NONEXISTENT ..."). The lines of a selection (CFG th_*.cfg): the title, the
// variable names (text cells), then one id a line in its first 10 columns.
#include <fmt/format.h>
#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "grammar/fields.hpp"
#include "grammar/radioss/cards.hpp"
#include "grammar/radioss/reader.hpp"
#include "grammar/value.hpp"
#include "lint/rules_radioss.hpp"

namespace sphdeck::lint::radioss {
namespace {

namespace rad = grammar::radioss;

struct ThKind {
    std::string_view selection;                // the keyword's second segment, as the starter matches it (a prefix)
    std::vector<std::string_view> defined_by;  // first segments of the headers whose lines or ids define them
    bool by_header = false;  // ids are the header's integer segments (/PART/5), not the lines' first cells
    diag::Severity severity = diag::Severity::Error;
    int message = 69;
    std::string_view what;
};

const std::vector<ThKind>& kinds() {
    using diag::Severity;
    static const std::vector<ThKind> all = {
        {"NODE", {"NODE", "CNODE"}, false, Severity::Error, 78, "node"},
        {"SPHCEL", {"SPHCEL"}, false, Severity::Error, 69, "SPH cell"},
        {"BRIC",
         {"BRICK", "BRIC20", "TETRA4", "TETRA10", "PENTA6", "SHEL16"},
         false,
         Severity::Error,
         69,
         "solid element"},
        {"SHEL", {"SHELL"}, false, Severity::Error, 69, "4-node shell"},
        {"SH3N", {"SH3N"}, false, Severity::Error, 69, "3-node shell"},
        {"QUAD", {"QUAD"}, false, Severity::Error, 69, "quad"},
        {"TRIA", {"TRIA"}, false, Severity::Error, 69, "2D triangle"},
        {"BEAM", {"BEAM"}, false, Severity::Error, 69, "beam"},
        {"TRUSS", {"TRUSS"}, false, Severity::Error, 69, "truss"},
        {"SPRING", {"SPRING"}, false, Severity::Error, 69, "spring"},
        {"PART", {"PART"}, true, Severity::Warning, 1610, "part"},
        {"INTER", {"INTER"}, true, Severity::Warning, 257, "interface"},
        {"RWALL", {"RWALL"}, true, Severity::Warning, 257, "rigid wall"},
        {"ACCEL", {"ACCEL"}, true, Severity::Warning, 257, "accelerometer"},
    };
    return all;
}

std::string_view trim(std::string_view s) { return grammar::trim_blanks(s); }

std::optional<long long> integer(std::string_view s) {
    const grammar::IntegerValue v = grammar::parse_integer(trim(s));
    if (v.status != grammar::NumberStatus::Ok) return std::nullopt;
    return v.value;
}

bool is_th_prefix(std::string_view first) {
    // /TH and the nine other time-history files /ATH ... /ITH read the same selections.
    return first == "TH" || (first.size() == 3 && first.substr(1) == "TH" && first[0] >= 'A' && first[0] <= 'I');
}

const ThKind* kind_of(std::string_view second) {
    for (const ThKind& k : kinds())
        if (second.starts_with(k.selection)) return &k;
    return nullptr;
}

bool th_in_engine_file(const grammar::RawDeck& deck, const grammar::Block& block) {
    const grammar::FileId root = deck.sources.include_chain(block.span.file).front();
    return rad::is_engine_file_name(deck.sources.file(root).display_name);
}

// The ids of one kind the starter deck defines: the first cell of its element or node lines, or
// the integer segments of its headers. Built for the kinds some selection names only.
std::set<long long> defined_ids(const grammar::RawDeck& deck, const ThKind& kind) {
    std::set<long long> ids;
    for (const grammar::Block& block : deck.blocks) {
        const auto segments = rad::path_segments(block.keyword);
        if (segments.empty() || th_in_engine_file(deck, block)) continue;
        const std::string_view first = trim(segments.front());
        bool match = false;
        for (std::string_view name : kind.defined_by) match = match || first == name;
        if (!match) continue;
        if (kind.by_header) {
            for (std::size_t k = 1; k < segments.size(); ++k)
                if (auto id = integer(segments[k])) ids.insert(*id);
            continue;
        }
        for (grammar::CardLinePtr l = deck.begin_lines(block); l != deck.end_lines(block); ++l) {
            const std::string_view text = deck.text(*l);
            if (auto id = integer(text.substr(0, std::min<std::size_t>(text.size(), 10)))) ids.insert(*id);
        }
    }
    return ids;
}

// Particles the starter makes itself have ids no line defines: SOL2SPH, /SPH/RESERVE.
bool starter_makes_cells(const model::RadiossFacts& f) {
    for (const auto& p : f.solid_properties)
        if (p.ndir.value != 0) return true;
    return !f.reserves.empty();
}

}  // namespace

void check_time_history_selections(RuleContext& c) {
    const model::RadiossFacts& f = *c.model.radioss;
    if (f.submodels || rad::is_v4(f.version)) return;  // submodels offset ids; V4 selections read otherwise
    std::map<const ThKind*, std::set<long long>> defined;
    for (const grammar::Block& block : c.deck.blocks) {
        const auto segments = rad::path_segments(block.keyword);
        if (segments.size() < 2 || !is_th_prefix(trim(segments[0])) || th_in_engine_file(c.deck, block)) continue;
        const ThKind* kind = kind_of(trim(segments[1]));
        if (!kind || (kind->selection == "SPHCEL" && starter_makes_cells(f))) continue;
        auto known = defined.find(kind);
        if (known == defined.end()) known = defined.emplace(kind, defined_ids(c.deck, *kind)).first;
        grammar::CardLinePtr line = c.deck.begin_lines(block);
        grammar::CardLinePtr end = c.deck.end_lines(block);
        if (line != end) ++line;  // the title
        bool ids_begun = false;   // the variable names come first
        for (; line != end; ++line) {
            const std::string_view text = c.deck.text(*line);
            const std::string_view cell = text.substr(0, std::min<std::size_t>(text.size(), 10));
            const auto id = integer(cell);
            if (!id) {
                if (ids_begun && !trim(cell).empty()) break;  // not an id line: stop judging
                continue;
            }
            ids_begun = true;
            if (*id <= 0 || known->second.count(*id)) continue;
            std::size_t offset = cell.find_first_not_of(' ');
            const auto column = static_cast<std::uint32_t>(offset + 1);
            const grammar::Span at{line->file, line->line, column,
                                   column + static_cast<std::uint32_t>(trim(cell).size())};
            const bool error = kind->severity == diag::Severity::Error;
            c.report("RAD042", kind->severity, at,
                     fmt::format("{} {} of {}: no {} of the deck has this id; the starter {} (starter message {})",
                                 kind->what, *id, trim(block.keyword), kind->what,
                                 error ? "stops" : "warns and leaves it out of the time history", kind->message));
        }
    }
}

}  // namespace sphdeck::lint::radioss
