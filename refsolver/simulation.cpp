// The time integration and the front door (simulation.hpp). Kick-drift-kick leapfrog with one
// right-hand side per step (velocity Verlet; density, energy and h are kicked like the velocity):
//   1. half kick:  v' = v + dt/2 a,  rho' = rho + dt/2 drho,  e' = e + dt/2 de,  h' = h + dt/2 dh
//   2. drift:      x += dt v'
//   3. predict v, rho, e, h at the new time with the old rates, evaluate the EOS, rebuild the
//      neighbour lists if the Verlet skin requires it, and compute the new rates (rates.hpp)
//   4. half kick:  v = v' + dt/2 a_new  (and rho, e, h alike; h clamped to [HMIN h0, HMAX h0])
// Second order, time-reversible for the conservative terms; the pair forces are antisymmetric, so
// every kick conserves momentum exactly where no load or boundary acts. The deviatoric stress of
// *MAT_ELASTIC parts (stress.hpp) is kicked like the density (kick_stress; fluid decks skip it).
#include "refsolver/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <omp.h>

#include "refsolver/body_load.hpp"
#include "refsolver/core_share.hpp"
#include "refsolver/deactivation.hpp"
#include "refsolver/grad_h.hpp"
#include "refsolver/neighbour_list.hpp"
#include "refsolver/rates.hpp"
#include "refsolver/renormalisation.hpp"
#include "refsolver/setup.hpp"
#include "refsolver/symmetry_ghosts.hpp"
#include "refsolver/radioss_time_step.hpp"
#include "refsolver/time_step.hpp"
#include "refsolver/verlet_skin.hpp"

namespace sphdeck::refsolver {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The Verlet skin, as a share of the largest h: lists hold pairs within 2 h_max + skin. Large,
// because the pair loop drops the listed pairs outside the support cheaply (rates.cpp) while a
// rebuild costs most of a step: 0.8 h halves the rebuilds of 0.5 h for about 3 % more per step
// (bench_refsolver).
constexpr double skin_share = 0.8;

bool is_finite(const Particles& s, std::size_t i) {
    return std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && std::isfinite(s.z[i]) && std::isfinite(s.vx[i]) &&
           std::isfinite(s.vy[i]) && std::isfinite(s.vz[i]) && std::isfinite(s.rho[i]) && std::isfinite(s.e[i]);
}

// The leapfrog of the deviatoric stress (*MAT_ELASTIC), kicked like the density: `predict` gives
// the half-step S and S at the new time from the old rate; otherwise S = S_half + dt/2 dS_new.
void kick_stress(Particles& s, double half, bool predict, int threads) {
    const std::size_t n = s.real;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t i = 0; i < n; ++i) {
        if (!s.active[i]) continue;
        for (int k = 0; k < 6; ++k) {
            if (predict) s.stress_half[i][k] = s.stress[i][k] + half * s.dstress[i][k];
            s.stress[i][k] = s.stress_half[i][k] + half * s.dstress[i][k];
        }
    }
}
}  // namespace

struct Simulation::Impl {
    SolverInput in;
    Particles s;
    NeighbourList list;
    RateParameters rates;
    RateScratch scratch;
    Deactivation deactivation;
    std::optional<CoreShare> core_share;  // set when the thread count is ours to choose (core_share.hpp)
    std::vector<long long> part_ids;
    double time = 0, dt = 0, dt_next = 0, external_work = 0;
    std::size_t steps = 0, since_rebuild = 0, rebuilds = 0;
    double h_max_built = 0, skin = 0;
    bool rebuild_every_step = false;                  // RunOptions::rebuild_every_step
    mutable std::vector<DisplacementBox> skin_cells;  // closing_bound's scratch
    Timings timings;
    std::string failure;
    mutable ParticleState state;
    mutable bool state_valid = false;

