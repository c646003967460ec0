#include "grammar/radioss/keyword_lookup.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <unordered_map>
#include <vector>

#include "grammar/radioss/generated_layouts.hpp"
#include "grammar/fields.hpp"
#include "grammar/similar_names.hpp"

namespace sphdeck::grammar::radioss {
namespace {

// KEY0 of the engine's freform.F (OpenRadioss engine/source/input): the first five characters of
// a header's first segment, blank-padded, must equal one of them.
constexpr std::array<std::string_view, 81> engine_keys = {
    "RUN",   "TITLE", "DT",    "TFILE", "PRINT", "RFILE", "VERS",  "ALE",   "DEL",   "VEL",   "BCS",   "BCSR",
    "INTER", "DTIX",  "IMPL",  "FUNCT", "FLSEC", "DYREL", "KEREL", "RBODY", "ANIM",  "DEBUG", "OUTP",  "ALESU",
    "PROC",  "@TFIL", "DELIN", "PARIT", "INIV",  "UPWM",  "MON",   "DT1",   "INCMP", "TH",    "STOP",  "KILL",
    "MADYM", "SPMD",  "RAD2R", "DAMP",  "ATFIL", "BTFIL", "CTFIL", "DTFIL", "ETFIL", "FTFIL", "GTFIL", "HTFIL",
    "ITFIL", "RERUN", "FXINP", "EIG",   "FVMBA", "STATE", "SHVER", "ABF",   "DTSDE", "AABF",  "BABF",  "CABF",
    "DABF",  "EABF",  "FABF",  "GABF",  "HABF",  "IABF",  "UPWIN", "THERM", "H3D",   "REPOR", "NEGVO", "ADYRE",
    "DT1TE", "PERF",  "DYNAI", "DTTSH", "MASS",  "SENS",  "VIPER", "PROFI", "ALE"};

// Read by the deck reader itself, no CFG file's HEADER (reader/source/cfgio mv_solver_input_infos.cpp:
// //SUBMODEL, //ENDSUB, /KEY, #enddata).
constexpr std::array<std::string_view, 4> reader_keywords = {"SUBMODEL", "ENDSUB", "KEY", "ENDDATA"};

std::size_t count_name_segments(std::string_view prefix) {
    return static_cast<std::size_t>(std::count(prefix.begin(), prefix.end(), '/'));
}

const KeywordSpec* generated_named(std::string_view name) { return generated::keyword_named(name); }

// A generated name that starts with `prefix` + '/': the hand-written `prefix` is then a family.
bool has_generated_below(std::string_view prefix) {
    const std::string below = std::string(prefix) + '/';
    const auto all = generated::layouts();
    auto it = std::lower_bound(all.begin(), all.end(), std::string_view(below),
                               [](const generated::LayoutEntry& k, std::string_view n) { return k.name < n; });
    return it != all.end() && it->name.substr(0, below.size()) == below;
}

KeywordLookup lookup_raw(std::string_view header);

// A generated layout whose newest format checks at least its first card (not only text lines).
bool checks_cards(const KeywordSpec& k) {
    if (k.formats.empty() || k.formats.front().cards.empty()) return false;
    const CardSpec& first = k.formats.front().cards.front();
    return !first.fields.empty() && first.fields.front().cell != Cell::Line;
}

// A table whose every format keeps every line as text (a family's catch-all: /PROP, /GRNOD).
bool keeps_text_only(const KeywordSpec& k) {
    for (const FormatSpec& f : k.formats)
        for (const CardSpec& c : f.cards)
            if (c.fields.size() != 1 || c.fields[0].cell != Cell::Line || c.repeat != Repeat::Repeated) return false;
    return true;
}

// The starter's reader takes the longest name that begins the header, character by character,
// once the first segment is whole (SolverInputInfo::GetKeywordSolverInfoFromHeaderLine in
// OpenRadioss reader/source/cfgio): /TH/SHELL reads as /TH/SHEL, /TH/BRICK as /TH/BRIC.
const KeywordSpec* find_by_characters(std::string_view header, std::size_t* prefix_segments) {
    const std::size_t first_end = header.find('/', 1);
    if (first_end == std::string_view::npos) return nullptr;
    for (std::size_t length = header.size(); length > first_end + 1; --length) {
        const std::string_view prefix = header.substr(0, length);
        if (prefix.back() == '/') continue;
        if (const KeywordSpec* k = generated_named(prefix)) {
            if (prefix_segments) *prefix_segments = count_name_segments(prefix);
            return k;
        }
    }
    return nullptr;
}

}  // namespace

const KeywordSpec* find_generated(std::string_view header, std::size_t* prefix_segments) {
    std::string_view prefix = header;
    while (!prefix.empty()) {
        if (const KeywordSpec* k = generated_named(prefix)) {
            if (prefix_segments) *prefix_segments = count_name_segments(prefix);
            return k;
        }
        const std::size_t slash = prefix.rfind('/');
        if (slash == std::string_view::npos || slash == 0) break;
        prefix = prefix.substr(0, slash);
    }
    return nullptr;
}

namespace {

KeywordLookup lookup_unremembered(std::string_view header);

// Heterogeneous lookup: a header is looked up without being copied into a string.
struct HeaderHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
};

}  // namespace

