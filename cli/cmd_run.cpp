// sphdeck run DECK: runs the deck with the reference SPH solver (refsolver/simulation.hpp): lists
// what the solver does not honour (and refuses, exit 2, when that changes the physics, unless
// --ignore-unsupported), draws a progress bar on a terminal, writes a time history, .vtp
// snapshots and their .pvd time series with --out, and ends with a summary: steps, wall time,
// particle updates per second, mass, momentum and the energy balance. Equations and settings: docs/solver.md.
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <optional>

#include "cli/commands.hpp"
#include "cli/progress_bar.hpp"
#include "cli/progress_log.hpp"
#include "diag/render_text.hpp"
#include "io/csv_writer.hpp"
#include "io/pvd_writer.hpp"
#include "io/vtp_writer.hpp"
#include "engine/check.hpp"
#include "text/source_map.hpp"
#include "refsolver/simulation.hpp"

namespace sphdeck::cli {
namespace {

struct RunArgs {
    std::string deck, out;
    std::size_t every = 100;
    std::optional<double> end_time;
    int threads = 0;
    bool ignore_unsupported = false, quiet = false;
    double progress_every = 5.0;  // seconds between progress lines off a terminal
    std::vector<std::string> include_paths;
};

// One row per step: the time history.
struct History {
    std::vector<double> time, dt, kinetic, internal, total, work, mx, my, mz, mass;
    std::vector<long long> active, step;

    void add(const refsolver::Totals& t) {
        step.push_back(static_cast<long long>(t.steps)), time.push_back(t.time), dt.push_back(t.dt);
        kinetic.push_back(t.kinetic), internal.push_back(t.internal), total.push_back(t.total);
        work.push_back(t.external_work), mx.push_back(t.momentum[0]), my.push_back(t.momentum[1]);
        mz.push_back(t.momentum[2]), mass.push_back(t.mass), active.push_back(static_cast<long long>(t.active));
    }
    void write(const std::string& path) const {
        using D = std::span<const double>;
        const std::vector<io::Column> columns = {{"step", std::span<const long long>(step)},
                                                 {"time", D(time)},
                                                 {"dt", D(dt)},
                                                 {"kinetic", D(kinetic)},
                                                 {"internal", D(internal)},
                                                 {"total", D(total)},
                                                 {"external_work", D(work)},
                                                 {"momentum_x", D(mx)},
                                                 {"momentum_y", D(my)},
                                                 {"momentum_z", D(mz)},
                                                 {"mass", D(mass)},
                                                 {"active", std::span<const long long>(active)}};
        io::write_csv_file(path, columns);
    }
};

// The .vtp snapshots of a run and their .pvd collection (particles.pvd), rewritten after each
// snapshot so that a run stopped early still leaves a series ParaView plays in simulation time.
class Snapshots {
public:
    explicit Snapshots(std::string dir) : dir_(std::move(dir)) {}

