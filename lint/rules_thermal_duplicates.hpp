// REF006 for thermal materials: *MAT_THERMAL_... blocks (the TMID a *PART names) have ids of their own,
// apart from the structural materials of model.materials, and two with one id in the same run are a
// duplicate as two *MAT_ELASTIC are (a block pasted twice).
#pragma once

#include "lint/rule_context.hpp"
#include "model/case_blocks.hpp"

namespace sphdeck::lint {

void check_thermal_material_duplicates(RuleContext& c, const model::CaseBlocks& cases);

}  // namespace sphdeck::lint
