#include "model/case_blocks.hpp"

namespace sphdeck::model {

void track_case(std::string_view keyword, std::string& current) {
    constexpr std::string_view begin = "*CASE_BEGIN_";
    if (keyword.substr(0, begin.size()) == begin)
        current = std::string(keyword.substr(begin.size()));
    else if (keyword.substr(0, 9) == "*CASE_END")
        current.clear();
}

CaseBlocks::CaseBlocks(const grammar::RawDeck& deck) : deck_(deck) {
    bool any = false;
    for (const grammar::Block& b : deck.blocks) any = any || b.keyword.rfind("*CASE_BEGIN_", 0) == 0;
    if (!any) return;
    std::string current;
    case_of_block_.reserve(deck.blocks.size());
    for (const grammar::Block& b : deck.blocks) {
        track_case(b.keyword, current);
        case_of_block_.push_back(current);  // blocks of an included file follow its *INCLUDE
    }
}

std::string_view CaseBlocks::case_of(const grammar::Span& where) const {
    if (case_of_block_.empty()) return {};
    // The block holding `where`: the last one of its file starting at or before its line.
    std::string_view found;
    for (std::size_t i = 0; i < deck_.blocks.size(); ++i) {
        const grammar::Span& s = deck_.blocks[i].span;
        if (s.file == where.file && s.line <= where.line) found = case_of_block_[i];
    }
    return found;
}

}  // namespace sphdeck::model