    void write(const refsolver::Simulation& sim) {
        const refsolver::ParticleState& s = sim.state();
        const std::size_t n = s.size();
        std::vector<long long> part(n);
        std::vector<std::uint32_t> active(s.active.begin(), s.active.end());
        for (std::size_t i = 0; i < n; ++i) part[i] = sim.part_ids()[s.part[i]];
        using D = std::span<const double>;
        io::VtpPoints points{s.x,
                             s.y,
                             s.z,
                             {{"density", D(s.rho)},
                              {"pressure", D(s.p)},
                              {"energy", D(s.e)},
                              {"h", D(s.h)},
                              {"mass", D(s.mass)},
                              {"part", std::span<const long long>(part)},
                              {"active", std::span<const std::uint32_t>(active)}},
                             {{"velocity", {D(s.vx), D(s.vy), D(s.vz)}, {"X", "Y", "Z"}}}};
        // Solids (*MAT_ELASTIC): the Cauchy stress sigma = S - p I as a symmetric tensor in VTK's
        // component order XX YY ZZ XY YZ XZ (the solver keeps S as xx yy zz xy xz yz).
        std::array<std::vector<double>, 6> sigma;
        if (!s.stress.empty()) {
            constexpr int from[6] = {0, 1, 2, 3, 5, 4};
            for (int k = 0; k < 6; ++k) {
                sigma[k].resize(n);
                for (std::size_t i = 0; i < n; ++i) sigma[k][i] = s.stress[i][from[k]] - (k < 3 ? s.p[i] : 0.0);
            }
            points.tuple_data.push_back({"stress",
                                         {D(sigma[0]), D(sigma[1]), D(sigma[2]), D(sigma[3]), D(sigma[4]), D(sigma[5])},
                                         {"XX", "YY", "ZZ", "XY", "YZ", "XZ"}});
        }
        const std::string file = fmt::format("particles_{:06}.vtp", sim.steps());
        io::write_vtp_file(dir_ + "/" + file, points, io::VtpEncoding::Base64);
        if (!entries_.empty() && entries_.back().file == file) entries_.pop_back();  // same step written again
        entries_.push_back({sim.time(), file});
        io::write_pvd_file(dir_ + "/particles.pvd", entries_);
    }

private:
    std::string dir_;
    std::vector<io::PvdEntry> entries_;
};

std::string span_location(const grammar::Span& span, const grammar::SourceMap& sources, const std::string& deck) {
    return diag::detail::has_location(span, sources) ? diag::detail::location(span, sources) : deck;
}

// Prints the unsupported list; returns whether something fatal is in it.
bool print_unsupported(const std::vector<refsolver::Unsupported>& items, const engine::CheckResult& r,
                       const RunArgs& args) {
    bool fatal = false;
    for (const refsolver::Unsupported& u : items) {
        const bool stops = u.blocking || (u.fatal && !args.ignore_unsupported);
        fatal = fatal || stops;
        const char* severity = stops ? "error" : u.fatal ? "warning" : "note";
        if (!args.quiet || stops)
            fmt::print(stderr, "{}: {}: {}{}\n", span_location(u.span, r.deck.sources, args.deck), severity,
                       diag::detail::printable(u.what),
                       u.fatal && !u.blocking && args.ignore_unsupported ? " (ignored)" : "");
    }
    return fatal;
}

std::string vec3(const std::array<double, 3>& v) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", v[0], v[1], v[2]); }

void print_summary(const refsolver::Simulation& sim, const refsolver::Totals& start, const refsolver::Totals& end,
                   double wall, std::size_t particles) {
    const double updates = wall > 0 ? double(particles) * double(end.steps) / wall : 0.0;
    fmt::print("steps: {}  end time: {:.6g}  wall time: {:.3f} s  particle updates/s: {:.3g}\n", end.steps, end.time,
               wall, updates);
    const refsolver::Timings timing = sim.timings();
    fmt::print("neighbour rebuilds: {} ({:.1f}% of the wall time of the steps)\n", sim.neighbour_rebuilds(),
               timing.total > 0 ? 100.0 * timing.neighbours / timing.total : 0.0);
    fmt::print("active particles: {} of {}\n", end.active, particles);
    // Ten digits: the sums' last digits follow the summation order, not the physics.
    fmt::print("mass: start {:.10g}, end {:.10g}{}\n", start.mass, end.mass,
               start.active == end.active ? " (unchanged: particle masses are constant)" : " (particles deactivated)");
    fmt::print("momentum: start {}, end {}\n", vec3(start.momentum), vec3(end.momentum));
    fmt::print("energy: kinetic {:.6g} -> {:.6g}, internal {:.6g} -> {:.6g}, total {:.6g} -> {:.6g}\n", start.kinetic,
               end.kinetic, start.internal, end.internal, start.total, end.total);
    // Drift of the energy balance: total - work of the body loads should stay at its start value.
    const double imbalance = end.total - end.external_work - start.total;
    const double scale = std::max({std::abs(start.total), std::abs(end.external_work), std::abs(end.total)});
    fmt::print("work of the body loads: {:.6g}; energy drift (total - work - total at start): {:.6g}",
               end.external_work, imbalance);
    if (scale > 0) fmt::print(" ({:.3g}% of {:.6g})", 100.0 * imbalance / scale, scale);
    fmt::print("\n");
}

int run_deck(const RunArgs& args) {
    engine::CheckOptions options;
    options.reader.include_paths = args.include_paths;
    const engine::CheckResult r = engine::check_file(args.deck, options);
    std::size_t read_errors = 0;
    for (const diag::Diagnostic& d : r.diagnostics)
        if (d.severity == diag::Severity::Error && d.code.rfind("DK", 0) == 0) {
            fmt::print(stderr, "{}", diag::render_concise(d, r.deck.sources));
            ++read_errors;
        }
    if (read_errors > 0) {
        fmt::print(stderr, "sphdeck: error: {}: {} reading error(s): not run\n", args.deck, read_errors);
        return exit_usage;
    }

    refsolver::RunOptions run_options;
    run_options.end_time = args.end_time;
    run_options.threads = args.threads;
    run_options.ignore_unsupported = args.ignore_unsupported;
    run_options.deck = &r.deck;  // OpenRadioss decks: /RUN and /INIVEL
    const auto t_setup = std::chrono::steady_clock::now();
    refsolver::Simulation::Setup setup = refsolver::Simulation::create(r.model, run_options);
    const bool fatal = print_unsupported(setup.unsupported, r, args);
    if (!setup.simulation || fatal) {
        const bool blocking = std::any_of(setup.unsupported.begin(), setup.unsupported.end(),
                                          [](const refsolver::Unsupported& u) { return u.blocking; });
        fmt::print(stderr, "sphdeck: error: {}: not run{}\n", args.deck,
                   blocking ? "" : " (--ignore-unsupported runs it without what is listed above)");
        return exit_usage;
    }
    refsolver::Simulation& sim = *setup.simulation;
    const double setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_setup).count();
    const std::size_t particles = sim.state().size();
    if (!args.quiet)
        fmt::print("{}: {} particles, {}D, end time {:.6g}, first time step {:.3g} (set-up {:.2f} s)\n", args.deck,
                   particles, sim.dimension(), sim.end_time(), sim.dt(), setup_seconds);

