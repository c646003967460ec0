// Thermal materials: *MAT_THERMAL_... blocks (the TMID a *PART names) have ids of their own, apart from the
// structural materials of model.materials. REF006: two with one id in the same run are a duplicate as two
// *MAT_ELASTIC are (a block pasted twice); their ids, for REF004 on a TMID (lint/rules_references.cpp).
#pragma once

#include <set>

#include "lint/rule_context.hpp"
#include "model/case_blocks.hpp"

namespace sphdeck::lint {

void check_thermal_material_duplicates(RuleContext& c, const model::CaseBlocks& cases);

// The ids the deck's *MAT_THERMAL_... blocks define, as a part's TMID names them (model::normalise_id);
// `unreadable` when one is not a plain integer (a parameter, a label, free format): it may define any id.
struct ThermalMaterialIds {
    std::set<model::Id> ids;
    bool unreadable = false;
};
ThermalMaterialIds thermal_material_ids(const grammar::RawDeck& deck);

}  // namespace sphdeck::lint
