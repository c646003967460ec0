// DK001's policy for LS-DYNA keyword names (docs/rules/DK001.md): a name is an error only when no source
// knows it. The sources, in the order they are asked:
//   1. the layouts (hand-written and pydyna's), through find_keyword, which also reads the other spellings
//      LS-DYNA accepts for a laid-out keyword (respellings below): cards checked, no DK001;
//   2. names known without a layout: the manual's keywords no table lays out (known_without_layout), the
//      names of OpenRadioss' Keyword971 CFG files (generated/keyword971_names.cpp), names LS-DYNA writes
//      itself (*RVE_INFO): an info, cards not checked;
//   3. the option grammar: a known keyword followed by options LS-DYNA adds across families (_ID, _TITLE,
//      _MPP, _OFFSET, _BEAM_OFFSET, _COLLECT, _LOCAL...) that no table gives it: a warning, cards not checked.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sphdeck::keywords {

namespace generated {
// The LS-DYNA keyword names of OpenRadioss' Keyword971 CFG files, sorted (scripts/gen_keyword971_names.py
// writes generated/keyword971_names.cpp): a second source of names, without layouts.
std::span<const std::string_view> keyword971_names();
}  // namespace generated

// Other spellings of `key` (upper case with '*', no format suffix) that LS-DYNA reads as the same keyword,
// to look up when `key` itself matches no layout: a legacy name rewritten (*SET_SHELL -> *SET_SHELL_LIST,
// *BOUNDARY_PRESCRIBED_MOTION_NODES -> _NODE, *SET_NODE_COLLECT -> *SET_NODE_LIST_COLLECT), and the options
// _ID, _TITLE and _MPP moved to the end (LS-DYNA takes them anywhere among the options:
// *CONTACT_TIED_SHELL_EDGE_TO_SURFACE_ID_BEAM_OFFSET_MPP). Empty when there is none.
std::vector<std::string> respellings(std::string_view key);

// True when a source other than the layouts knows `upper_name` as a whole (source 2 above).
bool known_by_name(std::string_view upper_name);

// The second source: OpenRadioss' Keyword971 names (sorted).
bool is_keyword971_name(std::string_view upper_name);

// Source 3: `upper_name` is a known keyword (laid out or known by name) followed by options of the option
// grammar only. nullopt when it is not.
struct NameWithOptions {
    std::string base;                  // the known keyword
    std::vector<std::string> options;  // the options after it, as written ("ID", "BEAM_OFFSET")
};
std::optional<NameWithOptions> known_with_options(std::string_view upper_name);

}  // namespace sphdeck::keywords
