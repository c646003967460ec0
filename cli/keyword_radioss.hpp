// `sphdeck keyword` for OpenRadioss cards: a Radioss keyword's formats by deck version, their
// cards and cells as grammar/radioss/cards_*.cpp describe them.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "grammar/radioss/cards.hpp"

namespace sphdeck::cli {

// The Radioss keyword a name reads: "/SPHGLO", "/sph/inout", an alias ("/PROP/TYPE34") or a
// header with ids ("/PROP/SPH/7"); nullptr when none (or no leading '/').
const grammar::radioss::KeywordSpec* find_radioss_keyword(std::string_view name);

// Prints the keyword's formats, cards and cells.
void print_radioss_keyword(const grammar::radioss::KeywordSpec& keyword);

// One --list row per Radioss keyword: its names, and what it is.
std::vector<std::pair<std::string, std::string>> radioss_list_rows();

// "; did you mean /SPHGLO?" for a name close to a Radioss keyword, or empty.
std::string radioss_suggestion(std::string_view name);

}  // namespace sphdeck::cli
