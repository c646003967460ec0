// The Sedov-Taylor point-blast similarity solution for an ideal gas at rest with uniform density rho0
// and no counter-pressure (Sedov 1959, "Similarity and Dimensional Methods in Mechanics", ch. IV;
// Kamm & Timmes 2007, LA-UR-07-2849, for the geometries and the energy constant), solved numerically:
// the similarity ODEs are integrated inward from the strong shock, and the energy integral gives alpha
// in E = alpha rho0 r_s^(j+2) / t^2 (j = 1 planar, 2 cylindrical, 3 spherical; E per unit area, per
// unit length, or total). Used for the Sedov case (docs/verification.md §4).
#pragma once

#include <optional>
#include <vector>

namespace sphdeck::verify {

struct SedovProfilePoint {
    double xi;         // r / r_s, from 1 (the shock) inward
    double rho, u, p;  // rho / rho0, u / u_shock, p / p_shock (the post-shock values are 1 at xi = 1)
};

struct SedovSolution {
    int j = 2;
    double gamma = 1.4;
    double alpha = 0;                        // E = alpha rho0 r_s^(j+2) / t^2
    double density_ratio = 0;                // (gamma + 1) / (gamma - 1), at the shock
    std::vector<SedovProfilePoint> profile;  // xi descending from 1 towards 0

    // r_s(t) for energy E (per unit area / length / total as j) in gas of density rho0.
    double shock_radius(double energy, double rho0, double t) const;
    // rho, u, p at radius r and time t (u radial); ambient (rho0, 0, 0) beyond the shock.
    struct State {
        double rho, u, p;
    };
    State sample(double r, double energy, double rho0, double t) const;
};

// nullopt for j outside 1..3 or gamma <= 1.
std::optional<SedovSolution> solve_sedov(int j, double gamma);

}  // namespace sphdeck::verify
