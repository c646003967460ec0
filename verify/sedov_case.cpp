// The Sedov-Taylor blast wave (docs/verification.md §4; decks/verification/make_sedov.py): a line
// explosion in an ideal gas, modelled as a quarter plane, at two resolutions, against the cylindrical
// similarity solution (sedov_exact.hpp) at the time the run reached.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "verify/cases.hpp"
#include "verify/deck_run.hpp"
#include "verify/norms.hpp"
#include "verify/radial_profile.hpp"
#include "verify/sedov_exact.hpp"
#include "verify/wave_detection.hpp"

namespace sphdeck::verify {
namespace {

// As in make_sedov.py.
constexpr double sedov_gamma = 1.4, sedov_rho0 = 1.0, blast_energy = 1.0, sedov_box = 1.0;

// Tolerances (issue 18, fixed before the first run): the shock radius within 2 % and the peak density
// within 20 % at the finer resolution, and both closer there than at the coarser one. The radius is read
// from rings one spacing wide, so it cannot be told apart below half a spacing of the finer run: once both
// runs are that close, the radius counts as converged (docs/verification.md §4).
constexpr double sedov_radius_tolerance = 0.02, peak_tolerance = 0.20;
constexpr double radius_resolution_spacings = 0.5;
// Energy: the scheme conserves kinetic + internal energy up to the time integration (energy.hpp).
constexpr double sedov_energy_tolerance = 0.01;

struct SedovRun {
    DeckRun run;
    int n = 0;  // particles along a side of the quarter
    double spacing = 0;
    double shock = NAN, peak = NAN;  // measured shock radius and peak density
    double peak_on_positions = NAN;  // the largest mass per ring area (reference row)
    double energy_start = 0, energy_end = 0;
    ErrorNorms rho;
    RadialProfile profile;
};

// The density the positions say, independent of the density variable: mass per ring area, rings one
// spacing wide centred at (k + 1/2) dx, each particle's mass shared between the two nearest centres in
// proportion to its distance from them (cloud-in-cell; plain counting jumps by a row wherever a lattice
// row crosses a ring edge). The largest value outside the first ring (docs/verification.md §5: the
// volume-weighted continuity's density drifted above it in the shell).
double peak_mass_per_ring_area(const ParticleState& s, double dx) {
    const auto rings = static_cast<std::size_t>(sedov_box / dx);  // whole rings inside the quarter
    std::vector<double> mass(rings + 1, 0.0);
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.active[i]) continue;
        const double u = std::max(0.0, std::hypot(s.x[i], s.y[i]) / dx - 0.5);
        const auto k = static_cast<std::size_t>(u);
        if (k + 1 > rings) continue;
        const double f = u - static_cast<double>(k);
        mass[k] += (1 - f) * s.mass[i], mass[k + 1] += f * s.mass[i];
    }
    double peak = NAN;
    for (std::size_t k = 1; k + 1 < rings; ++k) {
        const double area = 0.25 * std::numbers::pi * (2.0 * static_cast<double>(k) + 1.0) * dx * dx;
        if (!(mass[k] / area <= peak)) peak = mass[k] / area;
    }
    return peak;
}

SedovRun evaluate_sedov(DeckRun run, int n, const SedovSolution& exact) {
    SedovRun r;
    r.n = n, r.spacing = sedov_box / n;
    const ParticleState& s = run.simulation->state();
    r.profile = radial_profile(s, n);
    const double t = run.simulation->time();
    std::vector<double> volume, rho_exact;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.active[i]) continue;
        const double radius = std::hypot(s.x[i], s.y[i]);
        volume.push_back(s.mass[i] / s.rho[i]);
        rho_exact.push_back(exact.sample(radius, blast_energy, sedov_rho0, t).rho);
    }
    r.rho = error_norms(r.profile.rho, rho_exact, volume);
    // Density averaged in rings one spacing wide: the peak is the largest ring mean, the shock where the
    // mean falls to halfway between the peak and the ambient density, outside the peak.
    const Profile ring = binned_profile(r.profile.r, r.profile.rho, 0.0, sedov_box, r.spacing);
    if (!ring.f.empty()) {
        const auto top = std::max_element(ring.f.begin(), ring.f.end());
        r.peak = *top;
        const double from = ring.x[static_cast<std::size_t>(top - ring.f.begin())];
        r.shock = level_crossing(ring, 0.5 * (r.peak + sedov_rho0), from, sedov_box).value_or(NAN);
    }
    r.peak_on_positions = peak_mass_per_ring_area(s, r.spacing);
    r.energy_start = total_energy(run.initial);
    r.energy_end = total_energy(s);
    r.run = std::move(run);
    return r;
}

std::string sedov_figure(const std::vector<SedovRun>& runs, const SedovSolution& exact, double t) {
    std::vector<double> rs, rho, u, p;
    for (int k = 0; k <= 2000; ++k) {
        const double radius = sedov_box * k / 2000.0;
        const SedovSolution::State g = exact.sample(radius, blast_energy, sedov_rho0, t);
        rs.push_back(radius), rho.push_back(g.rho), u.push_back(g.u), p.push_back(g.p);
    }
    std::vector<const RadialProfile*> profiles;
    for (const SedovRun& run : runs) profiles.push_back(&run.profile);
    RadialCurve curve{"exact (Sedov, j = 2)", std::move(rs), std::move(rho), std::move(u), std::move(p)};
    const std::string title =
        fmt::format("Sedov-Taylor blast wave at t = {:.4g}: particles against the similarity solution", t);
    return radial_figure(profiles, curve, sedov_box, title);
}

}  // namespace