    void initialise();
    void step();
    // OpenRadioss decks: the engine's central differences (radioss_cycle below).
    double dt12 = 0;  // (dt_{n-1/2} + dt_{n+1/2}) / 2 of the last cycle: the velocity update's step
    double dt1 = 0;   // dt_{n-1/2}, the step that led to the current cycle (0 at cycle 0)
    // The velocity at the current time: v^(n-1/2) + dt1 / 2 a^n for OpenRadioss decks (the engine's
    // listing, ecrit.F), the leapfrog's v otherwise.
    std::array<double, 3> velocity(std::size_t k) const {
        const double w = in.radioss_step ? 0.5 * dt1 : 0.0;
        return {s.vx[k] + w * s.ax[k], s.vy[k] + w * s.ay[k], s.vz[k] + w * s.az[k]};
    }
    std::vector<double> heating;   // per real particle: the viscous power per unit mass of the last cycle
    std::vector<double> switches;  // per real particle: the engine's viscosity switch (viscosity.hpp)
    void radioss_cycle(double dt1);
    void radioss_step(Clock::time_point t0);  // after step() has set dt
    void evaluate();                          // EOS, lists, corrections, rates at the current (predicted) state
    void update_eos();
    void apply_kinematic();
    // TSSFAC times `smallest` (time_step.hpp), or for OpenRadioss decks the engine's particle or
    // nodal step (/DT/NODA).
    double next_time_step(double smallest) const {
        if (in.radioss_nodal_step)
            smallest = radioss_nodal_time_step(s, list, switches, in.q1, in.q2, rates.threads);
        else if (in.radioss_step)
            smallest = radioss_particle_time_step(s, list, in.q1, in.q2, rates.threads);
        return in.tssfac * smallest;
    }
    void update_interacting();
    void rebuild();
    bool needs_rebuild() const;
    bool timed_needs_rebuild();  // needs_rebuild, its time added to timings.skin_check
    // FORM 0's number-density continuity takes the grad-h factor where a particle thins out (grad_h.hpp).
    bool grad_h() const { return !rates.renormalise; }
    void check_finite();
    void report_non_finite(bool finite);  // sets `failure` when !finite
};

void Simulation::Impl::update_eos() {
    const std::size_t n = s.real;
#pragma omp parallel for schedule(static) num_threads(rates.threads)
    for (std::size_t i = 0; i < n; ++i) {
        const PartSetup& part = in.parts[s.part[i]];
        part.eos.evaluate(s.rho[i], s.e[i], s.p[i], s.c[i]);
        if (part.solid()) s.c[i] = part.wave_speed;  // stress.hpp: the dilatational wave speed
    }
}

void Simulation::Impl::update_interacting() {
    const bool global = time >= in.sph_start && time < in.sph_death;
    const std::size_t n = s.real;
#pragma omp parallel for schedule(static) num_threads(rates.threads)
    for (std::size_t i = 0; i < n; ++i) {
        const PartSetup& part = in.parts[s.part[i]];
        s.interacting[i] = s.active[i] && global && time >= part.start && time < part.death;
    }
}

void Simulation::Impl::rebuild() {
    const auto t0 = Clock::now();
    double h_max = 0;
    for (std::size_t i = 0; i < s.real; ++i)
        if (s.active[i]) h_max = std::max(h_max, s.h[i]);
    if (!(h_max > 0)) h_max = 1;
    skin = skin_share * h_max;
    const double radius = CubicSpline::support_factor * h_max + skin;
    build_ghosts(s, in.planes, radius, rates.threads, in.planes_per_image);
    // Also sorts the real particles into cell order; FORM 1 and FORM 0's Omega read the full lists too.
    list.build(s, radius, rates.threads, in.renormalise || grad_h());
    const std::size_t n = s.real;
#pragma omp parallel for schedule(static) num_threads(rates.threads)
    for (std::size_t i = 0; i < n; ++i) s.x_built[i] = s.x[i], s.y_built[i] = s.y[i], s.z_built[i] = s.z[i];
    h_max_built = h_max;
    since_rebuild = 0;
    ++rebuilds;
    state_valid = false;
    timings.neighbours += seconds_since(t0);
}

