// Inline suppression comments (linter-conventions.md §4.2), read from the deck's comment lines:
//
//   $ sphdeck: disable=SPH032,form-advice -- reason
//       silences those rules on the next non-comment line; when that line is a keyword line, on its
//       whole block (the keyword line up to the next keyword line of the same file)
//   $ sphdeck: disable-next-line=DK004 -- reason    the next non-comment line only
//   $ sphdeck: disable-file=RAD020 -- reason        the whole file the comment stands in
//
// Codes or rule names, comma-separated; `all` names every rule. A directive applies to its own file
// only, never to files it includes. The text after `--` is for people.
//
// Radioss decks (radioss-format.md §2) also take the directives after `#`, their other comment
// character, and their blocks start at `/` header lines. In LS-DYNA decks `#` is no comment, so
// a `# sphdeck:` line there is data and no directive.
#pragma once

#include <functional>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/read_deck.hpp"  // DeckFormat
#include "text/source_map.hpp"

namespace sphdeck::lint {

struct SuppressionItem {
    std::string code;                          // canonical rule code, or "all"
    std::uint32_t column = 0, end_column = 0;  // where the item stands on the comment line
};

struct Suppression {
    enum class Scope { NextBlock, NextLine, File } scope = Scope::NextBlock;
    std::uint32_t line = 0;  // the comment line
    std::vector<SuppressionItem> items;
};

// Parses one comment line. Returns false when the line is no directive (does not start with
// "$ sphdeck:" or "# sphdeck:"; the caller decides which lines are comments); otherwise fills `out` with the valid
// items and `problems` with DK028 findings for the rest (their spans carry `file` and `line`).
bool parse_suppression(std::string_view comment, grammar::FileId file, std::uint32_t line, Suppression& out,
                       std::vector<diag::Diagnostic>& problems);

// Drops the diagnostics that directives silence, then adds DK026 for every directive item that
// silenced nothing and DK028 for malformed directives. Keeps the diagnostics sorted by location.
// `format` says which lines are comments and which start blocks.
// `marker_free` (optional, by file id): files known to hold no directive are skipped (true on the
// way in: an editor's re-check knows it of a 100 MB text it read before, edited in a few lines), and
// on the way out it says of every file whether it holds none. `may_hold_directives` (optional) says
// whether a file's text holds `marker` (the word every directive starts with) at all, else the text is
// searched: the decks of one run search a shared include once (engine/shared_preview.hpp).
using DirectiveScan = std::function<bool(const grammar::SourceFile&, std::string_view marker)>;
void apply_suppressions(const grammar::SourceMap& sources, std::vector<diag::Diagnostic>& diagnostics,
                        grammar::DeckFormat format = grammar::DeckFormat::LsDyna,
                        std::vector<bool>* marker_free = nullptr, const DirectiveScan& may_hold_directives = {});
// Whether `text` can hold a directive (the marker every directive starts with occurs in it).
bool may_hold_suppressions(std::string_view text);

}  // namespace sphdeck::lint
