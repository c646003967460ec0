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

// Every generated keyword as a KeywordSpec (sorted by name; `generated` set): formats newest
// first, each ending in an unchecked card where the generator could not follow the CFG, and an
// unchecked format below the oldest one (deck versions no CFG format reads). Builds them all.
std::span<const KeywordSpec> keywords();

// The generated keyword of exactly this name, built at its first use only (a check reads a few
// dozen of the 1,629); nullptr when no entry has the name.
const KeywordSpec* keyword_named(std::string_view name);

// Whether an entry is an engine keyword (its flags line), without building it.
bool is_engine_entry(const LayoutEntry& entry);

// Whether a generated card read once is present, by its condition ("Ifail!0&Itype=1": fields of
// earlier cards compared with numbers); true for a card without one.
bool condition_holds(std::string_view condition, const EarlierValues& earlier);

}  // namespace sphdeck::grammar::radioss::generated
