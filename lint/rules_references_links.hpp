// REF001-REF004, REF008 and REF009 for the ids that generated keywords name (model/id_links.hpp):
// each id of a followed kind against the deck's definitions of that kind.
#pragma once

#include <set>
#include <unordered_set>

#include "lint/rule_context.hpp"

namespace sphdeck::lint {

// Reports every followed id no definition of its kind holds; adds the boxes named to `boxes`
// (REF007 says which boxes no keyword names). Run only when no include is missing.
void check_followed_references(RuleContext& c, std::set<model::Id>& boxes);

// Whether a keyword of the deck defines id `id` of `kind` ("SET_NODE", "SET_PART"...), read from
// the first field of its first card whatever the keyword's form (*SET_NODE_GENERAL, _ADD, _LIST...),
// or the kind has a definition whose id is not a number (a label, &name): it may be that one.
bool deck_may_define(const grammar::RawDeck& deck, std::string_view kind, long long id);
// The ids the deck's keywords define of `kind`, read as deck_may_define reads them (one pass over the blocks:
// for a rule that looks many ids up).
struct DefinedIds {
    std::unordered_set<long long> ids;
    bool unreadable = false;  // a definition whose id is not a number (&name, a label): the kind is not judged
};
DefinedIds defined_ids(const grammar::RawDeck& deck, std::string_view kind);

}  // namespace sphdeck::lint
