// DK010 "include file not found" for both readers: each path tried once with the search rule that
// gave it, a file of a similar name in the folders searched (did you mean, with an unsafe fix), and
// how to add a folder to the search (-I DIR, include-paths, *INCLUDE_PATH).
#pragma once

#include <string>

#include "diag/diagnostic.hpp"
#include "grammar/dyna/include_resolver.hpp"

namespace sphdeck::grammar::dyna {

// `where`: the file name as written on one line (the fix replaces it); `continued`: the name runs
// over several lines (no fix). `radioss`: the deck is an OpenRadioss deck (no *INCLUDE_PATH there).
diag::Diagnostic include_not_found(const std::string& name, Span where, const IncludeSearch& search, bool continued,
                                   bool radioss);

}  // namespace sphdeck::grammar::dyna
