#include "verify/dam_break_cross_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <span>
#include <string>

#include "verify/deck_run.hpp"
#include "verify/norms.hpp"
#include "verify/surge_front.hpp"

namespace sphdeck::verify {
namespace {

constexpr double cross_check_tolerance = 0.03;  // relative, on max x; the codes agree to ~1 % (docs/verification.md §3)
// Gated times: every 0.4 in T, and T = 2.2, the last row before the front reaches the far wall at H/80.
constexpr std::array<double, 6> gated_T = {0.4, 0.8, 1.2, 1.6, 2.0, 2.2};
constexpr double last_compared_T = 2.2;
constexpr double sample_dT = 0.005;      // max x is sampled this often in T (linear in between: error ~1e-6)
constexpr double rule_sample_dT = 0.02;  // our own front rule (§3) is sampled this often

struct Resolution {
    int per_height;  // particles across H
    const char* deck;
};
constexpr Resolution quick_runs[] = {{40, "dam_break_marrone_40.k"}};
constexpr Resolution full_runs[] = {{40, "dam_break_marrone_40.k"}, {80, "dam_break_marrone_80.k"}};

const char* scheme_name(TrixiScheme s) { return s == TrixiScheme::Wcsph ? "WCSPH" : "EDAC"; }

bool is_gated_time(double T) {
    return std::any_of(gated_T.begin(), gated_T.end(), [&](double g) { return std::abs(g - T) < 1e-9; });
}

// Our front over time: max x, and the rule of §3 (near the floor, with a neighbour) less often.
struct FrontSamples {
    double H = 0, W = 0, dx = 0, next_T = 0, next_rule_T = 0;
    std::vector<double> T, max_x, rule_T, rule_x;
};

}  // namespace

std::optional<double> trixi_front(const TrixiFrontRow& row, int per_height, TrixiScheme scheme) {
    const bool wcsph = scheme == TrixiScheme::Wcsph;
    if (per_height == 40) return wcsph ? row.wcsph_40 : row.edac_40;
    if (per_height == 80) return wcsph ? row.wcsph_80 : row.edac_80;
    return std::nullopt;
}

std::vector<FrontComparison> compare_with_trixi(std::span<const double> T, std::span<const double> max_x,
                                                int per_height, TrixiScheme scheme, double last_T) {
    std::vector<FrontComparison> rows;
    for (const TrixiFrontRow& row : trixi_dam_break_front) {
        if (row.T <= 0 || row.T > last_T + 1e-9) continue;
        const std::optional<double> theirs = trixi_front(row, per_height, scheme);
        const std::optional<double> ours = interpolate(T, max_x, row.T);
        if (theirs && ours) rows.push_back({row.T, *ours / trixi_H, *theirs / trixi_H});
    }
    return rows;
}

bool add_trixi_cross_check(CaseResult& result, const CaseOptions& options, std::vector<io::PlotPanel>& panels) {
    io::PlotPanel panel{
        "cross-check: Marrone et al. 2011 dam break", "T = t sqrt(g/H)", "max x / H", {}, std::nullopt, std::nullopt};
    const char* our_colours[] = {"#4c78a8", "#1b3a5c"};
    std::size_t k = 0;
    bool all_ran = true;
    const std::span<const Resolution> runs = options.quick ? std::span<const Resolution>(quick_runs) : full_runs;
    for (const Resolution& res : runs) {
        FrontSamples f;
        auto sample = [&](const Simulation& sim) {
            const ParticleState& s = sim.state();
            if (f.H == 0) {  // the lattice starts dx/2 from the walls (the first state, moved by ~1e-8 m)
                f.dx = 2.0 * *std::min_element(s.x.begin(), s.x.end());
                f.H = *std::max_element(s.y.begin(), s.y.end()) + 0.5 * f.dx;
                f.W = *std::max_element(s.x.begin(), s.x.end()) + 0.5 * f.dx;
            }
            const double T = sim.time() * std::sqrt(trixi_g / f.H);
            if (T < f.next_T && !sim.finished()) return;
            f.next_T = T + sample_dT;
            double front = -INFINITY;
            for (std::size_t i = 0; i < s.size(); ++i)
                if (s.active[i]) front = std::max(front, s.x[i]);
            f.T.push_back(T), f.max_x.push_back(front);
            if (T < f.next_rule_T && !sim.finished()) return;
            f.next_rule_T = T + rule_sample_dT;
            const auto rule = surge_front(s.x, s.y, s.active, f.dx, 0.25 * f.W);
            f.rule_T.push_back(T), f.rule_x.push_back(rule ? *rule : NAN);
        };
        const DeckRun run = run_deck(options.decks / res.deck, options, sample);
        if (!add_run(result, run)) {
            all_ran = false;
            break;
        }
        // The start, before the first step (the observer sees states after steps only).
        const ParticleState& s0 = run.initial;
        f.T.insert(f.T.begin(), 0.0);
        f.max_x.insert(f.max_x.begin(), *std::max_element(s0.x.begin(), s0.x.end()));

        std::string ranges;  // "WCSPH: -0.1 to +0.8 %; EDAC: ..." over every compared row
        for (TrixiScheme scheme : {TrixiScheme::Wcsph, TrixiScheme::Edac}) {
            const std::vector<FrontComparison> rows =
                compare_with_trixi(f.T, f.max_x, res.per_height, scheme, last_compared_T);
            double lowest = INFINITY, highest = -INFINITY;
            for (const FrontComparison& c : rows) {
                const double signed_error = (c.ours - c.theirs) / c.theirs;
                lowest = std::min(lowest, signed_error), highest = std::max(highest, signed_error);
                if (!is_gated_time(c.T)) continue;
                result.checks.push_back(
                    {fmt::format("cross-check: max x/H at T = {:.1f}, H/{} (TrixiParticles {} H/{})", c.T,
                                 res.per_height, scheme_name(scheme), res.per_height),
                     c.ours, c.theirs, relative_error(c.ours, c.theirs), cross_check_tolerance});
            }
            ranges += fmt::format("{}{}: {:+.1f} to {:+.1f} %", ranges.empty() ? "" : "; ", scheme_name(scheme),
                                  100.0 * lowest, 100.0 * highest);
            io::PlotSeries theirs{fmt::format("TrixiParticles {} H/{}", scheme_name(scheme), res.per_height),
                                  {},
                                  {},
                                  io::SeriesStyle::Markers,
                                  scheme == TrixiScheme::Wcsph ? "#e45756" : "#54a24b"};
            for (const TrixiFrontRow& row : trixi_dam_break_front) {
                theirs.x.push_back(row.T);
                theirs.y.push_back(*trixi_front(row, res.per_height, scheme) / trixi_H);
            }
            panel.series.push_back(std::move(theirs));
        }
        // Our own rule (§3) against max x: the same front unless a droplet or a thin jet leads it.
        double rule_gap = 0;
        for (std::size_t i = 0; i < f.rule_T.size(); ++i)
            if (f.rule_T[i] <= last_compared_T)
                rule_gap = std::max(rule_gap, *interpolate(f.T, f.max_x, f.rule_T[i]) - f.rule_x[i]);
        result.method.push_back(fmt::format(
            "Cross-check deck `{}` (`make_dam_break_marrone.py`, H/{}): our max x against TrixiParticles' at "
            "0.2 <= T <= {}, every 0.2: {} (gated at T = 0.4, 0.8, ..., 2.0 and 2.2, tolerance {:.0f} %). Our "
            "front rule of the experiments (particles below y = W/4 with a neighbour within 2 dx) stays within "
            "{:.2g} dx of max x (more would mean a droplet alone ahead).",
            res.deck, res.per_height, last_compared_T, ranges, 100.0 * cross_check_tolerance, rule_gap / f.dx));
        std::vector<double> our_y;
        for (double x : f.max_x) our_y.push_back(x / f.H);
        panel.series.push_back(
            {fmt::format("our max x, H/{}", res.per_height), f.T, our_y, io::SeriesStyle::Line, our_colours[k++ % 2]});
    }
    result.method.push_back(
        "Cross-check reference: TrixiParticles.jl (MIT license) `validation/dam_break_2d/validation_reference_"
        "{wcsph,edac}_{40,80}.json`, series max_x_coord_fluid_1 (the largest x over all fluid particles), the dam "
        "break of Marrone et al. (2011, CMAME 200, 1526): H = 0.6 m, W = 2H, free-slip walls, Wendland C2 with "
        "h = 2 dx, alpha = 0.01; WCSPH with c0 = 20 sqrt(g H), linear EOS and Molteni-Colagrossi density "
        "diffusion 0.1, EDAC with c0 = 50 sqrt(g H); sampled every 0.2 in T (`verify/trixi_dam_break.hpp`). "
        "Our deck: the same geometry, *EOS_LINEAR_POLYNOMIAL C1 = rho0 c0^2 with tension, cubic spline with "
        "h0 = 2 dx, symmetry-plane walls, uncompressed start, no density diffusion (docs/verification.md §3).");
    if (!panel.series.empty()) panels.push_back(std::move(panel));
    return all_ran;
}

}  // namespace sphdeck::verify
