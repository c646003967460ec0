// The dam break's numerical cross-check (docs/verification.md §3, "Against another SPH code"): the dam
// break of Marrone et al. (2011) run by our solver (decks/verification/make_dam_break_marrone.py), its front
// measured as TrixiParticles measures it (the largest x over all fluid particles) and compared with
// TrixiParticles' own WCSPH and EDAC results at the same resolution (verify/trixi_dam_break.hpp). Two codes
// solving the same idealised problem: no experimental gate, no uncertainty about when the water was let go.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "io/svg_plot.hpp"
#include "verify/case_result.hpp"
#include "verify/trixi_dam_break.hpp"

namespace sphdeck::verify {

enum class TrixiScheme { Wcsph, Edac };

// TrixiParticles' front [m] in `row` for `per_height` particles across H; nullopt unless 40 or 80.
std::optional<double> trixi_front(const TrixiFrontRow& row, int per_height, TrixiScheme scheme);

struct FrontComparison {
    double T = 0;       // t sqrt(g / H)
    double ours = 0;    // max x / H
    double theirs = 0;  // max x / H
};

// Our front (samples of max x [m] at ascending T) against theirs at every tabulated T in (0, last_T],
// interpolated linearly between our samples; rows our samples do not reach are left out.
std::vector<FrontComparison> compare_with_trixi(std::span<const double> T, std::span<const double> max_x,
                                                int per_height, TrixiScheme scheme, double last_T);

// Runs the cross-check decks (quick: H/40; full: H/40 and H/80) and adds their runs, gated checks, method
// lines and a plot panel to `result`. False when a deck did not run or its run was stopped.
bool add_trixi_cross_check(CaseResult& result, const CaseOptions& options, std::vector<io::PlotPanel>& panels);

}  // namespace sphdeck::verify
