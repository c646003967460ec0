// The two text renderers of diagnostics: concise one-liners for scripts and editors, and full
// rustc/clang-style code frames for people. Both return text; printing is the caller's business.
#pragma once

#include <string>
#include <string_view>

#include "diag/diagnostic.hpp"
#include "text/source_map.hpp"

namespace sphdeck::diag {

struct RenderOptions {
    bool colour = false;  // ANSI escapes; see colour_wanted()
};

// file:line:col: severity: message [CODE]
// plus one "file:line:col: note: message" line per note that has a location; every line ends in '\n'.
// Without a location: "sphdeck: severity: message [CODE]". Never coloured.
std::string render_concise(const Diagnostic& d, const text::SourceMap& sources);

// A code frame:
//   error[DK010]: include file 'x.k' not found
//     --> main.k:12:1
//      |
//   12 | parts.k
//      | ^^^^^^^
//      = note: included from main.k:3      (one per include level, innermost first)
// then each note in order: with a location, an excerpt headed "note: message"; without, "= note: message".
// Excerpts expand tabs (stop 8), show unprintable bytes as '?' and window long lines (~200 columns).
std::string render_full(const Diagnostic& d, const text::SourceMap& sources, const RenderOptions& options);

// True only when the descriptor is a terminal and NO_COLOR is unset or empty (https://no-color.org).
bool colour_wanted(int file_descriptor);

namespace detail {
// Whether a span can be shown: valid and naming a file of `sources`.
bool has_location(const text::Span& span, const text::SourceMap& sources);
// The name shown for a file: display_name, falling back to path.
std::string file_name(const text::SourceFile& file);
// "file:line:col" of a span that has_location().
std::string location(const text::Span& span, const text::SourceMap& sources);
// Control bytes replaced by '?': a message stays on one line and cannot drive the terminal.
std::string printable(std::string_view text);
}  // namespace detail

}  // namespace sphdeck::diag
