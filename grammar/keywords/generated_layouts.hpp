// The keyword layouts generated from pydyna (scripts/gen_keyword_layouts.py writes
// generated/keyword_layouts.cpp): the fallback for every keyword without a hand-written schema.
// One compact string per keyword, turned into a KeywordSchema only when a deck uses the keyword.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "grammar/keywords/schema.hpp"

namespace sphdeck::keywords::generated {

struct LayoutEntry {
    std::string_view name;  // "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", sorted
    std::string_view body;  // options line, then one line per card (format: the generator's docstring)
};

// Every generated layout, sorted by name.
std::span<const LayoutEntry> layouts();

// The generated layout of an upper-cased name with '*' (options and all: "*SECTION_SHELL_TITLE"):
// the longest base name whose remaining '_' tokens are all its options. nullopt: no such name.
// The schema holds only the cards of the options written; it lives as long as the program.
std::optional<KeywordMatch> find_generated(std::string_view key);

}  // namespace sphdeck::keywords::generated
