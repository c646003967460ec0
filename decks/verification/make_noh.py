#!/usr/bin/env python3
"""Write the Noh implosion decks noh_2d_<N>.k (N particles along each side of a quarter plane).

docs/verification.md section 5: the cylindrical Noh problem (Noh 1987, J. Comput. Phys. 72, 78) in the
plane. Cold ideal gas (gamma = 5/3, rho0 = 1, p0 ~ 0) streams towards the origin at unit speed,
v = -x / |x|. A shock starts at the origin and runs out at D = (gamma - 1) / 2 = 1/3; behind it the gas
is at rest with rho = rho0 ((gamma + 1) / (gamma - 1))^2 = 16 (the "2" is the geometry: cylindrical,
j = 2; spherical Noh gives 64), e = 1/2, p = 16/3. Ahead of it the gas still streams inward, compressed
by the convergence alone: rho = rho0 (1 + t / r). Compared at t = 0.6 (shock at r = 0.2).

IDIM 2 (plane strain): the plane of an infinite cylinder. Only the quarter x >= 0, y >= 0 is modelled:
symmetry planes at x = 0 and y = 0 mirror it into the full plane. The outer edges x = 1 and y = 1 are
free: with p0 ~ 0 nothing pushes the edge particles out, and by t = 0.6 the gas that has crossed the
shock came from r <= 0.8, so the edges never reach the compared region.

Gas: *MAT_NULL RO = 1 + *EOS_LINEAR_POLYNOMIAL C4 = C5 = gamma - 1 = 2/3 (p = (gamma - 1) rho e),
E0 = RO e with p0 = 1e-6. The velocity is given per particle by *INITIAL_VELOCITY_NODE (a deck has
no radial initial velocity by part; the velocity has unit length to the 7 digits a field holds).
Monaghan viscosity alpha = 1, beta = 2 as for Sod and Sedov; TSSFAC 0.3; h0 = 1.2 dx (CSLH), HMIN 0.2
(the LS-DYNA default: the gas compresses 16-fold, so h must shrink to a quarter) and HMAX 2.
FORM 0, the default (Sedov needs FORM 1, this case does not): the inflow is compressed tangentially
4-fold by the convergence and the shock compresses it 4-fold radially, so the shocked lattice is
compressed alike in both directions and DERIV 0's h ~ rho^(-1/2) follows its spacing (Sedov's shell is
compressed 6-fold radially only). Measured (docs/verification.md section 5): post-shock density 15.50 /
15.97 at N = 50 / 100 with FORM 0; FORM 1 keeps the volume-weighted continuity (refsolver/continuity.hpp)
and stays too dense, 17.25 / 17.83.

Standard library only; deterministic. Run `python3 decks/verification/make_noh.py`.
"""

import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the decks
from lsdyna_cards import Deck, card, field, lattice, ruler  # noqa: E402

GAMMA = 5.0 / 3.0
RHO0 = 1.0
P_AMBIENT = 1.0e-6
BOX = 1.0             # the quarter [0, BOX]^2
END_TIME = 0.6
RESOLUTIONS = (35, 50, 70, 100)  # quick: 35 and 70; full: 50 and 100


def noh_deck(n):
    dx = BOX / n
    mass = RHO0 * dx * dx
    points = [(x, y) for y in lattice(n, dx) for x in lattice(n, dx)]
    e_ambient = P_AMBIENT / ((GAMMA - 1) * RHO0)
    d = Deck(f"2D SPH Noh implosion, quarter plane {n} x {n}, gamma 5/3, t = {END_TIME}")
    d.termination(END_TIME)
    d.timestep(0.3, "TSSFAC 0.3: dt = 0.3 h / (c + |v|), room for the viscous term at shocks.")
    d.control_sph()
    d.bulk_viscosity(2.0, 1.0, "Classic Monaghan values for gas dynamics: alpha = 1, beta = 2.")
    d.section_sph(why="HMIN 0.2 (default): h must follow a 16-fold compression (make_noh.py).")
    d.part(1, "cold ideal gas, gamma 5/3", 1, 1, 1)
    d.mat_null(1, RHO0)
    d.add("*EOS_LINEAR_POLYNOMIAL",
          "$ Ideal gas: p = (C4 + C5 mu) E = (gamma - 1) rho e with C4 = C5 = gamma - 1;",
          f"$ E0 = RO e per reference volume, p0 = {P_AMBIENT:g}.",
          ruler("eosid", "c0", "c1", "c2", "c3", "c4", "c5", "c6"),
          card(1, 0.0, 0.0, 0.0, 0.0, GAMMA - 1, GAMMA - 1, 0.0),
          ruler("e0", "v0"),
          card(RHO0 * e_ambient, 1.0))
    d.symmetry_plane("Axis x = 0", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    d.symmetry_plane("Axis y = 0", (0.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    rows = [(x, y, 1, mass) for x, y in points]
    d.particles(rows, [f"{n} x {n} particles on a square lattice of spacing 1/{n}, half a spacing",
                       "from the axes; the edges x = 1 and y = 1 are free. Mass RO dx^2."])
    d.add("*INITIAL_VELOCITY_NODE", "$ Unit speed towards the origin: v = -x / |x|.",
          ruler("nid", "vx", "vy", "vz", "vxr", "vyr", "vzr"))
    for nid, (x, y) in enumerate(points, 1):
        r = math.hypot(x, y)
        d.add(field(nid, 10) + field(-x / r, 10) + field(-y / r, 10) + field(0.0, 10))
    return d


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for n in RESOLUTIONS:
        path = noh_deck(n).write(here, f"noh_2d_{n}.k")
        print(f"wrote {path}: {n * n} particles")


if __name__ == "__main__":
    main()