// A pair missing from the lists was at least radius = 2 h_max_built + skin apart at the build.
// - Real pairs and pairs with an existing ghost: the distance has changed by at most
//   |d_i - d_j| (d: displacement since the build; a ghost's is its source's, mirrored), which is
//   at most the diagonal of the box bounding all displacements. The diagonal, rather than twice
//   the largest displacement: a flow moving as a whole changes few distances, and needs few
//   rebuilds. When that bound is spent, the local one of verlet_skin.hpp (the same diagonal over
//   the two cells of build positions a pair within the support can come from): a flow that
//   stretches changes the distances of neighbours little.
// - A ghost that does not exist yet (its source was further than the radius from the plane): it
//   is at least dd_i + dd_j >= dd_j from any real particle i, so it stays out of the support while
//   no particle has moved towards a plane by more than the skin. Only particles now within the
//   support of a plane can have such a ghost within the support, so only they count; the radius
//   of the build stands for the support (if h grew past it, the first term asks for a rebuild).
// The support is 2 h_max now, so: rebuild when 2 (h_max - h_max_built) + either bound >= skin.
bool Simulation::Impl::timed_needs_rebuild() {
    const auto t0 = Clock::now();
    const bool needed = needs_rebuild();
    timings.skin_check += seconds_since(t0);
    return needed;
}

bool Simulation::Impl::needs_rebuild() const {
    if (rebuilds == 0 || rebuild_every_step) return true;
    if (since_rebuild + 1 < static_cast<std::size_t>(in.ncbs)) return false;  // NCBS: not more often than this
    constexpr double inf = std::numeric_limits<double>::infinity();
    double lx = inf, ly = inf, lz = inf, hx = -inf, hy = -inf, hz = -inf, towards = 0, h_max = 0;
    const std::size_t n = s.real, ghosts = s.ghosts();
    const std::vector<SymmetryPlane>& planes = in.planes;
    const double reach = list.radius;  // of the last build: 2 h_max_built + skin
#pragma omp parallel num_threads(rates.threads)
    {
#pragma omp for schedule(static) reduction(min : lx, ly, lz) reduction(max : hx, hy, hz, towards, h_max) nowait
        for (std::size_t i = 0; i < n; ++i) {
            if (!s.active[i]) continue;
            const double dx = s.x[i] - s.x_built[i], dy = s.y[i] - s.y_built[i], dz = s.z[i] - s.z_built[i];
            lx = std::min(lx, dx), ly = std::min(ly, dy), lz = std::min(lz, dz);
            hx = std::max(hx, dx), hy = std::max(hy, dy), hz = std::max(hz, dz);
            for (const SymmetryPlane& q : planes) {
                const double dd = s.x[i] * q.normal[0] + s.y[i] * q.normal[1] + s.z[i] * q.normal[2] - q.offset;
                if (dd < reach) towards = std::max(towards, -(dx * q.normal[0] + dy * q.normal[1] + dz * q.normal[2]));
            }
            h_max = std::max(h_max, s.h[i]);
        }
#pragma omp for schedule(static) reduction(min : lx, ly, lz) reduction(max : hx, hy, hz)
        for (std::size_t k = 0; k < ghosts; ++k) {
            const std::size_t j = s.ghost_source[k];
            if (!s.active[j]) continue;
            double d[3] = {s.x[j] - s.x_built[j], s.y[j] - s.y_built[j], s.z[j] - s.z_built[j]};
            for (std::size_t q = 0; q < planes.size() && q < 8; ++q) {
                if (!(s.ghost_planes[k] >> q & 1u)) continue;
                const auto& m = planes[q].normal;  // d - 2 (d . m) m
                const double dn = d[0] * m[0] + d[1] * m[1] + d[2] * m[2];
                for (int a = 0; a < 3; ++a) d[a] -= 2 * dn * m[a];
            }
            lx = std::min(lx, d[0]), ly = std::min(ly, d[1]), lz = std::min(lz, d[2]);
            hx = std::max(hx, d[0]), hy = std::max(hy, d[1]), hz = std::max(hz, d[2]);
        }
    }
    const double diagonal =
        lx <= hx ? std::sqrt((hx - lx) * (hx - lx) + (hy - ly) * (hy - ly) + (hz - lz) * (hz - lz)) : 0.0;
    const double grown = CubicSpline::support_factor * (h_max - h_max_built);
    if (grown + std::max(diagonal, towards) < skin) return false;
    // The global bound is spent: the local one (verlet_skin.hpp), which follows only the spread of
    // displacements between neighbouring regions. Written so that a NaN (a non-finite state) asks
    // for a rebuild too.
    const double local = closing_bound(s, in.planes, CubicSpline::support_factor * h_max, skin_cells, rates.threads);
    return !(grown + std::max(local, towards) < skin);
}

