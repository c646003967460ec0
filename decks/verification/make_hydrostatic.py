#!/usr/bin/env python3
"""Write the hydrostatic water column decks hydrostatic_2d_quick.k (20 particles across the depth) and
hydrostatic_2d.k (40 across).

verification.md section 2: a 2D tank (IDIM 2) of width W = 1 m filled to H = 1 m with water, rho0 = 1000
kg/m^3, g = 9.81 m/s^2, *EOS_MURNAGHAN (Tait) with gamma = 7 and K0 = rho0 c0^2 / 7, c0 = 10 sqrt(2 g H)
= 44.29 m/s. Walls: *BOUNDARY_SPH_SYMMETRY_PLANE at the bottom and both sides; the top is free. The
reference at rest is p(y) = rho0 g (H - y).

A deck cannot give each particle its own initial density (the solver starts every particle at the part's
RO), so the column starts uncompressed and gravity is ramped up by the *DEFINE_CURVE: a half-cosine from
0 to 1 over T_RAMP = 0.3 s (3.3 periods of the column's slowest acoustic mode, 4 H / c0 = 0.090 s), then
held. A load applied slowly compared with the system's period leaves little oscillation behind (the
quasi-static loading of dynamic relaxation); the run then settles for T_HOLD more seconds before the
pressure is compared. Monaghan viscosity alpha = 0.1 (Q2), beta = 0 (Q1), as in weakly compressible
SPH water runs.

Standard library only; deterministic. Run `python3 decks/verification/make_hydrostatic.py`.
"""

import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the decks
from lsdyna_cards import Deck, card, lattice, ruler  # noqa: E402

RHO, GAMMA, G = 1000.0, 7.0, 9.81
H, W = 1.0, 1.0
C0 = 10.0 * math.sqrt(2.0 * G * H)
K0 = RHO * C0 ** 2 / GAMMA
T_RAMP = 0.3
VARIANTS = {"hydrostatic_2d_quick.k": (20, 0.2), "hydrostatic_2d.k": (40, 0.4)}  # particles across H, T_HOLD


def ramp_points(samples=16):
    """Half-cosine ramp 0 -> 1 over T_RAMP as a piecewise-linear curve, then constant to t = 100 s."""
    points = [(round(T_RAMP * k / samples, 10), round(0.5 * (1.0 - math.cos(math.pi * k / samples)), 10))
              for k in range(samples + 1)]
    return points + [(100.0, 1.0)]


def hydrostatic_deck(ny, t_hold):
    dx = H / ny
    nx = round(W / dx)
    d = Deck(f"2D SPH hydrostatic water column, H = {H} m, W = {W} m, {nx} x {ny} particles")
    d.termination(T_RAMP + t_hold)
    d.timestep(0.3, "TSSFAC 0.3: dt = 0.3 h / (c + |v|).")
    d.control_sph()
    d.bulk_viscosity(0.0, 0.1, "Weakly compressible water: alpha = 0.1, beta = 0.")
    d.section_sph()
    d.part(1, "water", 1, 1, 1)
    d.mat_null(1, RHO)
    d.add("*EOS_MURNAGHAN",
          f"$ c0 = 10 sqrt(2 g H) = {C0:.4f} m/s; K0 = RO c0^2 / GAMMA.",
          ruler("eosid", "gamma", "k0", "v0"),
          card(1, GAMMA, K0, 1.0))
    d.gravity(G, ramp_points(),
              f"Gravity ramped up as 0.5 (1 - cos(pi t / {T_RAMP})) until t = {T_RAMP} s, then held.")
    d.symmetry_plane("Tank bottom y = 0", (0.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    d.symmetry_plane("Tank side x = 0", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    d.symmetry_plane(f"Tank side x = {W}", (W, 0.0, 0.0), (W - 1.0, 0.0, 0.0))
    mass = RHO * dx * dx
    points = [(x, y, 1, mass) for y in lattice(ny, dx) for x in lattice(nx, dx)]
    d.particles(points, [f"{nx} x {ny} particles on a square lattice of spacing {dx:g} m, half a spacing",
                         f"from the walls; free surface at y = H = {H} m. Mass RO dx^2 = {mass:g} kg/m."])
    return d


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for name, (ny, t_hold) in VARIANTS.items():
        path = hydrostatic_deck(ny, t_hold).write(here, name)
        print(f"wrote {path}: {round(W * ny / H) * ny} particles, K0 = {K0:g} Pa, c0 = {C0:.3f} m/s")


if __name__ == "__main__":
    main()
