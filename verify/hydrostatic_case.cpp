// The hydrostatic water column (verification.md §2; decks/verification/make_hydrostatic.py): after the
// ramped gravity has settled, particle pressures against rho0 g (H - y), the bottom pressure against
// rho0 g H, and the residual kinetic energy (§9.3).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "io/svg_plot.hpp"
#include "verify/cases.hpp"
#include "verify/deck_run.hpp"
#include "verify/norms.hpp"
#include "verify/wave_detection.hpp"

namespace sphdeck::verify {
namespace {

constexpr double column_rho0 = 1000.0, column_gravity = 9.81;  // as in the decks (make_hydrostatic.py)

// Tolerances: §2's suggested gate of 1-2 % on the bottom pressure (the ceiling 2 % taken); the L1 of the
// pressure profile below the surface band, which includes the layer next to the floor; residual kinetic
// energy relative to rho0 g H times the water's area (§9.3).
constexpr double l1_tolerance = 0.03, bottom_tolerance = 0.02, kinetic_tolerance = 1e-5;
// Free-surface band left out of the norms: the kernel support (2 h0 = 2.4 dx) under the initial surface,
// where the particles' neighbourhoods are truncated.
constexpr double band_spacings = 2.4;

struct Sample {
    double time, bottom_pressure, kinetic;
};

}  // namespace

CaseResult run_hydrostatic(const CaseOptions& options) {
    CaseResult result;
    result.name = "hydrostatic";
    result.title = "Hydrostatic water column against rho0 g (H - y)";
    const std::string deck = options.quick ? "hydrostatic_2d_quick.k" : "hydrostatic_2d.k";

    // The bottom row's mean pressure and the kinetic energy, sampled every step for the figure.
    std::vector<Sample> history;
    double bottom_row = 0;  // y below which a particle belongs to the bottom row (set at the first step: dx)
    DeckRun run = run_deck(options.decks / deck, options, [&](const Simulation& sim) {
        const ParticleState& s = sim.state();
        if (bottom_row == 0 && s.size() > 0) bottom_row = 2.0 * *std::min_element(s.y.begin(), s.y.end());
        double sum = 0;
        std::size_t n = 0;
        for (std::size_t i = 0; i < s.size(); ++i)
            if (s.active[i] && s.y[i] < bottom_row) sum += s.p[i], ++n;
        history.push_back({sim.time(), n > 0 ? sum / static_cast<double>(n) : NAN, sim.totals().kinetic});
    });
    if (!add_run(result, run)) return result;

    // Geometry from the initial lattice: first row at dx/2, the surface dx/2 above the top row.
    const ParticleState& s0 = run.initial;
    const double dx = 2.0 * *std::min_element(s0.y.begin(), s0.y.end());
    const double depth = *std::max_element(s0.y.begin(), s0.y.end()) + 0.5 * dx;
    const double width = *std::max_element(s0.x.begin(), s0.x.end()) + 0.5 * dx;
    const double band_top = depth - band_spacings * dx;

    const ParticleState& s = run.simulation->state();
    std::vector<double> p, p_exact, volume, ys, ps;
    Profile below;  // (y, p) of the particles below the band, for the line fit
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.active[i]) continue;
        ys.push_back(s.y[i]);
        ps.push_back(s.p[i]);
        if (s.y[i] > band_top) continue;
        p.push_back(s.p[i]);
        p_exact.push_back(column_rho0 * column_gravity * (depth - s.y[i]));
        volume.push_back(s.mass[i] / s.rho[i]);
        below.x.push_back(s.y[i]);
        below.f.push_back(s.p[i]);
    }
    const ErrorNorms norms = error_norms(p, p_exact, volume);
    const double reference_bottom = column_rho0 * column_gravity * depth;
    const auto fit = fit_line(below, -INFINITY, INFINITY, -INFINITY, INFINITY);
    const double bottom = fit ? fit->intercept : NAN;  // p at y = 0 from the straight line through the column
    const double kinetic_scale = column_rho0 * column_gravity * depth * depth * width;
    const double kinetic = run.simulation->totals().kinetic / kinetic_scale;

    result.checks.push_back({"L1(p) below the surface band", norms.l1, std::nullopt, norms.l1, l1_tolerance});
    result.checks.push_back({"bottom pressure (line fit at y = 0) [Pa]", bottom, reference_bottom,
                             relative_error(bottom, reference_bottom), bottom_tolerance});
    result.checks.push_back(
        {"residual kinetic energy / (rho0 g H^2 W)", kinetic, std::nullopt, kinetic, kinetic_tolerance});

    result.method = {
        fmt::format("Deck `{}` (`make_hydrostatic.py`): water column H = {:g} m, tank W = {:g} m, spacing {:g} m, "
                    "symmetry planes at the bottom and both sides, *EOS_MURNAGHAN gamma = 7, K0 = rho0 c0^2 / 7 "
                    "with c0 = 10 sqrt(2 g H); gravity ramped up by a half-cosine *DEFINE_CURVE over 0.3 s, "
                    "then held until t = {:g} s.",
                    deck, depth, width, dx, run.simulation->time()),
        "Reference: p(y) = rho0 g (H - y), bottom pressure rho0 g H (verification.md §2).",
        fmt::format("L1 relative (§9.1, V_i = m_i / rho_i) over the particles below y = H - {:g} dx = {:g} m: the "
                    "band of one kernel support under the free surface is left out ({} particles compared, "
                    "Linf {:.3g}).",
                    band_spacings, band_top, norms.count, norms.linf),
        "Bottom pressure: least-squares line p(y) through the same particles, evaluated at y = 0 (the "
        "particles sit dx/2 and more above the floor).",
        "Residual kinetic energy at the end, divided by rho0 g H^2 W (§9.3).",
    };

    // Figure: the final profile and the bottom row's pressure over time.
    std::vector<double> ref_y = {0.0, depth}, ref_p = {reference_bottom, 0.0};
    std::vector<double> t, pb, ke, pb_ref_t, pb_ref;
    for (const Sample& h : history) {
        t.push_back(h.time), pb.push_back(h.bottom_pressure), ke.push_back(h.kinetic / kinetic_scale);
    }
    if (!t.empty()) {
        pb_ref_t = {t.front(), t.back()};
        pb_ref = {column_rho0 * column_gravity * (depth - 0.5 * dx), column_rho0 * column_gravity * (depth - 0.5 * dx)};
    }
    std::vector<io::PlotPanel> panels = {
        {"pressure at the end",
         "y [m]",
         "p [Pa]",
         {{"SPH particles", ys, ps, io::SeriesStyle::Dots, "#4c78a8"},
          {"rho0 g (H - y)", ref_y, ref_p, io::SeriesStyle::Line, "#222222"}},
         std::nullopt,
         std::nullopt},
        {"bottom row: mean pressure",
         "t [s]",
         "p [Pa]",
         {{"SPH, particles with y < dx", t, pb, io::SeriesStyle::Line, "#4c78a8"},
          {"rho0 g (H - dx/2)", pb_ref_t, pb_ref, io::SeriesStyle::Line, "#222222"}},
         std::nullopt,
         std::nullopt},
        {"kinetic energy / (rho0 g H^2 W)",
         "t [s]",
         "KE (relative)",
         {{"SPH", t, ke, io::SeriesStyle::Line, "#e45756"}},
         std::nullopt,
         std::nullopt},
    };
    io::PlotOptions plot;
    plot.title = fmt::format("Hydrostatic column, H = {:g} m, {} particles, t = {:.3g} s", depth, run.record.particles,
                             run.record.end_time);
    result.svg = io::svg_plot(panels, plot);
    return result;
}

}  // namespace sphdeck::verify