void Simulation::Impl::evaluate() {
    update_interacting();
    update_eos();
    if (timed_needs_rebuild())
        rebuild();
    else
        update_ghosts(s, in.planes, rates.threads);
    if (in.renormalise) {  // FORM 1 (volume_weighted alone keeps the corrections at I)
        compute_corrections(s, list, rates.kernel, rates.threads);
        update_ghosts(s, in.planes, rates.threads);
    }
    if (grad_h()) {
        const auto t0 = Clock::now();
        compute_grad_h(s, list, rates.kernel, in.h_rule == SmoothingLengthRule::Divergence, rates.threads);
        timings.grad_h += seconds_since(t0);
    }
    rates.body = body_acceleration(in.loads, time);
    compute_rates(s, list, rates, scratch);
    if (!in.kinematic.empty()) apply_kinematic();
}

// OpenRadioss /SPHBCS kinematic conditions (setup.hpp: SolverInput::kinematic): the acceleration
// projected, so that a velocity that satisfies them at the start keeps satisfying them.
void Simulation::Impl::apply_kinematic() {
    const std::size_t n = s.real;
#pragma omp parallel for schedule(static) num_threads(rates.threads)
    for (std::size_t k = 0; k < n; ++k) {
        const std::array<double, 9>& p = in.kinematic[s.model_index[k]];
        const double ax = s.ax[k], ay = s.ay[k], az = s.az[k];
        s.ax[k] = p[0] * ax + p[1] * ay + p[2] * az;
        s.ay[k] = p[3] * ax + p[4] * ay + p[5] * az;
        s.az[k] = p[6] * ax + p[7] * ay + p[8] * az;
    }
}

void Simulation::Impl::initialise() {
    const std::size_t n = in.x.size();
    for (const PartSetup& p : in.parts) {
        rates.shear.push_back(p.elastic.shear);
        rates.solid = rates.solid || p.solid();
    }
    s.solid = rates.solid;
    s.resize_real(n);
    for (std::size_t i = 0; i < n; ++i) {
        s.x[i] = in.x[i], s.y[i] = in.y[i], s.z[i] = in.z[i];
        s.vx[i] = in.vx[i], s.vy[i] = in.vy[i], s.vz[i] = in.vz[i];
        s.rho[i] = in.rho[i], s.e[i] = in.e[i], s.h[i] = in.h[i], s.m[i] = in.m[i];
        s.h_low[i] = in.h_low[i], s.h_high[i] = in.h_high[i];
        s.part[i] = in.part[i], s.model_index[i] = static_cast<std::uint32_t>(i);
    }
    rates.kernel.dimension = in.dimension;
    rates.viscosity = {in.q1, in.q2};
    rates.renormalise = in.renormalise || in.volume_weighted;  // the volume-weighted equations
    rates.h_rule = in.h_rule;
    deactivation.maxv = in.maxv, deactivation.box = in.box, deactivation.dimension = in.dimension;
    const auto t0 = Clock::now();
    deactivation.apply(s);
    update_interacting();
    since_rebuild = static_cast<std::size_t>(in.ncbs);  // the first evaluation builds the lists
    s.x_built.assign(n, std::numeric_limits<double>::infinity());
    s.y_built = s.x_built, s.z_built = s.x_built;
    if (in.radioss_step) {
        radioss_cycle(0.0);  // cycle 0: no density update yet (dt_{-1/2} = 0)
    } else {
        evaluate();
        dt_next = std::min(next_time_step(stable_time_step(s, 1.0, rates.threads)), in.end_time - time);
    }
    dt = dt_next;
    timings.total += seconds_since(t0);
    check_finite();
}

