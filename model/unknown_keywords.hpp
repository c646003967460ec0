// DK001 for LS-DYNA decks, by the policy of grammar/keywords/keyword_names.hpp: a keyword name no source
// knows is an error at its line (LS-DYNA stops at a keyword it does not know), with the closest known name
// as an unsafe fix; a known keyword with options the tables do not lay out is a warning; a name known
// without a layout (the manual's, OpenRadioss' Keyword971 names) is an info, once per name.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

class UnknownKeywords {
public:
    // One block whose keyword no table matched.
    void add(const grammar::RawDeck& deck, const grammar::Block& block, std::vector<diag::Diagnostic>& out);
    // The infos for keywords known without a layout, once per name, with their block counts.
    void finish(std::vector<diag::Diagnostic>& out) const;

private:
    const std::optional<std::string>& suggestion(const std::string& keyword);

    struct Unchecked {
        grammar::Span first;
        std::size_t count = 0;
    };
    std::map<std::string, Unchecked> unchecked_;
    std::map<std::string, std::optional<std::string>> suggestions_;  // per name: suggested once
};

}  // namespace sphdeck::model
