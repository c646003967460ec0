// "Did you mean" for any name a person typed (keywords, parameters, file names): a typing distance
// in which swapping two neighbouring letters costs half an ordinary edit, since that is the
// commonest slip (*CONTROL_SHP for *CONTROL_SPH, *PRAT for *PART).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sphdeck::grammar {

// Distance in half edits: an insertion, deletion or substitution costs 2, a swap of neighbours 1.
// `fold_case`: letters compare without case. Past `limit` the answer is only "more than limit"
// (limit + 1): the work stops there, which matters when thousands of names are tried.
std::size_t typing_distance(std::string_view a, std::string_view b, bool fold_case = false,
                            std::size_t limit = static_cast<std::size_t>(-1) / 2);

// The largest distance (half edits) at which `known` still counts as close to what was typed:
// a quarter of its length in edits, at least one edit for names of up to 4 characters, else two.
std::size_t close_enough(std::string_view known);

// The candidates closest to `typed` within close_enough, best first (then alphabetically), at most
// `max`; empty when none is close.
std::vector<std::string> closest_names(std::string_view typed, std::span<const std::string> candidates,
                                       std::size_t max = 1, bool fold_case = false);

}  // namespace sphdeck::grammar