void Simulation::Impl::check_finite() {
    bool finite = true;
    const std::size_t n = s.real;
#pragma omp parallel for schedule(static) reduction(&& : finite) num_threads(rates.threads)
    for (std::size_t i = 0; i < n; ++i) finite = finite && is_finite(s, i);
    report_non_finite(finite);
}

void Simulation::Impl::report_non_finite(bool finite) {
    if (!finite && failure.empty())
        failure = "the state became non-finite (NaN or infinity) at step " + std::to_string(steps) +
                  ": the time step is too large for this deck, or the material state left its EOS's range";
}

void Simulation::Impl::step() {
    const auto t0 = Clock::now();
    dt = std::min(dt_next, in.end_time - time);
    if (!(dt > 0) || !std::isfinite(dt)) {
        failure = "the time step collapsed to " + std::to_string(dt) + " at time " + std::to_string(time);
        return;
    }
    if (core_share) rates.threads = core_share->threads();
    if (in.radioss_step) return radioss_step(t0);
    const double half = 0.5 * dt;
    const std::array<double, 3> body_mid = body_acceleration(in.loads, time + half);
    double work = 0;
    const std::size_t n = s.real;
    const bool plane_strain = in.dimension == 2;
#pragma omp parallel for schedule(static) reduction(+ : work) num_threads(rates.threads)
    for (std::size_t i = 0; i < n; ++i) {
        if (!s.active[i]) continue;
        s.vx_half[i] = s.vx[i] + half * s.ax[i], s.vy_half[i] = s.vy[i] + half * s.ay[i];
        s.vz_half[i] = plane_strain ? 0.0 : s.vz[i] + half * s.az[i];
        s.rho_half[i] = s.rho[i] + half * s.drho[i], s.e_half[i] = s.e[i] + half * s.de[i];
        s.h_half[i] = clamp_smoothing_length(s.h[i] + half * s.dh[i], s.h_low[i], s.h_high[i]);
        s.x[i] += dt * s.vx_half[i], s.y[i] += dt * s.vy_half[i], s.z[i] += dt * s.vz_half[i];
        work += s.m[i] * dt *
                (body_mid[0] * s.vx_half[i] + body_mid[1] * s.vy_half[i] +
                 (plane_strain ? 0.0 : body_mid[2] * s.vz_half[i]));
        // Predicted state at the new time, from the old rates.
        s.vx[i] = s.vx_half[i] + half * s.ax[i], s.vy[i] = s.vy_half[i] + half * s.ay[i];
        s.vz[i] = s.vz_half[i] + half * s.az[i];
        s.rho[i] = s.rho_half[i] + half * s.drho[i], s.e[i] = s.e_half[i] + half * s.de[i];
        s.h[i] = clamp_smoothing_length(s.h_half[i] + half * s.dh[i], s.h_low[i], s.h_high[i]);
    }
    external_work += work;
    if (s.solid) kick_stress(s, half, true, rates.threads);
    reflect_crossed(s, in.planes, rates.threads);
    time += dt;
    deactivation.apply(s);
    evaluate();
    // The last half kick, and in the same pass the next time step (time_step.hpp: the stress kick
    // below changes none of its inputs) and the finite check: one pass over the particles, not three.
    double smallest = std::numeric_limits<double>::infinity();
    bool finite = true;
#pragma omp parallel for schedule(static) reduction(min : smallest) reduction(&& : finite) num_threads(rates.threads)
    for (std::size_t i = 0; i < n; ++i) {
        if (s.active[i]) {
            s.vx[i] = s.vx_half[i] + half * s.ax[i], s.vy[i] = s.vy_half[i] + half * s.ay[i];
            s.vz[i] = s.vz_half[i] + half * s.az[i];
            s.rho[i] = s.rho_half[i] + half * s.drho[i], s.e[i] = s.e_half[i] + half * s.de[i];
            s.h[i] = clamp_smoothing_length(s.h_half[i] + half * s.dh[i], s.h_low[i], s.h_high[i]);
            const double speed = std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i]);
            const double accel = std::sqrt(s.ax[i] * s.ax[i] + s.ay[i] * s.ay[i] + s.az[i] * s.az[i]);
            smallest = std::min(smallest, particle_time_step(s.h[i], s.c[i], speed, accel));
        }
        finite = finite && is_finite(s, i);
    }
    if (s.solid) kick_stress(s, half, false, rates.threads);
    ++steps, ++since_rebuild;
    state_valid = false;
    dt_next = next_time_step(smallest);
    timings.total += seconds_since(t0);
    report_non_finite(finite);
}

