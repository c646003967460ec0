// The unified diff `--diff` prints (for `check --fix` and `format`), as `diff -u` would print it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"

namespace sphdeck::edit {

// The diff of `text` against `text` with `edits` applied (placed as apply_edits places them), with
// three lines of context and `--- a/PATH` / `+++ b/PATH` headers; empty when no edit changes a byte.
// It is built from the edits themselves, line by line, so it is exact and linear in the file's size
// however many lines change (a general diff algorithm is quadratic when every line of a deck changes).
std::string unified_diff(std::string_view path, std::string_view text, const std::vector<diag::TextEdit>& edits);

}  // namespace sphdeck::edit
