// The dam break (verification.md §3; decks/verification/make_dam_break.py): the surge front Z/a against
// T = t sqrt(2 g / a), interpolated at the experimental T values from T = 1.5 (earlier the experiment lags
// because its gate takes time to open, §3) up to the end of the run, for two experiments: Martin & Moyce
// (1952, two column widths) and Koshizuka & Oka (1996, the 0.146 m column of the decks). Beside them a
// numerical cross-check with no gate involved: the Marrone et al. (2011) dam break against TrixiParticles'
// results (verify/dam_break_cross_check.cpp).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "io/svg_plot.hpp"
#include "verify/cases.hpp"
#include "verify/dam_break_cross_check.hpp"
#include "verify/deck_run.hpp"
#include "verify/koshizuka_oka.hpp"
#include "verify/martin_moyce.hpp"
#include "verify/norms.hpp"
#include "verify/surge_front.hpp"

namespace sphdeck::verify {
namespace {

constexpr double dam_gravity = 9.81;           // as in the decks
constexpr double first_T = 1.5;                // earlier points left out (§3)
constexpr double front_tolerance = 0.10;       // relative, the upper end of §3's 5-10 %
constexpr double experiment_sample_dT = 0.02;  // front sampled every 0.02 in T
constexpr double max_diagnostic_delay = 0.6;   // largest lag tried by the (ungated) delay diagnostic

}  // namespace

CaseResult run_dam_break(const CaseOptions& options) {
    CaseResult result;
    result.name = "dambreak";
    result.title =
        "Dam break: surge front against Martin & Moyce (1952) and Koshizuka & Oka (1996); "
        "cross-check with TrixiParticles";
    const std::string deck = options.quick ? "dam_break_mm_quick.k" : "dam_break_mm.k";

    // a and dx from the first observed state: the column's lattice starts dx/2 from the back wall.
    double a = 0, dx = 0, next_T = 0;
    std::vector<double> Ts, fronts;
    auto sample = [&](const Simulation& sim) {
        const ParticleState& s = sim.state();
        if (a == 0) {
            dx = 2.0 * *std::min_element(s.x.begin(), s.x.end());
            a = *std::max_element(s.x.begin(), s.x.end()) + 0.5 * dx;
        }
        const double T = sim.time() * std::sqrt(2.0 * dam_gravity / a);
        if (T < next_T && !sim.finished()) return;
        next_T = T + experiment_sample_dT;
        const auto front = surge_front(s.x, s.y, s.active, dx, 0.25 * a);
        Ts.push_back(T);
        fronts.push_back(front ? (*front + 0.5 * dx) / a : NAN);  // the fluid's edge is dx/2 past the particle
    };
    DeckRun run = run_deck(options.decks / deck, options, sample);
    if (!add_run(result, run)) return result;
    const double end_T = Ts.empty() ? 0.0 : Ts.back();

    std::vector<io::PlotSeries> experiment;
    const char* colours[] = {"#e45756", "#54a24b", "#b279a2"};
    std::vector<std::pair<std::string, FrontSeries>> all;
    for (const FrontSeries& series : martin_moyce())
        all.emplace_back(fmt::format("Martin & Moyce, {}", series.column), series);
    all.emplace_back(std::string(koshizuka_oka().column), koshizuka_oka());
    // Per series: the gated points and their largest error (for the diagnostic lines).
    struct Gated {
        std::string label;
        std::vector<double> T, z;
        double worst = 0;
    };
    std::vector<Gated> gated;
    std::size_t k = 0;
    for (const auto& [label, series] : all) {
        io::PlotSeries points{label, {}, {}, io::SeriesStyle::Markers, colours[k++ % 3]};
        Gated g{label, {}, {}, 0.0};
        for (const FrontPoint& p : series.points) {
            if (p.T > end_T + 0.5) continue;
            points.x.push_back(p.T);
            points.y.push_back(p.z_over_a);
            if (p.T < first_T || p.T > end_T) continue;
            g.T.push_back(p.T), g.z.push_back(p.z_over_a);
            const double simulated = interpolate(Ts, fronts, p.T).value_or(NAN);
            result.checks.push_back({fmt::format("Z/a at T = {:.3f} ({})", p.T, label), simulated, p.z_over_a,
                                     relative_error(simulated, p.z_over_a), front_tolerance});
            result.checks.back().gated = false;  // the experiments' gate lag: a reference, not the verdict
            g.worst = std::max(g.worst, result.checks.back().error);
        }
        gated.push_back(std::move(g));
        experiment.push_back(std::move(points));
    }

    result.method = {
        fmt::format("Deck `{}` (`make_dam_break.py`): column a = {:g} m wide and 2a high, spacing a/{:.0f}, "
                    "tank 5a long; floor, back wall and far wall are symmetry planes; *EOS_MURNAGHAN gamma = 7 "
                    "with c0 = 10 sqrt(2 g 2a); Monaghan alpha = 0.1; run to T = {:.3g}.",
                    deck, a, a / dx, end_T),
        "Reference: Martin & Moyce (1952) surge-front data as tabulated in verification.md §3 (both column "
        "widths), and Koshizuka & Oka (1996, Nucl. Sci. Eng. 123, 421), the 0.146 m column of the decks, as "
        "tabulated in pysph's `db_exp_data.py` (Z/L against T = t sqrt(2 g / L), L the column width).",
        "Front: the largest x among the particles below y = a/4 that have another particle within 2 dx (a "
        "lone droplet does not count), plus dx/2 for the fluid's edge; sampled every 0.02 in T and "
        "interpolated linearly at the experimental T values.",
        fmt::format("Experiments, reference rows, not gated: relative error |Z_sph - Z_exp| / Z_exp at every "
                    "experimental point with {} <= T <= end of the run, as measured and after the constant time shift "
                    "that aligns them best. The experiments lead the run by their gate's opening, which no deck "
                    "keyword models (docs/verification.md §3); the gate of this case is the cross-check below.",
                    first_T),
    };
    // Reference rows: how much of the disagreement a constant lag of each experiment explains.
    for (const Gated& g : gated) {
        if (g.T.empty()) continue;
        if (const auto lag = best_front_delay(Ts, fronts, g.T, g.z, max_diagnostic_delay, 0.01)) {
            Check shifted{fmt::format("Z/a largest error after a shift dT = {:.2f} (t = {:.4f} s), {}", lag->delay,
                                      lag->delay / std::sqrt(2.0 * dam_gravity / a), g.label),
                          lag->worst_error, std::nullopt, lag->worst_error, front_tolerance};
            shifted.gated = false;
            result.checks.push_back(std::move(shifted));
            result.method.push_back(fmt::format(
                "{}: the SPH front delayed by dT = {:.2f} is within {:.1f} % of its {} points (largest error {:.1f} % "
                "without the shift).",
                g.label, lag->delay, 100.0 * lag->worst_error, g.T.size(), 100.0 * g.worst));
        }
    }

    std::vector<double> px, py;
    const ParticleState& s = run.simulation->state();
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.active[i]) px.push_back(s.x[i] / a), py.push_back(s.y[i] / a);
    io::PlotPanel front{"surge front", "T = t sqrt(2g/a)",
                        "Z/a",         {{"SPH front", Ts, fronts, io::SeriesStyle::Line, "#4c78a8"}},
                        std::nullopt,  std::nullopt};
    for (io::PlotSeries& e : experiment) front.series.push_back(std::move(e));
    io::PlotPanel particles{fmt::format("particles at T = {:.3g}", end_T),
                            "x/a",
                            "y/a",
                            {{"SPH particles", px, py, io::SeriesStyle::Dots, "#4c78a8"}},
                            std::pair{0.0, 5.0},
                            std::pair{0.0, 2.0}};
    std::vector<io::PlotPanel> panels = {front, particles};
    // The run of the experiments stays in the report even when a cross-check deck cannot run.
    add_trixi_cross_check(result, options, panels);
    io::PlotOptions plot;
    plot.title = fmt::format("Dam break, a = {:g} m, {} particles", a, run.record.particles);
    result.svg = io::svg_plot(panels, plot);
    return result;
}

}  // namespace sphdeck::verify
