// *CASE_BEGIN_n ... *CASE_END_n (LS-DYNA manual, *CASE): the keywords between are read only when
// case n runs, the rest of the deck in every case. Two definitions clash only within one run: both
// in the common part, one common and one in a case block, or both in the same case block.
#pragma once

#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// The case a block opens (*CASE_BEGIN_n: "n") or closes (*CASE_END...: ""), folded into `current`.
void track_case(std::string_view keyword, std::string& current);

// Whether definitions in cases `a` and `b` ("" = every case) are read in one run.
inline bool same_run(std::string_view a, std::string_view b) { return a.empty() || b.empty() || a == b; }

// The case of any location of a deck, from its blocks.
class CaseBlocks {
public:
    explicit CaseBlocks(const grammar::RawDeck& deck);
    // "n" inside a *CASE_BEGIN_n block, else "" (also for decks without cases: no search then).
    std::string_view case_of(const grammar::Span& where) const;
    // Whether the deck has any *CASE_BEGIN_n block.
    bool any() const { return !case_of_block_.empty(); }

private:
    std::vector<std::string> case_of_block_;  // empty when the deck has no case block
    // Each block's (file, first line) and index, sorted: case_of is a binary search (rules ask it per part).
    std::vector<std::tuple<grammar::FileId, std::uint32_t, std::size_t>> starts_;
};

}  // namespace sphdeck::model