// OpenRadioss decks: one cycle of the engine at the current positions x^n and velocities
// v^(n-1/2), dt1 = dt_(n-1/2) the step that led here (0 at cycle 0). The engine's order (resol.F,
// forintp.F; learnt from, not copied; OpenRadioss, AGPL-3.0):
//   1. the density at x^n, v^(n-1/2) with the old density: rho^n = rho^(n-1) (1 - dt1 div v), div v
//      with spdens.F's second-order term (radioss_time_step.hpp); the energy by the trapezoid of the
//      pressure over that volume change (the EOS update of eosmain),
//      de = -(p^(n-1) + p^n) / 2 d(1/rho); a solid's deviatoric stress by dt1 times its rate;
//   2. the forces at x^n, v^(n-1/2) with p^n (spforcp.F);
//   3. the next step dt2 (dtnoda.F or mdtsph.F) and the viscous heating over
//      dt12 = (dt1 + dt2) / 2 (spwfvis.F: the work of the viscous pair forces goes into the energy);
//   4. h follows the volume: h += dt1 h div v / 3 (spadah.F).
// radioss_step then moves: v^(n+1/2) = v^(n-1/2) + dt12 a^n, x^(n+1) = x^n + dt2 v^(n+1/2) (resol.F).
// So after a step the state is the engine's listing at that cycle: the internal energy with the
// viscous heating up to dt12 ahead, and the kinetic energy and momentum (totals(), state()) of the
// velocity synchronised to t^n, v^(n-1/2) + dt1 / 2 a^n (ecrit.F).
void Simulation::Impl::radioss_cycle(double dt1) {
    update_interacting();
    update_eos();
    if (timed_needs_rebuild())
        rebuild();
    else
        update_ghosts(s, in.planes, rates.threads);
    if (in.renormalise) {  // Order 1: the corrections once per cycle, before the density (spcompl.F)
        compute_corrections(s, list, rates.kernel, rates.threads);
        update_ghosts(s, in.planes, rates.threads);
    }
    rates.body = body_acceleration(in.loads, time);
    rates.viscosity_switch = nullptr;        // 1 reads only the density, h and stress rates (the SIMD rows may run)
    compute_rates(s, list, rates, scratch);  // 1: d rho/dt and dh/dt at the old density
    RadiossGradient gradient = radioss_velocity_gradient(s, list, dt1);
    const std::size_t n = s.real;
    s.h_half.resize(n);
#pragma omp parallel for schedule(static) num_threads(rates.threads)
    for (std::size_t i = 0; i < n; ++i) {
        if (!s.active[i]) continue;
        const PartSetup& part = in.parts[s.part[i]];
        const double rho_old = s.rho[i], p_old = s.p[i];
        const double div_extra = gradient.second_order[i];  // spdens.F's second-order term of div v
        s.rho[i] = rho_old + dt1 * (s.drho[i] - rho_old * div_extra);
        const double dv = 1 / rho_old - 1 / s.rho[i];  // -d(1/rho): > 0 in compression
        double p = 0, c = 0;
        part.eos.evaluate(s.rho[i], s.e[i] + p_old * dv, p, c);  // p^n with the energy predicted
        s.e[i] += 0.5 * (p_old + p) * dv;
        const double dh = s.dh[i] + (in.h_rule == SmoothingLengthRule::Divergence ? s.h[i] * div_extra / 3 : 0.0);
        s.h_half[i] = clamp_smoothing_length(s.h[i] + dt1 * dh, s.h_low[i], s.h_high[i]);  // 4, applied below
        if (s.solid)
            for (int k = 0; k < 6; ++k) s.stress[i][k] += dt1 * s.dstress[i][k];
    }
    update_eos();
    update_ghosts(s, in.planes, rates.threads);
    switches = std::move(gradient.f);
    rates.viscosity_switch = &switches;
    compute_rates(s, list, rates, scratch);  // 2
    if (!in.kinematic.empty()) apply_kinematic();
    heating.assign(n, 0.0);
#pragma omp parallel for schedule(static) num_threads(rates.threads)
    for (std::size_t i = 0; i < n; ++i)  // de/dt less the own pdV work (energy.hpp): the viscous heating
        if (s.active[i]) heating[i] = s.de[i] - s.p[i] * s.drho[i] / (s.rho[i] * s.rho[i]);
    dt_next = std::min(next_time_step(0.0), in.end_time - time);  // 3
    dt12 = 0.5 * (dt1 + dt_next);
    bool finite = true;
#pragma omp parallel for schedule(static) reduction(&& : finite) num_threads(rates.threads)
    for (std::size_t i = 0; i < n; ++i) {
        if (s.active[i]) s.e[i] += dt12 * heating[i], s.h[i] = s.h_half[i];
        finite = finite && is_finite(s, i);
    }
    state_valid = false;
    report_non_finite(finite);
}

