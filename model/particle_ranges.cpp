#include "model/particle_ranges.hpp"

#include <fmt/format.h>

#include "grammar/keywords/schema.hpp"

namespace sphdeck::model {

std::size_t node_lines(const grammar::RawDeck& deck) {
    std::size_t lines = 0;
    for (const grammar::Block& block : deck.blocks) {
        if (block.keyword.size() < 5) continue;
        const auto match = keywords::find_keyword(block.keyword);
        if (match && match->schema->name == "*NODE") lines += block.line_count;
    }
    return lines;
}

std::size_t range_extra(const std::vector<FieldValue>& v) {
    // NEND > NID generates NID..NEND with the same part and mass (lsdyna-sph-cards.md §3). Both
    // are integers within 2^53 once decoded (the decoder refuses larger ones), so the
    // difference is exact and fits.
    if (v.size() < 4 || !v[0].valid || !v[3].valid || !v[3].explicit_value || !(v[3].number > v[0].number)) return 0;
    return static_cast<std::size_t>(v[3].number - v[0].number);
}

std::size_t RangeBudget::nodes() {
    if (!nodes_) nodes_ = node_lines(deck_);
    return *nodes_;
}

std::optional<std::string> RangeBudget::check_alone(std::size_t extra) {
    if (extra == 0) return std::nullopt;
    if (extra + 1 > nodes())
        return fmt::format("NEND asks for a range of {} particles; the deck defines {} node(s)", extra + 1, nodes());
    return std::nullopt;
}

std::optional<std::string> RangeBudget::take(std::size_t extra) {
    if (auto problem = check_alone(extra)) return problem;
    if (extra == 0) return std::nullopt;
    // Twice the nodes: ranges that overlap or run past the last node stay REF006 and REF001
    // findings; only beyond that is the deck asking for memory it cannot mean.
    if (spent_ + extra + 1 > 2 * nodes())
        return fmt::format(
            "NEND asks for a range of {} particles; with the ranges before it that is more than "
            "twice the {} node(s) the deck defines",
            extra + 1, nodes());
    spent_ += extra + 1;
    return std::nullopt;
}

diag::Diagnostic range_error(grammar::Span nend, const std::string& problem) {
    return {"DK007", diag::Severity::Error, problem + "; the range is not generated", nend, {}};
}

}  // namespace sphdeck::model
