// The Noh implosion's exact solution (Noh 1987, J. Comput. Phys. 72, 78; the geometry factors as in
// lanl/ExactPack's noh1 and Gehmeyr, Cheng & Mihalas 1997): cold ideal gas of density rho0 streaming
// towards the origin (axis, plane) at speed u0. A shock leaves the centre at D = (gamma - 1) u0 / 2;
// behind it the gas is at rest with rho0 ((gamma + 1) / (gamma - 1))^j, e = u0^2 / 2; ahead of it the
// gas keeps its speed and is compressed by the convergence alone, rho0 (1 + u0 t / r)^(j - 1)
// (j = 1 planar, 2 cylindrical, 3 spherical). Used for the Noh case (docs/verification.md §5).
#pragma once

namespace sphdeck::verify {

struct NohSolution {
    int j = 2;
    double gamma = 5.0 / 3.0;
    double rho0 = 1.0, u0 = 1.0;  // u0 > 0: the inward speed

    struct State {
        double rho, u, p, e;  // u radial (negative: inward)
    };

    double shock_speed() const { return 0.5 * (gamma - 1) * u0; }
    double shock_radius(double t) const { return shock_speed() * t; }
    double post_shock_density() const;
    // Ahead of the shock (r > r_s): the streaming gas, p = 0.
    double pre_shock_density(double r, double t) const;
    State sample(double r, double t) const;
};

}  // namespace sphdeck::verify
