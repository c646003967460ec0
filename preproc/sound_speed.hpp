// Sound speeds at the reference state (sph-algorithms.md §10), for the time-step estimates.
// With an equation of state the bulk sound speed comes from the EOS and a material with shear
// stiffness adds it: c^2 = c_eos^2 + 4G / (3 rho0). Without one, elastic materials give the
// dilatational wave speed sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu) rho0)), the conservative choice for
// a time step (the bulk speed sqrt(K / rho0) is lower).
#pragma once

#include <string>

#include "model/model.hpp"

namespace sphdeck::preproc {

// *EOS_MURNAGHAN: c0 = sqrt(gamma k0 / rho0).
double murnaghan_sound_speed(double gamma, double k0, double rho0);
// *EOS_LINEAR_POLYNOMIAL at mu = 0, E = E0: c0^2 = (C1 + C5 E0 + C4 p0) / rho0, p0 = C0 + C4 E0.
double linear_polynomial_sound_speed(const double (&c)[7], double e0, double rho0);
// Dilatational wave speed of an isotropic elastic solid.
double elastic_sound_speed(double young, double poisson, double rho0);

struct SoundSpeed {
    double c = 0;        // 0 when unknown
    std::string source;  // "*EOS_MURNAGHAN", "*MAT_ELASTIC", ...
    std::string note;    // why c is missing or approximate, in words
};

// The sound speed of a part's material and EOS (either may be missing: nullptr).
SoundSpeed sound_speed(const model::Model& model, const model::Material* material, const model::Eos* eos);

}  // namespace sphdeck::preproc