void Simulation::Impl::radioss_step(Clock::time_point t0) {
    const std::size_t n = s.real;
#pragma omp parallel for schedule(static) num_threads(rates.threads)
    for (std::size_t i = 0; i < n; ++i) {
        if (!s.active[i]) continue;
        s.vx[i] += dt12 * s.ax[i], s.vy[i] += dt12 * s.ay[i], s.vz[i] += dt12 * s.az[i];
        s.x[i] += dt * s.vx[i], s.y[i] += dt * s.vy[i], s.z[i] += dt * s.vz[i];
    }
    reflect_crossed(s, in.planes, rates.threads);
    time += dt;
    deactivation.apply(s);
    dt1 = dt;
    radioss_cycle(dt);
    ++steps, ++since_rebuild;
    timings.total += seconds_since(t0);
}

Simulation::Setup Simulation::create(const model::Model& model, const RunOptions& options) {
    SetupResult r = build_setup(model, options);
    Setup setup;
    setup.unsupported = std::move(r.unsupported);
    if (!r.input) return setup;
    auto impl = std::make_unique<Impl>();
    impl->in = std::move(*r.input);
    // Small runs on one thread unless told: a handful of particles per thread costs more in
    // barriers than it gains (and far more on a loaded machine).
    constexpr std::size_t small_run = 4096;
    impl->rates.threads = options.threads > 0             ? options.threads
                          : impl->in.x.size() < small_run ? 1
                                                          : omp_get_max_threads();
    // Not told how many: as many as the cores other processes leave free, watched while the run goes.
    if (options.threads <= 0 && impl->rates.threads > 1) {
        impl->core_share.emplace(impl->rates.threads);
        impl->rates.threads = impl->core_share->threads();
    }
    impl->rates.simd = options.simd, impl->rates.avx512 = options.avx512;
    impl->rebuild_every_step = options.rebuild_every_step;
    for (const PartSetup& p : impl->in.parts) impl->part_ids.push_back(p.id);
    impl->initialise();
    setup.simulation.reset(new Simulation(std::move(impl)));
    return setup;
}