CaseResult run_sedov(const CaseOptions& options) {
    CaseResult result;
    result.name = "sedov";
    result.title = "Sedov-Taylor blast wave (2D, cylindrical) against the similarity solution";
    const SedovSolution exact = *solve_sedov(2, sedov_gamma);
    const std::vector<int> resolutions = options.quick ? std::vector<int>{35, 70} : std::vector<int>{50, 100};

    std::vector<SedovRun> runs;
    for (int n : resolutions) {
        DeckRun run = run_deck(options.decks / fmt::format("sedov_2d_{}.k", n), options);
        if (!add_run(result, run)) return result;
        runs.push_back(evaluate_sedov(std::move(run), n, exact));
    }
    const SedovRun& coarse = runs.front();
    const SedovRun& fine = runs.back();
    const double t = fine.run.simulation->time();
    const double shock_exact = exact.shock_radius(blast_energy, sedov_rho0, t);
    const double peak_exact = exact.density_ratio * sedov_rho0;
    auto radius_error = [&](const SedovRun& r) { return relative_error(r.shock, shock_exact); };
    auto peak_error = [&](const SedovRun& r) { return relative_error(r.peak, peak_exact); };

    result.checks.push_back({fmt::format("shock radius, {} x {}", fine.n, fine.n), fine.shock, shock_exact,
                             radius_error(fine), sedov_radius_tolerance});
    result.checks.push_back({fmt::format("peak density, {} x {}", fine.n, fine.n), fine.peak, peak_exact,
                             peak_error(fine), peak_tolerance});
    // Convergence: the finer run closer than the coarser; for the radius, or within what the rings resolve.
    const double radius_floor = radius_resolution_spacings * fine.spacing / shock_exact;
    result.checks.push_back({fmt::format("shock radius error, {} x {}: below the {} x {} one or half a spacing", fine.n,
                                         fine.n, coarse.n, coarse.n),
                             radius_error(fine), std::nullopt, radius_error(fine),
                             std::max(radius_error(coarse), radius_floor)});
    const double peak_ratio = peak_error(fine) / peak_error(coarse);
    result.checks.push_back({"peak density error, finer / coarser", peak_ratio, std::nullopt, peak_ratio, 1.0});
    for (const SedovRun& r : runs) {
        const double drift = relative_error(r.energy_end, r.energy_start);
        result.checks.push_back({fmt::format("total energy drift, {} x {}", r.n, r.n), r.energy_end, r.energy_start,
                                 drift, sedov_energy_tolerance});
    }

    // Reference rows: the peak the positions say (not gated; docs/verification.md §5).
    for (const SedovRun& r : runs) {
        Check positions{fmt::format("peak mass per ring area (positions), {} x {}", r.n, r.n), r.peak_on_positions,
                        peak_exact, relative_error(r.peak_on_positions, peak_exact), peak_tolerance};
        positions.gated = false;
        result.checks.push_back(positions);
    }
    const double ratio = fine.spacing > 0 ? coarse.spacing / fine.spacing : NAN;
    result.method = {
        fmt::format("Decks `sedov_2d_{}.k` and `sedov_2d_{}.k` (`make_sedov.py`): the quarter x, y in [0, 1] of a "
                    "line explosion, E = 1 per unit length (E/4 in the quarter, in the 8 particles within 3 dx "
                    "of the origin), ideal gas gamma = 1.4, rho0 = 1, p0 = 1e-6; symmetry planes at x = 0, "
                    "y = 0 and the box walls; FORM 1, h0 = 1.2 dx (CSLH), HMIN 1, HMAX 5; Monaghan alpha = 1, "
                    "beta = 2; TSSFAC 0.3.",
                    resolutions[0], resolutions[1]),
        fmt::format("Reference: the cylindrical (j = 2) similarity solution, solved in `verify/sedov_exact.cpp` "
                    "(alpha = {:.6f}; 0.984 in Kamm & Timmes 2007), shock at r_s = (E / (alpha rho0))^(1/4) "
                    "t^(1/2) = {:.4f} at t = {:.4g}, density jump (gamma + 1) / (gamma - 1) = {:g}.",
                    exact.alpha, shock_exact, t, peak_exact),
        "Density averaged in rings one spacing wide: peak density = the largest ring mean; shock radius = where "
        "the ring means fall, outside the peak, to halfway between the peak and rho0. Convergence: the finer "
        "run's errors below the coarser's; for the radius, or below half the finer spacing (what the rings "
        "resolve).",
        "Energy: sum m (v^2 / 2 + e) at the end against the start (the symmetry planes do no work).",
        fmt::format("Not gated: shock radius {:.4f} / {:.4f}, peak density {:.3f} / {:.3f}, L1(rho) {:.4f} / {:.4f} "
                    "(coarse / fine, spacing ratio {:g}); observed order of L1(rho) {:.2f}.",
                    coarse.shock, fine.shock, coarse.peak, fine.peak, coarse.rho.l1, fine.rho.l1, ratio,
                    observed_order(coarse.rho.l1, fine.rho.l1, ratio)),
    };
    result.svg = sedov_figure(runs, exact, t);
    return result;
}

}  // namespace sphdeck::verify
