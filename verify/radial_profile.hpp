// The particles of a 2D case about the origin (Sedov, Noh) against radius, their total energy, and the
// figure of their profiles beside the exact solution.
#pragma once

#include <string>
#include <vector>

#include "verify/deck_run.hpp"

namespace sphdeck::verify {

struct RadialProfile {
    int n = 0;                         // particles along a side of the quarter
    std::vector<double> r, rho, u, p;  // active particles: radius, density, radial velocity, pressure
};

RadialProfile radial_profile(const ParticleState& s, int n);

// Kinetic plus internal energy of the active particles.
double total_energy(const ParticleState& s);

// The exact solution sampled along the radius, with its legend.
struct RadialCurve {
    std::string label;
    std::vector<double> r, rho, u, p;
};

// Density, radial velocity and pressure panels from r = 0 to `reach`: each run's particles as dots
// and the exact curve.
std::string radial_figure(const std::vector<const RadialProfile*>& runs, const RadialCurve& exact, double reach,
                          const std::string& title);

}  // namespace sphdeck::verify
