// Which fixes one round of `check --fix` applies: the findings' fixes (diag::Fix) turned into text
// edits per file path, never two that touch the same text (issue 27 item 1; ruff's rounds).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "text/source_map.hpp"

namespace sphdeck::edit {

enum class FixLevel {
    Safe,    // `--fix`: the fixes marked safe
    Unsafe,  // `--fix --unsafe-fixes`: every fix
};

// The fix of a finding that `level` allows: its first safe fix, or with Unsafe its first fix; nullptr
// when none. A finding's fixes come most likely first (diag::Diagnostic::fixes).
const diag::Fix* chosen_fix(const diag::Diagnostic& d, FixLevel level);

struct FixRound {
    std::map<std::string, std::vector<diag::TextEdit>> edits;  // canonical path -> edits, spans of that file
    std::size_t fixes = 0;     // findings whose fix is taken (findings sharing one fix are each counted)
    std::size_t deferred = 0;  // fixes that touch the text of one taken before: the next round tries them again
    std::size_t unusable = 0;  // fixes that name no file, or (at the safe level) whose replacement holds a line break
};

// Chooses whole fixes, in the findings' order: a fix is taken when none of its edits overlaps an edit
// already taken on the same file (an identical edit, the same fix seen through a second include of
// the file, is not an overlap and is kept once). The files are told apart by their canonical path
// (grammar::canonical_path), so a file included twice, by one name or by two (a symbolic link), gets
// its edits once. The edits of one round are all placed on the text as it was checked, so a
// replacement holding a line break (an inserted line: DK032's blank heading) renumbers nothing the
// round's other edits name; it is taken only at the Unsafe level: adding a line is a judgement.
FixRound choose_fixes(const grammar::SourceMap& sources, const std::vector<diag::Diagnostic>& diagnostics,
                      FixLevel level);

}  // namespace sphdeck::edit
