#include "cli/suggest.hpp"

#include "grammar/similar_names.hpp"

namespace sphdeck::cli {

std::string did_you_mean(std::string_view typed, const std::vector<std::string_view>& candidates) {
    std::string_view best;
    std::size_t best_distance = 3;
    for (auto c : candidates) {
        std::size_t d = grammar::edit_distance(typed, c, grammar::SwapCost::TwoEdits);  // Levenshtein
        if (d < best_distance) best_distance = d, best = c;
    }
    return best.empty() ? std::string() : "; did you mean '" + std::string(best) + "'?";
}

}  // namespace sphdeck::cli
