// Applying text edits to one file's text: the one applier of the CLI's --fix and --diff (edit/fix_session,
// edit/unified_diff), `format`, and the engine's re-check of a deck mended (engine/mended_consequences).
// The editor server applies none: it sends the edits, and the editor applies them to its buffer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "text/text_edit.hpp"

namespace sphdeck::text {

// An edit placed on the text: the bytes it replaces and the line they are on.
struct PlacedEdit {
    std::size_t begin = 0, end = 0;            // byte offsets into the text, end exclusive
    std::uint32_t line = 0;                    // 1-based line of `begin`
    const std::string* replacement = nullptr;  // points into the edits given to place_edits
};

struct PlacedEdits {
    std::vector<PlacedEdit> edits;  // in order of position, none overlapping another
    std::size_t skipped = 0;        // overlapped an edit already taken, or named a line that does not exist
};

// Places `edits` (all on the same file; the span's file id is not looked at) on `text`. Lines are 1-based,
// columns 1-based bytes with end_column exclusive, as in every Span. A column past the end of its line
// (before its "\n" or "\r\n") is clamped to the line's end, so "columns 1 to length+1" replaces a whole
// line and keeps its line break. An edit that overlaps one placed before it (in order of position, then
// the order given) is skipped and counted, as ruff does with fixes that touch the same text: one round
// never applies two competing mends; the caller re-checks and tries the rest again.
PlacedEdits place_edits(std::string_view text, const std::vector<TextEdit>& edits);

struct AppliedEdits {
    std::string text;
    std::size_t applied = 0;
    std::size_t skipped = 0;
};

// The text with the placed edits applied.
AppliedEdits apply_edits(std::string_view text, const std::vector<TextEdit>& edits);

}  // namespace sphdeck::text
