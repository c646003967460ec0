// Arguments on the *KEYWORD line: `*KEYWORD 100m memory2=20m long=y i10=y ncpu=4`.
#pragma once

#include <string_view>

#include "grammar/raw_deck.hpp"

namespace sphdeck::grammar::dyna {

// Parses the text after "*KEYWORD" (case-insensitive names; a bare first value is the memory).
KeywordArguments parse_keyword_arguments(std::string_view text);

}  // namespace sphdeck::grammar::dyna
