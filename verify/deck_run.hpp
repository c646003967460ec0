// Runs one verification deck through the reference solver in-process: read and check it as `sphdeck
// check` does, refuse it on read errors or on anything the solver cannot honour, step to the end time.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "refsolver/simulation.hpp"
#include "verify/case_result.hpp"

namespace sphdeck::verify {

// The solver types the cases drive (refsolver/ is a library that runs a model).
using refsolver::ParticleState;
using refsolver::RunOptions;
using refsolver::Simulation;
using refsolver::Unsupported;

struct DeckRun {
    RunRecord record;
    ParticleState initial;                   // state before the first step
    std::unique_ptr<Simulation> simulation;  // at the end time; null when `failure` is set
    std::string failure;  // why the deck did not run: a read error, deck errors, an unsupported feature
    std::string stopped;  // why a run that started was stopped before its end time (a collapsing time step)
};

// A run is stopped when it needs more than this many times the steps its first time step implies: the
// step has collapsed (the solution is blowing up), and waiting for the end would take hours.
inline constexpr double step_budget_factor = 10.0;

// `observer` is called after every step (it may be empty).
DeckRun run_deck(const std::filesystem::path& deck, const CaseOptions& options,
                 const std::function<void(const Simulation&)>& observer = {});

// The check a stopped run fails: the time reached against the end time (tolerance 0).
Check reached_end_time(const DeckRun& run);

// Adds `run` to `result`. False when the case cannot go on: the deck did not run (result.failure is
// set) or the run was stopped (its record, the failed end-time check and the reason are added).
bool add_run(CaseResult& result, const DeckRun& run);

}  // namespace sphdeck::verify
