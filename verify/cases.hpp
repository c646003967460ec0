// The verification cases of `sphdeck verify` (verification.md §1-3), each a small function that runs its
// decks through the reference solver and compares them with the exact or experimental reference.
#pragma once

#include <string_view>
#include <vector>

#include "verify/case_result.hpp"

namespace sphdeck::verify {

// Sod shock tube (§1): L1 errors of rho, u, p at two resolutions, wave positions, convergence order.
CaseResult run_sod(const CaseOptions& options);
// Hydrostatic water column (§2): pressure against rho0 g (H - y), bottom pressure, residual kinetic energy.
CaseResult run_hydrostatic(const CaseOptions& options);
// Dam break (§3): surge-front position against Martin & Moyce (1952) and Koshizuka & Oka (1996).
CaseResult run_dam_break(const CaseOptions& options);
// Sedov-Taylor blast wave (§4): shock radius and peak density at two resolutions, energy conservation.
CaseResult run_sedov(const CaseOptions& options);
// Noh implosion (§5): post-shock density and shock radius of a converging shock at two resolutions.
CaseResult run_noh(const CaseOptions& options);
// OpenRadioss's QA case WavesCompression (§6): energies and time steps against the engine's listing.
CaseResult run_radioss_waves(const CaseOptions& options);

struct VerificationCase {
    std::string_view name;  // as typed on the command line
    std::string_view summary;
    CaseResult (*run)(const CaseOptions&);
};

// In the order `sphdeck verify all` runs them.
const std::vector<VerificationCase>& verification_cases();

}  // namespace sphdeck::verify
