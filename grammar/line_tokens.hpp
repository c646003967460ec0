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

// Calls `f(LineToken)` for each run of non-blank characters of `text`, left to right, until `f` returns
// false; allocates nothing (the alignment tally runs on every line the serial walk decodes).
template <class F>
void for_each_token(std::string_view text, F&& f) {
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == ' ') {
            ++i;
            continue;
        }
        LineToken t{i, i, 0};
        while (t.end < text.size() && text[t.end] != ' ') ++t.end;
        i = t.end;
        if (!f(t)) return;
    }
}

// The runs of non-blank characters of `text`, left to right.
std::vector<LineToken> line_tokens(std::string_view text);

// True when `token` would be read without complaint by a field of `type` (a parameter reference
// always is; an Unused field never is).
bool reads_as(std::string_view token, keywords::FieldType type);

}  // namespace sphdeck::grammar