Simulation::Simulation(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Simulation::~Simulation() = default;

void Simulation::step() {
    if (!finished()) impl_->step();
}

bool Simulation::finished() const {
    const Impl& m = *impl_;
    if (!m.failure.empty()) return true;
    if (m.in.end_cycle > 0 && m.steps >= static_cast<std::size_t>(m.in.end_cycle)) return true;
    return m.time >= m.in.end_time * (1 - 1e-12);
}

void Simulation::run(const std::function<void(const Simulation&)>& observer) {
    while (!finished()) {
        step();
        if (observer) observer(*this);
    }
}

double Simulation::time() const { return impl_->time; }
double Simulation::end_time() const { return impl_->in.end_time; }
double Simulation::dt() const { return impl_->steps == 0 ? impl_->dt_next : impl_->dt; }
std::size_t Simulation::steps() const { return impl_->steps; }
int Simulation::dimension() const { return impl_->in.dimension; }
Timings Simulation::timings() const {
    Timings t = impl_->timings;
    t.rates = impl_->scratch.rates_seconds, t.merge = impl_->scratch.merge_seconds;
    return t;
}
const std::vector<long long>& Simulation::part_ids() const { return impl_->part_ids; }
const std::string& Simulation::failure() const { return impl_->failure; }
std::size_t Simulation::neighbour_rebuilds() const { return impl_->rebuilds; }
int Simulation::threads() const { return impl_->rates.threads; }

const ParticleState& Simulation::state() const {
    const Impl& m = *impl_;
    if (m.state_valid) return m.state;
    const Particles& s = m.s;
    ParticleState& out = m.state;
    const std::size_t n = s.real;
    for (auto* v : {&out.x, &out.y, &out.z, &out.vx, &out.vy, &out.vz, &out.rho, &out.e, &out.p, &out.h, &out.mass})
        v->resize(n);
    out.part.resize(n), out.active.resize(n);
    out.stress.resize(s.solid ? n : 0);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = s.model_index[k];
        out.x[i] = s.x[k], out.y[i] = s.y[k], out.z[i] = s.z[k];
        const std::array<double, 3> v = m.velocity(k);
        out.vx[i] = v[0], out.vy[i] = v[1], out.vz[i] = v[2];
        out.rho[i] = s.rho[k], out.e[i] = s.e[k], out.h[i] = s.h[k], out.mass[i] = s.m[k];
        out.p[i] = m.in.parts[s.part[k]].eos.pressure(s.rho[k], s.e[k]);  // at the final rho, e
        out.part[i] = s.part[k], out.active[i] = s.active[k];
        if (s.solid) out.stress[i] = s.stress[k];
    }
    m.state_valid = true;
    return out;
}

Totals Simulation::totals() const {
    const Impl& m = *impl_;
    const Particles& s = m.s;
    Totals t;
    t.time = m.time, t.dt = dt(), t.steps = m.steps, t.external_work = m.external_work;
    for (std::size_t i = 0; i < s.real; ++i) {
        if (!s.active[i]) continue;
        const double mass = s.m[i];
        t.mass += mass;
        const std::array<double, 3> v = m.velocity(i);
        t.kinetic += 0.5 * mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        t.internal += mass * s.e[i];
        t.momentum[0] += mass * v[0], t.momentum[1] += mass * v[1], t.momentum[2] += mass * v[2];
        ++t.active;
    }
    t.total = t.kinetic + t.internal;
    return t;
}

}  // namespace sphdeck::refsolver
