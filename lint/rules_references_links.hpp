// REF001-REF004, REF008 and REF009 for the ids that generated keywords name (model/id_links.hpp):
// each id of a followed kind against the deck's definitions of that kind.
#pragma once

#include <set>

#include "lint/rule_context.hpp"

namespace sphdeck::lint {

// Reports every followed id no definition of its kind holds; adds the boxes named to `boxes`
// (REF007 says which boxes no keyword names). Run only when no include is missing.
void check_followed_references(RuleContext& c, std::set<model::Id>& boxes);

}  // namespace sphdeck::lint
