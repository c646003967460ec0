// `sphdeck check --format github`: GitHub Actions workflow commands, one annotation per finding:
//   ::error file=F,line=L,col=C,endColumn=E,title=CODE::message
// (::warning, ::notice for info). Escaping as actions/toolkit does (linter-conventions.md §6.5).
#pragma once

#include <string>
#include <string_view>

#include "diag/diagnostic.hpp"
#include "text/source_map.hpp"

namespace sphdeck::diag {

// One line ending in '\n'; notes with a location follow the message as "note: file:line:col: text".
// Without a location the file, line and column properties are left out.
std::string render_github(const Diagnostic& d, const text::SourceMap& sources);

// Message text: % -> %25, CR -> %0D, LF -> %0A.
std::string github_escape_data(std::string_view text);
// Property values: as data, and also : -> %3A, , -> %2C.
std::string github_escape_property(std::string_view text);

}  // namespace sphdeck::diag
