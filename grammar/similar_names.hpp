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

// What a swap of two neighbouring letters costs, in half edits.
enum class SwapCost : std::size_t {
    Slip = 1,     // half an edit: names a person typed (the typing distance below)
    OneEdit = 2,  // one edit: the optimal string alignment distance
    TwoEdits = 4  // two substitutions: the plain Levenshtein distance
};

// The one edit distance of the project, in half edits: an insertion, deletion or substitution costs 2,
// a swap of neighbours `swap` (by default 1, the typing distance). `fold_case`: letters compare without
// case. Past `limit` the answer is only "more than limit" (limit + 1): the work stops there, which
// matters when thousands of names are tried.
std::size_t typing_distance(std::string_view a, std::string_view b, bool fold_case = false,
                            std::size_t limit = static_cast<std::size_t>(-1) / 2, SwapCost swap = SwapCost::Slip);

// The distance in whole edits (insertions, deletions, substitutions, and swaps of neighbours as `swap`
// says: one edit or two), for suggestions among command names and rule names.
std::size_t edit_distance(std::string_view a, std::string_view b, SwapCost swap);

// The largest distance (half edits) at which `known` still counts as close to what was typed:
// a quarter of its length in edits, at least one edit for names of up to 4 characters, else two.
std::size_t close_enough(std::string_view known);
// The same for any name `length` characters long.
std::size_t close_enough_for_length(std::size_t length);

// The candidates closest to `typed` within close_enough, best first (then alphabetically), at most
// `max`; empty when none is close.
std::vector<std::string> closest_names(std::string_view typed, std::span<const std::string> candidates,
                                       std::size_t max = 1, bool fold_case = false);

}  // namespace sphdeck::grammar
