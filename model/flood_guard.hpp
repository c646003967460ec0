// One block, one finding per kind of mistake repeated on its lines: a *NODE or *ELEMENT_SPH block of
// thousands of lines with one column shifted must not make thousands of findings (issue 13, class 7).
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"

namespace sphdeck::model {

// Findings of one code on the lines of one block, beyond the first `shown`, become one finding at
// the next one that counts them and names the first of their lines. Works on out[from, end).
void collapse_block_floods(std::vector<diag::Diagnostic>& out, std::size_t from, std::string_view keyword,
                           std::size_t shown = 5);

}  // namespace sphdeck::model
