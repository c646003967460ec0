#include "verify/deck_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <fmt/format.h>

#include "diag/diagnostic.hpp"
#include "engine/check.hpp"

namespace sphdeck::verify {

DeckRun run_deck(const std::filesystem::path& deck, const CaseOptions& options,
                 const std::function<void(const Simulation&)>& observer) {
    DeckRun run;
    run.record.deck = deck.filename().string();
    run.record.threads = options.threads;
    if (options.progress) options.progress(fmt::format("running {}", deck.string()));
    engine::CheckResult checked;
    try {
        checked = engine::check_file(deck.string());
    } catch (const std::exception& e) {
        run.failure = fmt::format("cannot read {}: {}", deck.string(), e.what());
        return run;
    }
    std::size_t errors = 0;
    for (const diag::Diagnostic& d : checked.diagnostics) errors += d.severity == diag::Severity::Error;
    if (errors > 0) {
        run.failure =
            fmt::format("{} has {} error(s); 'sphdeck check {}' lists them", deck.string(), errors, deck.string());
        return run;
    }
    RunOptions run_options;
    run_options.deck = &checked.deck;  // OpenRadioss decks: /RUN and /INIVEL (model/radioss_run_input.hpp)
    run_options.threads = options.threads;
    Simulation::Setup setup = Simulation::create(checked.model, run_options);
    if (!setup.simulation) {
        std::string why;
        for (const Unsupported& u : setup.unsupported)
            if (u.fatal) why += fmt::format("{}{}", why.empty() ? "" : "; ", u.what);
        run.failure = fmt::format("the solver refuses {}: {}", deck.string(), why.empty() ? "no reason given" : why);
        return run;
    }
    Simulation& sim = *setup.simulation;
    run.initial = sim.state();
    const auto start = std::chrono::steady_clock::now();
    const double budget = step_budget_factor * std::max(1.0, (sim.end_time() - sim.time()) / sim.dt());
    while (!sim.finished()) {
        sim.step();
        if (observer) observer(sim);
        if (static_cast<double>(sim.steps()) > budget) {
            run.stopped = fmt::format(
                "stopped at t = {:.4g} of {:.4g} after {} steps ({} times the {:.0f} the first time "
                "step implies): the time step collapsed to {:.3g}",
                sim.time(), sim.end_time(), sim.steps(), step_budget_factor, budget / step_budget_factor, sim.dt());
            break;
        }
    }
    if (run.stopped.empty() && !sim.failure().empty()) run.stopped = sim.failure();
    run.record.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.record.particles = sim.state().size();
    run.record.steps = sim.steps();
    run.record.end_time = sim.time();
    run.simulation = std::move(setup.simulation);
    return run;
}

Check reached_end_time(const DeckRun& run) {
    const double t = run.simulation->time(), end = run.simulation->end_time();
    return {fmt::format("{}: time reached (run stopped: the solution blew up)", run.record.deck), t, end,
            std::abs(t - end) / end, 0.0};
}

bool add_run(CaseResult& result, const DeckRun& run) {
    if (!run.failure.empty()) {
        result.failure = run.failure;
        return false;
    }
    result.runs.push_back(run.record);
    if (run.stopped.empty()) return true;
    result.checks.push_back(reached_end_time(run));
    result.method.push_back(run.stopped);
    return false;
}

}  // namespace sphdeck::verify
