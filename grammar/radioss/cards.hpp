// Radioss card layouts as data (radioss-format.md §2, §3, §5): per keyword, its formats by
// version, per format its cards, per card its fields. A field names its cell kind only; the
// width follows the deck's format version (Invers on /BEGIN): from format 51 on, integers and
// short text are 10 characters and reals 20, in V4 decks (format 44 and older) 8 and 16.
// Defaults are not here: what the starter does with a blank or zero is decoding logic
// (model/radioss_decoder.cpp), because it differs per field and per version.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "grammar/fields.hpp"

namespace sphdeck::grammar::radioss {

enum class Cell : std::uint8_t {
    Int,     // %10d (%8d in V4)
    Real,    // %20lg (%16lg)
    Text,    // %10s (%8s)
    Text20,  // %20s (%16s): unit names of /BEGIN
    Line,    // the whole line: titles, run names, cards sphdeck keeps as text
    Skip,    // an unused %10s cell (%8s)
    Skip20,  // an unused %20s cell (%16s)
};

struct FieldSpec {
    std::string_view name = {};
    Cell cell = Cell::Int;
    // A literal width the CFG format spells out (`%8d          %8d`: ten blanks even in V4);
    // 0: the cell's width in the deck's version.
    std::uint32_t width = 0;
    // What a blank or 0 means and which values the starter takes, as its reader decides them
    // (shown by `sphdeck keyword`; the decoding itself lives in model/).
    std::string_view note = {};
    // The kind of id the cell names, from the CFG's ATTRIBUTES (generated layouts only): 'F' a
    // function or table, 'S' a sensor, 'Y' a skew or frame, 'G' a node group, 'U' a surface, 'M' a
    // material, 'P' a property, 'C' a part; 0 none.
    char link = 0;
};

enum class Repeat : std::uint8_t {
    Once,      // one line; an absent card takes every default
    Repeated,  // one line each until the block ends (a trailing group repeats together)
};

// The numbers read on the cards before a card, by field name (0 when blank, absent or text).
class EarlierValues {
public:
    virtual double operator()(std::string_view field) const = 0;

protected:
    ~EarlierValues() = default;
};
// Whether a card read once is in the deck, decided by the cards before it (CFG `if(Itype == 1)`).
using CardCondition = bool (*)(const EarlierValues& earlier);

struct CardSpec {
    std::vector<FieldSpec> fields = {};
    Repeat repeat = Repeat::Once;
    // A LIST card of a repeated group (CFG `LIST("%20lg", V, nvarsph)`): as many values as the
    // integer field `count` of the group's first card says, fields.size() a line, no line for 0.
    std::string_view count = {};
    // A card read once only when this holds (nullptr: always); `condition` says it in words.
    CardCondition present_if = nullptr;
    std::string_view condition = {};
    // A generated card's condition as data ("Ifail!0&Itype=1", generated::condition_holds);
    // empty: none. `condition` says the same for `sphdeck keyword`.
    std::string_view when = {};

    const FieldSpec* field(std::string_view name) const;
    std::size_t index(std::string_view name) const;  // fields.size() when absent
};

struct FormatSpec {
    int since = 0;  // the lowest deck version (Invers) that reads cards in this format
    std::vector<CardSpec> cards = {};
};

struct KeywordSpec {
    std::string_view name = {};                  // canonical header prefix: "/PROP/SPH"
    std::vector<std::string_view> aliases = {};  // other prefixes read alike: "/PROP/TYPE34"
    bool title = true;                           // a title line follows the header (format 51 and later)
    bool engine = false;                         // an engine keyword: list-directed (free) data lines
    bool decoded = true;                         // false: known, kept as is (structural or not needed)
    // Text past the last field is reported (DK006) as the starter's reader does (100213/100214);
    // false where the starter's listing shows it reads such text silently.
    bool trailing_checked = true;
    // The keyword family a law-specific table belongs to ("/MAT" for "/MAT/LAW2"): the builder
    // handles it as the family, and the header's segments after the family are its arguments.
    std::string_view family = {};
    std::string_view summary = {};
    std::string_view source = {};  // where the layout comes from (CFG files of the starter)
    bool generated = false;        // from generated/radioss_layouts.cpp, not written by hand
    // A family's generic reading (/MAT: the density card of any law): where the starter's CFG files
    // lay out the law, its generated cards are checked instead and the builder reads their values
    // by name (keyword_lookup.cpp).
    bool fallback = false;
    std::vector<FormatSpec> formats = {};  // newest first

    // The format a deck of version `version` reads: the newest one not above it (the reader's
    // cascade 2026 → 2025 → … → 51 → 44 → 41), or the oldest one.
    const FormatSpec& format_for(int version) const;
};

inline constexpr int latest_version = 2026;
inline bool is_v4(int version) { return version < 51; }

// Width of a cell in a deck of this version.
std::uint32_t cell_width(Cell cell, int version);
// Characters of a line the starter reads: 100, or 80 in V4 decks.
std::uint32_t line_width(int version);

// Column positions of a card's fields in a deck of this version (Line cells: to the line end).
std::vector<FixedField> layout(const CardSpec& card, int version);

// The keyword reading a header path (upper case, "/PROP/TYPE34/7"): the longest name or alias
// that matches whole leading path segments. `prefix_segments` receives how many segments it
// matched (2 for /PROP/SPH), so the caller can read the ids and options that follow.
const KeywordSpec* find_keyword(std::string_view header, std::size_t* prefix_segments = nullptr);

// Every keyword, for `sphdeck keyword` style listings and tests.
std::span<const KeywordSpec> all_keywords();

// The segments of a header path: "/PROP/SPH/7" → {"PROP", "SPH", "7"}.
std::vector<std::string_view> path_segments(std::string_view header);

namespace detail {
// The tables, one file per family (cards_*.cpp).
void add_mesh_keywords(std::vector<KeywordSpec>& out);      // /BEGIN, /NODE, /PART, elements, groups, frames
void add_property_keywords(std::vector<KeywordSpec>& out);  // /PROP/SPH, /PROP/TYPE14, /PROP/TYPE6, /EOS
void add_material_keywords(std::vector<KeywordSpec>& out);  // /MAT and the laws sphdeck reads
void add_sph_keywords(std::vector<KeywordSpec>& out);       // /SPHCEL, /SPHGLO, /SPHBCS, /SPH/..., engine /DT
}  // namespace detail

}  // namespace sphdeck::grammar::radioss
