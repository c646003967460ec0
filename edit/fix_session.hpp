// `sphdeck check --fix`: apply the findings' fixes to a deck and its include files in rounds, as ruff
// does: apply the fixes that do not overlap, check again, repeat until no fix applies (or a bound is
// reached), then the findings that remain. Everything happens on texts held in memory (laid over the
// disk with engine::Documents); the caller writes the changed files or prints their diff.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "edit/fix_choice.hpp"
#include "engine/check.hpp"

namespace sphdeck::edit {

struct FixedFile {
    std::string path;      // as the reader first opened it (SourceFile::path of its first instance)
    std::string original;  // the text before the first round
    std::string fixed;     // after the last; differs from `original`
};

struct FixOutcome {
    engine::CheckResult remaining;  // the check of the fixed texts: the findings no fix mended
    std::vector<FixedFile> files;   // the files that changed, in the order first changed
    std::size_t fixed = 0;          // fixes applied over all rounds
    std::size_t rounds = 0;         // rounds that applied at least one fix
};

inline constexpr std::size_t max_fix_rounds = 10;

// Checks the deck at `path` (its texts from `documents` where they hold them, else from disk), applies
// the fixes `level` allows, and checks again, up to `max_rounds` rounds. `documents` receives the fixed
// texts, so several decks fixed in one run see each other's mended include files. Throws as
// engine::check_deck does when the deck cannot be read.
FixOutcome fix_deck(const std::string& path, engine::Documents& documents, const engine::CheckOptions& options,
                    FixLevel level, std::size_t max_rounds = max_fix_rounds);

// Per-line edits that turn `original` into `fixed`, for edit::unified_diff; each changed line is
// replaced whole, a line a fix inserted (DK032's blank heading) joins the old line below it. None when
// `fixed` has fewer lines (fixes never remove a line).
std::vector<diag::TextEdit> line_edits_between(std::string_view original, std::string_view fixed);

}  // namespace sphdeck::edit
