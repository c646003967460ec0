// The Noh implosion (docs/verification.md §5; decks/verification/make_noh.py): cold gas streaming
// towards the axis of a cylinder, modelled as a quarter plane, at two resolutions, against the exact
// solution (noh_exact.hpp) at the time the run reached.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "verify/cases.hpp"
#include "verify/deck_run.hpp"
#include "verify/noh_exact.hpp"
#include "verify/norms.hpp"
#include "verify/radial_profile.hpp"
#include "verify/wave_detection.hpp"

namespace sphdeck::verify {
namespace {

// As in make_noh.py: cylindrical (j = 2), gamma 5/3, rho0 = 1, unit inward speed, the quarter [0, 1]^2.
constexpr double noh_box = 1.0;

// Tolerances (issue 31, fixed before the first run): the post-shock density within 10 % of 16 at the
// finer resolution and closer there than at the coarser; the shock radius within 5 %.
constexpr double density_tolerance = 0.10, noh_radius_tolerance = 0.05;
// Energy: the scheme conserves kinetic + internal energy up to the time integration (energy.hpp).
constexpr double noh_energy_tolerance = 0.01;
// The post-shock plateau is measured over r_s / 4 < r < 3 r_s / 4 (0.05 < r < 0.15 at t = 0.6, the
// issue's band): clear of the wall-heating dip at the centre and of the smeared shock.
constexpr double plateau_low = 0.25, plateau_high = 0.75;

struct NohRun {
    DeckRun run;
    int n = 0;  // particles along a side of the quarter
    double spacing = 0;
    double plateau = NAN, shock = NAN;    // median post-shock density, shock radius
    double centre = NAN, centre_e = NAN;  // mean density and specific energy within r_s / 4 (the wall heating)
    double energy_start = 0, energy_end = 0;
    ErrorNorms rho;  // within the shocked gas and the inflow up to 2 r_s
    RadialProfile profile;
};

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    if (v.size() % 2) return *mid;
    return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

NohRun evaluate_noh(DeckRun run, int n, const NohSolution& exact) {
    NohRun r;
    r.n = n, r.spacing = noh_box / n;
    const ParticleState& s = run.simulation->state();
    r.profile = radial_profile(s, n);
    const double t = run.simulation->time(), rs = exact.shock_radius(t);
    std::vector<double> band, volume, rho_exact, rho_compared;
    double centre_mass = 0, centre_volume = 0, centre_energy = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.active[i]) continue;
        const double radius = std::hypot(s.x[i], s.y[i]);
        if (radius > plateau_low * rs && radius < plateau_high * rs) band.push_back(s.rho[i]);
        if (radius < plateau_low * rs) {
            centre_mass += s.mass[i], centre_volume += s.mass[i] / s.rho[i], centre_energy += s.mass[i] * s.e[i];
        }
        if (radius < 2 * rs) {
            rho_compared.push_back(s.rho[i]);
            volume.push_back(s.mass[i] / s.rho[i]);
            rho_exact.push_back(exact.sample(radius, t).rho);
        }
    }
    r.plateau = median(band);
    r.centre = centre_volume > 0 ? centre_mass / centre_volume : NAN;
    r.centre_e = centre_mass > 0 ? centre_energy / centre_mass : NAN;
    r.rho = error_norms(rho_compared, rho_exact, volume);
    // Shock: where the density averaged in rings one spacing wide falls, outward from the plateau, to
    // halfway between the measured plateau and the exact density just ahead of the shock (4 at t = 0.6).
    const Profile ring = binned_profile(r.profile.r, r.profile.rho, 0.0, noh_box, r.spacing);
    const double level = 0.5 * (r.plateau + exact.pre_shock_density(rs, t));
    r.shock = level_crossing(ring, level, plateau_high * rs, noh_box).value_or(NAN);
    r.energy_start = total_energy(run.initial);
    r.energy_end = total_energy(s);
    r.run = std::move(run);
    return r;
}

std::string noh_figure(const std::vector<NohRun>& runs, const NohSolution& exact, double t) {
    const double reach = 0.5;  // the inflow beyond is uniform in the plot's eyes
    std::vector<double> rs, rho, u, p;
    for (int k = 1; k <= 2000; ++k) {
        const double radius = reach * k / 2000.0;
        const NohSolution::State g = exact.sample(radius, t);
        rs.push_back(radius), rho.push_back(g.rho), u.push_back(g.u), p.push_back(g.p);
    }
    std::vector<const RadialProfile*> profiles;
    for (const NohRun& run : runs) profiles.push_back(&run.profile);
    RadialCurve curve{"exact (Noh, cylindrical)", std::move(rs), std::move(rho), std::move(u), std::move(p)};
    return radial_figure(profiles, curve, reach,
                         fmt::format("Noh implosion at t = {:.4g}: particles against the exact solution", t));
}

}  // namespace