    History history;
    const refsolver::Totals start = sim.totals();
    history.add(start);
    Snapshots snapshots(args.out);
    if (!args.out.empty()) {
        std::filesystem::create_directories(args.out);
        snapshots.write(sim);
    }
    ProgressBar bar("run", !args.quiet && ProgressBar::stderr_is_terminal());
    ProgressLog log(!args.quiet && !ProgressBar::stderr_is_terminal(), args.progress_every);
    const auto t0 = std::chrono::steady_clock::now();
    sim.run([&](const refsolver::Simulation& s) {
        history.add(s.totals());
        if (!args.out.empty() && args.every > 0 && s.steps() % args.every == 0 && !s.finished()) snapshots.write(s);
        bar.update(s.end_time() > 0 ? s.time() / s.end_time() : 1.0);
        log.update(s.steps(), s.time(), s.end_time(), s.dt(), particles);
    });
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    bar.finish();
    const refsolver::Totals end = sim.totals();
    if (!args.out.empty()) {
        snapshots.write(sim);
        history.write(args.out + "/history.csv");
    }
    print_summary(sim, start, end, wall, particles);
    if (!args.out.empty())
        fmt::print("wrote {0}/history.csv, particles_*.vtp and {0}/particles.pvd (open it in ParaView)\n", args.out);
    if (!sim.failure().empty()) {
        fmt::print(stderr, "sphdeck: error: {}: the run stopped: {}\n", args.deck, sim.failure());
        return exit_findings;
    }
    return exit_clean;
}

}  // namespace

std::function<int()> setup_run(CLI::App& app) {
    auto args = std::make_shared<RunArgs>();
    app.add_option(
           "deck", args->deck,
           "LS-DYNA keyword deck, or OpenRadioss starter deck <run>_0000.rad (its engine deck <run>_0001.rad beside it)")
        ->required();
    app.add_option("--out", args->out,
                   "folder for history.csv (one row per step), particles_NNNNNN.vtp "
                   "snapshots and particles.pvd, their time series for ParaView (created if missing)");
    app.add_option("--every", args->every, "write a snapshot every N steps (0: only the first and the last)")
        ->capture_default_str();
    app.add_option("--end-time", args->end_time, "end time, instead of *CONTROL_TERMINATION ENDTIM (OpenRadioss: /RUN)")
        ->check(CLI::PositiveNumber);
    app.add_option("--threads", args->threads, "OpenMP threads (0: the OpenMP default)")->check(CLI::NonNegativeNumber);
    app.add_flag("--ignore-unsupported", args->ignore_unsupported,
                 "run even when the deck uses what the solver does not honour (it is left out)");
    app.add_flag("--quiet", args->quiet, "print only the summary and errors, no progress bar");
    app.add_option("--progress-every", args->progress_every,
                   "seconds between progress lines when stderr is no terminal (a CI log)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    app.add_option("-I,--include-path", args->include_paths, "extra folder searched for *INCLUDE files")
        ->allow_extra_args(false);
    return [args] { return run_deck(*args); };
}

}  // namespace sphdeck::cli
