// Stable time-step estimates of a particle at rest (sph-algorithms.md §7).
#pragma once

namespace sphdeck::preproc {

// LS-DYNA-style CFL step: scale * h / (c + |v|); 0 when c + |v| is not positive.
double cfl_time_step(double h, double c, double scale, double speed = 0.0);

// The OpenRadioss particle time step as coded in mdtsph.F for an inviscid material:
// dt = scale * h / (QX + sqrt(QX^2 + c^2)), QX = qb c + qa mu_bar. At rest (mu_bar = 0) with the
// /PROP/SPH default qb = 1 this is scale * h / (c (1 + sqrt 2)). 0 when c is not positive.
double radioss_particle_time_step(double h, double c, double scale, double qa = 2.0, double qb = 1.0,
                                  double mu_bar = 0.0);

}  // namespace sphdeck::preproc
