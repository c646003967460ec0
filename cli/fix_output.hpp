// What `check --fix` and `check --diff` do with the files edit::fix_deck mended: write them in place, or
// print their unified diff.
#pragma once

#include <string>

#include "edit/fix_session.hpp"

namespace sphdeck::cli {

// The path a diff header or message shows: relative to the working directory when inside it.
std::string shown_path(const std::string& path);

// Writes the fixed text over the file (its bytes outside the edits, line endings included, are those
// of the original). Returns an error message, empty on success.
std::string write_fixed_file(const edit::FixedFile& file);

// The file's change as `diff -u` prints it (edit::unified_diff).
std::string fixed_file_diff(const edit::FixedFile& file);

}  // namespace sphdeck::cli
