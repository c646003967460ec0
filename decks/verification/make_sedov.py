#!/usr/bin/env python3
"""Write the Sedov-Taylor blast-wave decks sedov_2d_<N>.k (N particles along each side of a quarter plane).

docs/verification.md section 4: a line explosion in an ideal gas (gamma = 1.4) at rest, density 1, the
cylindrical (j = 2) similarity solution of Sedov / Kamm & Timmes in the plane. IDIM 2 (plane strain): the
energy E = 1 is per unit length of the line source, the masses per unit thickness. Only the quarter
x >= 0, y >= 0 is modelled: symmetry planes at x = 0 and y = 0 mirror it into the full plane, and planes
at x = y = 1 close the box (the shock reaches r_s = 0.71 at t = 0.5, well inside). The quarter holds E / 4.

The point energy goes into the particles within 3 dx of the origin (8 in the quarter, 32 in the full plane,
at every resolution, so the deposit shrinks towards a point as dx does) as one hot part with the same RO: a
deck gives each part its own initial energy (*EOS_LINEAR_POLYNOMIAL E0, per reference volume), not each
particle. The ambient gas has p0 = 1e-6, negligible against the post-shock pressure (0.42 at t = 0.5): the
strong-shock limit of the similarity solution.

Gas: *MAT_NULL RO = 1 + *EOS_LINEAR_POLYNOMIAL C4 = C5 = gamma - 1 (p = (gamma - 1) rho e, sph-algorithms.md
section 10.1). Monaghan viscosity alpha = 1, beta = 2 (Q2 = 1, Q1 = 2) as for Sod; TSSFAC 0.3; h0 from
CSLH 1.2. Three settings a strong 2D shock needs (docs/verification.md section 4, measured):
- FORM 1 (renormalised gradients). The lattice is compressed 6-fold radially behind the shock but not
  tangentially, and DERIV 0 shrinks h as rho^(-1/2) in 2D, so h falls below the tangential spacing; the
  uncorrected FORM 0 gradients then left the shock 7 % short at N = 50 and 100 alike (0.660 / 0.665 for
  0.710), with the kinetic share of the energy at 13 % instead of 21 %.
- HMIN 1: h never below h0, so the shell keeps its tangential neighbours (peak density 6.94 with HMIN 0.2,
  6.23 with HMIN 1, exact 6, at N = 100).
- HMAX 5: the core thins about 20-fold; with HMAX 2 the hot particles stopped at h = 2 h0, lost their
  neighbours and kept their energy (with FORM 0 and HMAX 2 the shock ended 12-21 % short).

Standard library only; deterministic. Run `python3 decks/verification/make_sedov.py`.
"""

import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the decks
from lsdyna_cards import Deck, card, lattice, ruler  # noqa: E402

GAMMA = 1.4
RHO0 = 1.0
ENERGY = 1.0          # per unit length of the line source, the full plane
P_AMBIENT = 1.0e-6
BOX = 1.0             # the quarter [0, BOX]^2
END_TIME = 0.5
HOT_RADIUS = 3.0      # in spacings: the particles within it get the energy
RESOLUTIONS = (35, 50, 70, 100)  # quick: 35 and 70; full: 50 and 100


def hot(x, y, dx):
    return math.hypot(x, y) < HOT_RADIUS * dx


def sedov_deck(n):
    dx = BOX / n
    mass = RHO0 * dx * dx
    points = [(x, y) for y in lattice(n, dx) for x in lattice(n, dx)]
    n_hot = sum(1 for x, y in points if hot(x, y, dx))
    e_hot = ENERGY / 4.0 / (n_hot * mass)        # specific energy of the hot particles
    e_ambient = P_AMBIENT / ((GAMMA - 1) * RHO0)
    d = Deck(f"2D SPH Sedov blast wave, quarter plane {n} x {n}, gamma 1.4, t = {END_TIME}")
    d.termination(END_TIME)
    d.timestep(0.3, "TSSFAC 0.3: dt = 0.3 h / (c + |v|), room for the viscous term at shocks.")
    d.control_sph(1, "FORM 1: renormalised gradients (make_sedov.py).")
    d.bulk_viscosity(2.0, 1.0, "Classic Monaghan values for gas dynamics: alpha = 1, beta = 2.")
    d.section_sph(hmin=1.0, hmax=5.0, why="HMIN 1: h never below h0; HMAX 5: the core thins 20-fold (make_sedov.py).")
    for pid, name, e in ((1, "ambient gas", e_ambient), (2, f"hot core: E / 4 in {n_hot} particles", e_hot)):
        d.part(pid, name, 1, pid, pid)
        d.mat_null(pid, RHO0)
        d.add("*EOS_LINEAR_POLYNOMIAL",
              "$ Ideal gas: p = (C4 + C5 mu) E = (gamma - 1) rho e with C4 = C5 = gamma - 1;",
              f"$ E0 = RO e per reference volume, e = {e:.6g}.",
              ruler("eosid", "c0", "c1", "c2", "c3", "c4", "c5", "c6"),
              card(pid, 0.0, 0.0, 0.0, 0.0, GAMMA - 1, GAMMA - 1, 0.0),
              ruler("e0", "v0"),
              card(RHO0 * e, 1.0))
    d.symmetry_plane("Axis x = 0", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    d.symmetry_plane("Axis y = 0", (0.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    d.symmetry_plane(f"Box wall x = {BOX}", (BOX, 0.0, 0.0), (BOX - 1.0, 0.0, 0.0))
    d.symmetry_plane(f"Box wall y = {BOX}", (0.0, BOX, 0.0), (0.0, BOX - 1.0, 0.0))
    rows = [(x, y, 2 if hot(x, y, dx) else 1, mass) for x, y in points]
    d.particles(rows, [f"{n} x {n} particles on a square lattice of spacing 1/{n}, half a spacing",
                       f"from every wall; part 2 within {HOT_RADIUS:g} dx of the origin. Mass RO dx^2."])
    return d, n_hot


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for n in RESOLUTIONS:
        deck, n_hot = sedov_deck(n)
        path = deck.write(here, f"sedov_2d_{n}.k")
        print(f"wrote {path}: {n * n} particles, {n_hot} hot")


if __name__ == "__main__":
    main()
