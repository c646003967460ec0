// The OpenRadioss keyword layouts generated from the starter's CFG files
// (scripts/gen_radioss_layouts.py writes generated/radioss_layouts.cpp): every keyword name the
// CFG files give a HEADER, and the cards of each format where the generator could follow them.
// One compact string per keyword, turned into KeywordSpecs once, at first use.
#pragma once

#include <span>
#include <string_view>

#include "grammar/radioss/cards.hpp"

namespace sphdeck::grammar::radioss::generated {

struct LayoutEntry {
    std::string_view name;  // "/INTER/TYPE7", sorted
    std::string_view body;  // flags line, then one line per format (the generator's docstring)
};

// Every generated entry, sorted by name.
std::span<const LayoutEntry> layouts();

// Every generated keyword as a KeywordSpec (sorted by name; `source` says "CFG"): formats newest
// first, each ending in an unchecked card where the generator could not follow the CFG, and an
// unchecked format below the oldest one (deck versions no CFG format reads).
std::span<const KeywordSpec> keywords();

// Whether a generated card read once is present, by its condition ("Ifail!0&Itype=1": fields of
// earlier cards compared with numbers); true for a card without one.
bool condition_holds(std::string_view condition, const EarlierValues& earlier);

}  // namespace sphdeck::grammar::radioss::generated
