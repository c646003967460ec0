#!/usr/bin/env python3
"""Write the Martin & Moyce dam-break decks dam_break_mm_quick.k (a / 20) and dam_break_mm.k (a / 40).

verification.md section 3: a water column of width a = 0.146 m and height 2 a (n^2 = 2) collapses along a
dry floor, IDIM 2. The tank is 5 a long, one a longer than the usual 4 a, so the surge front stays clear
of the far wall until T = t sqrt(2 g / a) = 3.15 (the experiment has Z/a = 3.7 at T = 2.95). Floor, back wall and
far wall are *BOUNDARY_SPH_SYMMETRY_PLANE planes. Water: rho0 = 1000 kg/m^3, *EOS_MURNAGHAN with
gamma = 7 and K0 = rho0 c0^2 / 7, c0 = 10 sqrt(2 g 2a) = 23.93 m/s; gravity *LOAD_BODY_Y with a constant
*DEFINE_CURVE. Monaghan viscosity alpha = 0.1 (Q2), beta = 0 (Q1), as in weakly compressible SPH dam
breaks. End time: T = 2.5 (quick) and T = 3.15 (past the last Koshizuka & Oka point, T = 3.096).

Standard library only; deterministic. Run `python3 decks/verification/make_dam_break.py`.
"""

import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the decks
from lsdyna_cards import Deck, card, lattice, ruler  # noqa: E402

RHO, GAMMA, G = 1000.0, 7.0, 9.81
A = 0.146
TANK = 5.0 * A
C0 = 10.0 * math.sqrt(2.0 * G * 2.0 * A)
K0 = RHO * C0 ** 2 / GAMMA
T_SCALE = math.sqrt(A / (2.0 * G))  # t = T * T_SCALE
VARIANTS = {"dam_break_mm_quick.k": (20, 2.5), "dam_break_mm.k": (40, 3.15)}  # particles across a, end T


def dam_break_deck(nx, end_T):
    dx = A / nx
    ny = 2 * nx
    end_time = round(end_T * T_SCALE, 6)
    d = Deck(f"2D SPH dam break, Martin & Moyce: a = {A} m, column a x 2a, {nx} x {ny} particles")
    d.termination(end_time)
    d.timestep(0.3, "TSSFAC 0.3: dt = 0.3 h / (c + |v|).")
    d.control_sph()
    d.bulk_viscosity(0.0, 0.1, "Weakly compressible water: alpha = 0.1, beta = 0.")
    d.section_sph()
    d.part(1, "water column", 1, 1, 1)
    d.mat_null(1, RHO)
    d.add("*EOS_MURNAGHAN",
          f"$ c0 = 10 sqrt(2 g 2a) = {C0:.4f} m/s; K0 = RO c0^2 / GAMMA.",
          ruler("eosid", "gamma", "k0", "v0"),
          card(1, GAMMA, K0, 1.0))
    d.gravity(G, [(0.0, 1.0), (100.0, 1.0)], "Constant gravity from t = 0.")
    d.symmetry_plane("Tank floor y = 0", (0.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    d.symmetry_plane("Back wall x = 0", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    d.symmetry_plane(f"Far wall x = 5a = {round(TANK, 10)}", (TANK, 0.0, 0.0), (TANK - 1.0, 0.0, 0.0))
    mass = RHO * dx * dx
    points = [(x, y, 1, mass) for y in lattice(ny, dx) for x in lattice(nx, dx)]
    d.particles(points, [f"{nx} x {ny} particles on a square lattice of spacing a/{nx} = {dx:g} m, half a",
                         f"spacing from the walls. End time T = {end_T}: t = {end_time} s. Mass RO dx^2."])
    return d


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for name, (nx, end_T) in VARIANTS.items():
        path = dam_break_deck(nx, end_T).write(here, name)
        print(f"wrote {path}: {2 * nx * nx} particles, K0 = {K0:g} Pa, c0 = {C0:.3f} m/s")


if __name__ == "__main__":
    main()
