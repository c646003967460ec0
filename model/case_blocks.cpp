#include "model/case_blocks.hpp"

#include <algorithm>

namespace sphdeck::model {

void track_case(std::string_view keyword, std::string& current) {
    constexpr std::string_view begin = "*CASE_BEGIN_";
    if (keyword.substr(0, begin.size()) == begin)
        current = std::string(keyword.substr(begin.size()));
    else if (keyword.substr(0, 9) == "*CASE_END")
        current.clear();
}

CaseBlocks::CaseBlocks(const grammar::RawDeck& deck) {
    bool any = false;
    for (const grammar::Block& b : deck.blocks) any = any || b.keyword.rfind("*CASE_BEGIN_", 0) == 0;
    if (!any) return;
    std::string current;
    case_of_block_.reserve(deck.blocks.size());
    starts_.reserve(deck.blocks.size());
    for (std::size_t i = 0; i < deck.blocks.size(); ++i) {
        const grammar::Block& b = deck.blocks[i];
        track_case(b.keyword, current);
        case_of_block_.push_back(current);  // blocks of an included file follow its *INCLUDE
        starts_.emplace_back(b.span.file, b.span.line, i);
    }
    std::sort(starts_.begin(), starts_.end());
}

std::string_view CaseBlocks::case_of(const grammar::Span& where) const {
    if (case_of_block_.empty()) return {};
    // The block holding `where`: the last one of its file starting at or before its line (a file's blocks
    // come in the order of their lines).
    const auto after = std::upper_bound(starts_.begin(), starts_.end(),
                                        std::tuple{where.file, where.line, static_cast<std::size_t>(-1)});
    if (after == starts_.begin() || std::get<0>(after[-1]) != where.file) return {};
    return case_of_block_[std::get<2>(after[-1])];
}

}  // namespace sphdeck::model
