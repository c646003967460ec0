// Reference-solver benchmark: a 3D dam break of about 100,000 particles (a 0.6 x 0.6 x 0.28 m water
// block at 1 cm spacing in a 1.6 m tank; floor and walls are *BOUNDARY_SPH_SYMMETRY_PLANE; gravity
// by *LOAD_BODY_Y; *MAT_NULL + *EOS_MURNAGHAN), written as deck text and read by the same reader as
// `sphdeck run`. For 1 and 2 OpenMP threads, several repetitions of STEPS steps each:
//   particle updates per second = particles * steps / wall time of the steps,
//   neighbour share = time rebuilding lists / time of the steps,
// and the cost of one rebuild (the one at set-up) in steps. Medians are printed.
//   bench_refsolver [steps = 30] [repetitions = 3] [spacing = 0.01]
// Goal (issue 7): >= 1,000,000 particle updates/s on 2 threads, rebuild <= 5% of a step.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <string>
#include <vector>

#include "lint/pipeline.hpp"
#include "refsolver/simulation.hpp"

using namespace sphdeck;

namespace {

std::string dam_break_deck(double dx) {
    const int nx = static_cast<int>(0.6 / dx + 0.5), ny = nx, nz = static_cast<int>(0.28 / dx + 0.5);
    const double width = nz * dx, rho = 1000, gamma = 7, height = ny * dx;
    const double c0 = 10 * std::sqrt(2 * 9.81 * height), k0 = rho * c0 * c0 / gamma;
    std::string d = "*KEYWORD\n*CONTROL_TERMINATION\n10.0\n*CONTROL_TIMESTEP\n0,0.3\n";
    d += "*CONTROL_SPH\n1,0,1e20,3,150,0,0,1e15\n*CONTROL_BULK_VISCOSITY\n1.0,1.0\n";
    d += "*SECTION_SPH\n1,1.2,0.2,2.0\n*PART\nwater\n1,1,1,1\n";
    d += fmt::format("*MAT_NULL\n1,{}\n*EOS_MURNAGHAN\n1,{},{},1\n", rho, gamma, k0);
    d += "*LOAD_BODY_Y\n1,9.81\n*DEFINE_CURVE\n1\n0,1\n100,1\n";
    for (const char* plane : {"0,0,0,1,0,0", "1.6,0,0,0.6,0,0", "0,0,0,0,1,0", "0,0,0,0,0,1"})
        d += fmt::format("*BOUNDARY_SPH_SYMMETRY_PLANE\n{}\n", plane);
    d += fmt::format("*BOUNDARY_SPH_SYMMETRY_PLANE\n0,0,{},0,0,{}\n", width, width - 1);
    std::string nodes = "*NODE\n", elements = "*ELEMENT_SPH\n";
    const double mass = rho * dx * dx * dx;
    long long id = 1;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i, ++id) {
                nodes += fmt::format("{},{},{},{}\n", id, (i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx);
                elements += fmt::format("{},1,{}\n", id, mass);
            }
    return d + nodes + elements + "*END\n";
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

int main(int argc, char** argv) {
    const int steps = argc > 1 ? std::atoi(argv[1]) : 30;
    const int repetitions = argc > 2 ? std::atoi(argv[2]) : 3;
    const double dx = argc > 3 ? std::atof(argv[3]) : 0.01;
    const lint::CheckResult deck = lint::check_buffer(dam_break_deck(dx), "dam_break_3d.k");
    const std::size_t n = deck.model.particles.size();
    fmt::print("3D dam break: {} particles, spacing {} m, {} steps x {} repetitions per thread count\n", n, dx, steps,
               repetitions);
    bool met = true;
    for (int threads : {1, 2}) {
        std::vector<double> rate, share, rebuild_in_steps, rebuilds;
        for (int r = 0; r < repetitions; ++r) {
            refsolver::RunOptions options;
            options.threads = threads;
            options.end_time = 10.0;
            auto setup = refsolver::Simulation::create(deck.model, options);
            if (!setup.simulation) {
                for (const auto& u : setup.unsupported) fmt::print(stderr, "{}\n", u.what);
                return 1;
            }
            refsolver::Simulation& sim = *setup.simulation;
            const refsolver::Timings before = sim.timings();  // set-up: one list build + one evaluation
            const std::size_t rebuilds_before = sim.neighbour_rebuilds();
            const auto t0 = std::chrono::steady_clock::now();
            for (int s = 0; s < steps; ++s) sim.step();
            const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            const refsolver::Timings after = sim.timings();
            const double step_time = (after.total - before.total) / steps;
            rate.push_back(double(n) * steps / wall);
            share.push_back((after.neighbours - before.neighbours) / (after.total - before.total));
            rebuild_in_steps.push_back(before.neighbours / step_time);
            rebuilds.push_back(double(sim.neighbour_rebuilds() - rebuilds_before));
        }
        const double r = median(rate), s = median(share);
        fmt::print("threads {}: {:.3g} particle updates/s; neighbour rebuild share of the steps {:.1f}% ({} rebuilds "
                   "in {} steps); one rebuild costs {:.2f} steps\n",
                   threads, r, 100 * s, median(rebuilds), steps, median(rebuild_in_steps));
        if (threads == 2) met = r >= 1e6 && s <= 0.05;
    }
    fmt::print("goal (2 threads: >= 1e6 updates/s, rebuild <= 5%): {}\n", met ? "met" : "not met");
    return 0;
}