KeywordLookup lookup_keyword(std::string_view header) {
    // The answers of this thread, by header, as suggest_keyword remembers its own: a deck names the same
    // headers again and again (/PART/1, /PART/2... differ; /NODE, /MAT/LAW2/1 in each copy of a block do
    // not), and a deck checked again (the editor at each keystroke, a fuzzer mutating a byte) asks again
    // for each; an answer tries every prefix of the header against the tables. Bounded: emptied when full.
    constexpr std::size_t max_remembered = 4096;
    thread_local std::unordered_map<std::string, KeywordLookup, HeaderHash, std::equal_to<>> remembered;
    if (const auto it = remembered.find(header); it != remembered.end()) return it->second;
    const KeywordLookup answer = lookup_unremembered(header);
    if (remembered.size() >= max_remembered) remembered.clear();
    remembered.emplace(std::string(header), answer);
    return answer;
}

namespace {

KeywordLookup lookup_unremembered(std::string_view header) {
    KeywordLookup out;
    // Blanks around a segment are the starter's reader's concern, not the name's ("/GRNOD/NODE   /2").
    if (header.find(' ') != std::string_view::npos || header.find('\t') != std::string_view::npos) {
        std::string plain;
        for (std::string_view segment : path_segments(header)) {
            plain += '/';
            plain += trim_blanks(segment);
        }
        out = lookup_raw(plain);
        const KeywordLookup raw = lookup_raw(header);
        out.spec = raw.spec;
        out.cards = raw.cards;
        out.prefix_segments = raw.prefix_segments;
        return out;
    }
    return lookup_raw(header);
}

}  // namespace

namespace {
KeywordLookup lookup_raw(std::string_view header) {
    KeywordLookup out;
    const auto segments = path_segments(header);
    if (!segments.empty() &&
        std::find(reader_keywords.begin(), reader_keywords.end(), segments.front()) != reader_keywords.end())
        out.known = true;
    std::size_t hand_segments = 0, generated_segments = 0;
    const KeywordSpec* hand = find_keyword(header, &hand_segments);
    const KeywordSpec* made = find_generated(header, &generated_segments);
    if (!made) made = find_by_characters(header, &generated_segments);
    bool hand_known = false;
    if (hand) {
        // The matched prefix: the header's first hand_segments segments.
        std::size_t end = 0;
        for (std::size_t s = 0; s < hand_segments && end < header.size(); ++s) {
            end = header.find('/', end + 1);
            if (end == std::string_view::npos) end = header.size();
        }
        const std::string_view prefix = header.substr(0, end);
        hand_known = generated_named(prefix) || !has_generated_below(prefix);
    }
    out.known = out.known || hand_known || made;
    if (hand && (hand->decoded || !made || hand_segments > generated_segments)) {
        out.spec = hand;
        out.prefix_segments = hand_segments;
    } else if (made) {
        out.spec = made;
        out.prefix_segments = generated_segments;
    }
    out.cards = out.spec;
    if (out.spec == hand && hand && made && generated_segments > hand_segments &&
        (keeps_text_only(*hand) || (hand->fallback && checks_cards(*made))))
        out.cards = made;
    return out;
}
}  // namespace

