// The mechanical fix of a fixed-format card whose values stray over their columns (DK002, DK003:
// "1.0E-3" starting in column 6 of a 10-column field runs into the next one): each value moved
// into the field that holds most of its characters, right-aligned (text left-aligned). Offered
// only when that is certain: every value fits its field, no two values claim one field, no value
// is shared equally by two fields, the line is neither free format nor tabbed, and every moved
// value reads as its field's type.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "grammar/keywords/schema.hpp"

namespace sphdeck::grammar {

// The realigned line, or nullopt when nothing strays or the fix is not certain.
std::optional<std::string> realign_card(std::string_view text, const keywords::CardSpec& card,
                                        grammar::CardFormat format);

}  // namespace sphdeck::grammar
