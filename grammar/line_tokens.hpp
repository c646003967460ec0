// The blank-separated runs of characters of a fixed-format line, and whether one reads as a field's
// type: what the realign fix (grammar/realign.hpp) and the shifted-line and field-width diagnosis
// (grammar/shifted_line.hpp) move between fields. Only for lines already known to be odd: never
// on the bulk reading path.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "grammar/keywords/schema.hpp"

namespace sphdeck::grammar {

struct LineToken {
    std::size_t begin = 0, end = 0;  // 0-based [begin, end)
    std::size_t slot = 0;            // the field it is given to, once placed
};

// The runs of non-blank characters of `text`, left to right.
std::vector<LineToken> line_tokens(std::string_view text);

// True when `token` would be read without complaint by a field of `type` (a parameter reference
// always is; an Unused field never is).
bool reads_as(std::string_view token, keywords::FieldType type);

}  // namespace sphdeck::grammar
