// A misspelt keyword that the model would have read (*CONTROL_SHP for *CONTROL_SPH, *PRAT for *PART)
// leaves settings at their defaults or ids undefined, and rules then report the symptoms far from the
// cause (a particle mass that looks like a unit mistake, a part without its section). Each such finding
// gets a note pointing at the unknown keyword (DK001), so the cause is not drowned by its consequences.
#pragma once

#include <vector>

#include "diag/diagnostic.hpp"

namespace sphdeck::lint {

// Adds the note to the model rules' findings (REF, SPH, RAD codes) when `diagnostics` hold a DK001
// error whose suggested keyword is one the model reads (a hand-written table).
void point_to_misspelt_keywords(std::vector<diag::Diagnostic>& diagnostics);

}  // namespace sphdeck::lint