bool is_engine_only_key(std::string_view header) {
    if (!is_engine_key(header)) return false;
    static const std::vector<std::string> starter_firsts = [] {
        std::vector<std::string> out;
        const auto first = [](std::string_view name) {
            const auto segments = path_segments(name);
            return segments.empty() ? std::string() : std::string(segments.front());
        };
        for (const generated::LayoutEntry& k : generated::layouts())
            if (!generated::is_engine_entry(k)) out.push_back(first(k.name));
        for (const KeywordSpec& k : all_keywords())
            if (!k.engine) out.push_back(first(k.name));
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }();
    // The engine keywords' first segments in full (the engine itself compares five characters).
    static const std::vector<std::string> engine_firsts = [] {
        std::vector<std::string> out;
        for (const generated::LayoutEntry& k : generated::layouts())
            if (generated::is_engine_entry(k)) out.push_back(std::string(path_segments(k.name).front()));
        for (const KeywordSpec& k : all_keywords())
            if (k.engine) out.push_back(std::string(path_segments(k.name).front()));
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }();
    const auto segments = path_segments(header);
    if (segments.empty()) return false;
    const std::string first(segments.front());
    if (std::binary_search(starter_firsts.begin(), starter_firsts.end(), first)) return false;
    if (std::binary_search(engine_firsts.begin(), engine_firsts.end(), first)) return true;
    // No engine keyword has this first segment in full, and its five characters begin a starter keyword's
    // (/FUNCTT, /INTERR): a starter keyword mistyped, not an engine one out of place.
    const std::string_view key = std::string_view(first).substr(0, 5);
    return std::none_of(starter_firsts.begin(), starter_firsts.end(),
                        [&](const std::string& s) { return std::string_view(s).substr(0, 5) == key; });
}

bool is_engine_key(std::string_view header) {
    if (header.size() < 2 || header[0] != '/') return false;
    std::string_view first = header.substr(1, header.find('/', 1) == std::string_view::npos ? std::string_view::npos
                                                                                            : header.find('/', 1) - 1);
    first = first.substr(0, 5);
    return std::find(engine_keys.begin(), engine_keys.end(), first) != engine_keys.end();
}

std::vector<std::string> options_below(std::string_view family) {
    std::vector<std::string> out;
    const std::string below = std::string(family) + '/';
    const auto all = generated::layouts();
    auto it = std::lower_bound(all.begin(), all.end(), std::string_view(below),
                               [](const generated::LayoutEntry& k, std::string_view n) { return k.name < n; });
    for (; it != all.end() && it->name.substr(0, below.size()) == below; ++it) {
        const std::string_view rest = it->name.substr(below.size());
        std::string option(rest.substr(0, rest.find('/')));
        if (out.empty() || out.back() != option) out.push_back(std::move(option));
    }
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::optional<std::string> suggest_keyword(std::string_view name) {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const generated::LayoutEntry& k : generated::layouts()) out.emplace_back(k.name);
        for (const KeywordSpec& k : all_keywords()) {
            if (!has_generated_below(k.name) || generated_named(k.name)) out.emplace_back(k.name);
            for (std::string_view alias : k.aliases) out.emplace_back(alias);
        }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }();
    // Remembered per thread, as keywords::suggest_keyword does: a deck checked again asks again.
    constexpr std::size_t max_remembered = 4096;
    thread_local std::unordered_map<std::string, std::optional<std::string>> remembered;
    const std::string key(name);
    if (const auto it = remembered.find(key); it != remembered.end()) return it->second;
    auto best = closest_names(name, names);
    std::optional<std::string> answer;
    if (!best.empty()) answer = std::string(best.front());
    if (remembered.size() >= max_remembered) remembered.clear();
    remembered.emplace(key, answer);
    return answer;
}

}  // namespace sphdeck::grammar::radioss
