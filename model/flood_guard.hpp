// A safety bound, not a presentation: every finding reaches every output format (the text formats
// fold long runs themselves, cli/text_folding.cpp), but a pathological block of 10^7 broken lines
// must not hold 10^7 findings in memory. Past `kept_per_code` findings of one code on the lines of
// one block, the rest are dropped and counted in the last one kept (issue 13 class 7, issue 25 item 5).
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"

namespace sphdeck::model {

inline constexpr std::size_t kKeptPerCodePerBlock = 100000;

// Findings of one code on the lines of one block beyond the first `kept` are dropped; the last one
// kept says how many were dropped and names the first of their lines. Works on out[from, end).
void collapse_block_floods(std::vector<diag::Diagnostic>& out, std::size_t from, std::string_view keyword,
                           std::size_t kept = kKeptPerCodePerBlock);

}  // namespace sphdeck::model
