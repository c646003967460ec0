#include "verify/cases.hpp"

namespace sphdeck::verify {

const std::vector<VerificationCase>& verification_cases() {
    static const std::vector<VerificationCase> cases = {
        {"sod", "Sod shock tube against the exact Riemann solution", run_sod},
        {"hydrostatic", "hydrostatic water column against rho0 g (H - y)", run_hydrostatic},
        {"dambreak",
         "dam-break surge front against Martin & Moyce (1952) and Koshizuka & Oka (1996); cross-check with "
         "TrixiParticles",
         run_dam_break},
        {"sedov", "Sedov-Taylor blast wave against the similarity solution", run_sedov},
        {"noh", "Noh implosion (converging shock) against the exact solution", run_noh},
        {"radioss-waves", "OpenRadioss QA case WavesCompression against the OpenRadioss engine's listing",
         run_radioss_waves},
    };
    return cases;
}

}  // namespace sphdeck::verify