CaseResult run_noh(const CaseOptions& options) {
    CaseResult result;
    result.name = "noh";
    result.title = "Noh implosion (2D, cylindrical) against the exact solution";
    const NohSolution exact;  // j = 2, gamma 5/3, rho0 = 1, u0 = 1
    const std::vector<int> resolutions = options.quick ? std::vector<int>{35, 70} : std::vector<int>{50, 100};

    std::vector<NohRun> runs;
    for (int n : resolutions) {
        DeckRun run = run_deck(options.decks / fmt::format("noh_2d_{}.k", n), options);
        if (!add_run(result, run)) return result;
        runs.push_back(evaluate_noh(std::move(run), n, exact));
    }
    const NohRun& coarse = runs.front();
    const NohRun& fine = runs.back();
    const double t = fine.run.simulation->time();
    const double shock_exact = exact.shock_radius(t), post = exact.post_shock_density();
    auto density_error = [&](const NohRun& r) { return relative_error(r.plateau, post); };

    result.checks.push_back({fmt::format("post-shock density, {} x {}", fine.n, fine.n), fine.plateau, post,
                             density_error(fine), density_tolerance});
    const double density_ratio = density_error(fine) / density_error(coarse);
    result.checks.push_back(
        {fmt::format("post-shock density error, {} x {} / {} x {}", fine.n, fine.n, coarse.n, coarse.n), density_ratio,
         std::nullopt, density_ratio, 1.0});
    result.checks.push_back({fmt::format("shock radius, {} x {}", fine.n, fine.n), fine.shock, shock_exact,
                             relative_error(fine.shock, shock_exact), noh_radius_tolerance});
    for (const NohRun& r : runs) {
        const double drift = relative_error(r.energy_end, r.energy_start);
        result.checks.push_back({fmt::format("total energy drift, {} x {}", r.n, r.n), r.energy_end, r.energy_start,
                                 drift, noh_energy_tolerance});
    }
    // Reference rows: the coarser run, and the wall heating at the centre (a known defect of every
    // scheme with artificial viscosity and no heat flux: the first shocked gas is over-heated, so it
    // stays less dense than 16). Reported, not gated.
    Check coarse_density{fmt::format("post-shock density, {} x {}", coarse.n, coarse.n), coarse.plateau, post,
                         density_error(coarse), density_tolerance};
    coarse_density.gated = false;
    result.checks.push_back(coarse_density);
    Check coarse_shock{fmt::format("shock radius, {} x {}", coarse.n, coarse.n), coarse.shock, shock_exact,
                       relative_error(coarse.shock, shock_exact), noh_radius_tolerance};
    coarse_shock.gated = false;
    result.checks.push_back(coarse_shock);
    for (const NohRun& r : runs) {
        Check dip{fmt::format("wall heating: density within r_s / 4, {} x {}", r.n, r.n), r.centre, post,
                  relative_error(r.centre, post), density_tolerance};
        dip.gated = false;
        result.checks.push_back(dip);
    }

    const double ratio = fine.spacing > 0 ? coarse.spacing / fine.spacing : NAN;
    result.method = {
        fmt::format("Decks `noh_2d_{}.k` and `noh_2d_{}.k` (`make_noh.py`): the quarter x, y in [0, 1] of a "
                    "cylindrical implosion, cold ideal gas gamma = 5/3, rho0 = 1, p0 = 1e-6, v = -x / |x| per "
                    "particle (*INITIAL_VELOCITY_NODE); symmetry planes at x = 0 and y = 0, free outer edges; "
                    "FORM 0, h0 = 1.2 dx (CSLH), HMIN 0.2, HMAX 2; Monaghan alpha = 1, beta = 2; TSSFAC 0.3.",
                    resolutions[0], resolutions[1]),
        fmt::format("Reference: Noh (1987), cylindrical: shock at r_s = t / 3 = {:.4f} at t = {:.4g}; behind it "
                    "rho = ((gamma + 1) / (gamma - 1))^2 = {:g}, u = 0, p = 16 / 3; ahead rho = 1 + t / r, u = -1.",
                    shock_exact, t, post),
        "Post-shock density: the median particle density over r_s / 4 < r < 3 r_s / 4. Shock radius: where "
        "the density averaged in rings one spacing wide falls, outward, to halfway between that median and "
        "the exact density just ahead of the shock (1 + t / r_s = 4). Wall heating: the density (mass over "
        "volume) and specific energy of the particles within r_s / 4 (exact 16 and 0.5), not gated.",
        "Energy: sum m (v^2 / 2 + e) at the end against the start (the symmetry planes do no work).",
        fmt::format("Not gated: post-shock density {:.3f} / {:.3f}, shock radius {:.4f} / {:.4f}, centre density "
                    "{:.2f} / {:.2f} and energy {:.3f} / {:.3f}, L1(rho) over r < 2 r_s {:.4f} / {:.4f} (coarse / "
                    "fine, spacing ratio {:g}); observed order of L1(rho) {:.2f}.",
                    coarse.plateau, fine.plateau, coarse.shock, fine.shock, coarse.centre, fine.centre, coarse.centre_e,
                    fine.centre_e, coarse.rho.l1, fine.rho.l1, ratio,
                    observed_order(coarse.rho.l1, fine.rho.l1, ratio)),
    };
    result.svg = noh_figure(runs, exact, t);
    return result;
}

}  // namespace sphdeck::verify
