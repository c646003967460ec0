#!/usr/bin/env python3
"""Write the dam-break decks of the numerical cross-check (verification.md section 3, "Against another
SPH code"): dam_break_marrone_40.k (H / 40, 3,200 particles; quick and full) and dam_break_marrone_80.k
(H / 80, 12,800; full), TrixiParticles' two resolutions. marrone_deck(20) writes a coarser one for a study.

The problem is the 2D dam break of Marrone et al. (2011, CMAME 200, 1526) as TrixiParticles.jl runs it
for its published reference results (trixi-framework/TrixiParticles.jl, MIT license,
validation/dam_break_2d/validation_reference_{wcsph,edac}_{40,80}.json; the set-up is
examples/fluid/dam_break_2d.jl with validation/dam_break_2d/setup_marrone_2011.jl, and the values below
are the ones the reference files record in their "meta" block): a water column H = 0.6 m high and
W = 2 H wide at rest against the back wall of a tank floor(5.366 H / dx) dx long, free-slip walls,
rho0 = 1000 kg/m^3, g = 9.81 m/s^2, c0 = 20 sqrt(g H) = 48.52 m/s, Monaghan alpha = 0.01, beta = 0.
No experimental gate: the front can be compared with the other code from t = 0.

How the deck maps their model (what differs is said; verification.md section 3 gives the effect):
- EOS: TrixiParticles' StateEquationCole with exponent 1, p = c0^2 (rho - rho0), negative pressures kept.
  *EOS_LINEAR_POLYNOMIAL with C1 = rho0 c0^2 is exactly that (p = C1 mu, mu = rho/rho0 - 1); *MAT_NULL
  PC = -1e20 keeps the tension (PC = 0 would clip it). Murnaghan gamma = 7 would not be their model.
- Kernel: theirs is Wendland C2 with h = 2 dx, support 2h = 4 dx; ours is the cubic B-spline (SPHKERN 0,
  the only one the solver runs), here with h0 = SPHINI = 2 dx: the same support, 4 dx.
- Walls: theirs are 4 layers of dummy particles (Adami pressure extrapolation, no wall viscosity); ours
  are *BOUNDARY_SPH_SYMMETRY_PLANE mirrors at the same places (x = 0, y = 0 and the far wall), both free
  slip. The column's lattice starts dx/2 from the walls, as theirs.
- Start: theirs is hydrostatic (density from the inverse EOS); ours starts uncompressed (rho0 g H /
  (rho0 c0^2) = 0.25 % of compression to settle). A deck gives one density per part: a hydrostatic start
  needs a part and an EOS (V0) per row, which was tried and moved the front by under 0.1 % to T = 2.
- Not in the deck: their density diffusion (Molteni & Colagrossi, delta = 0.1) and their 4th-order
  Runge-Kutta time stepping; ours has no density diffusion and integrates with leapfrog, TSSFAC 0.3.
End time t sqrt(g / H) = 2.5: the front reaches the far wall at 2.4-2.45, after which the largest x of the
fluid only shows where the wall is (TrixiParticles' series stay at 3.21-3.22 m from T = 2.5 to 7).

Standard library only; deterministic. Run `python3 decks/verification/make_dam_break_marrone.py`.
"""

import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the decks
from lsdyna_cards import Deck, card, lattice, ruler  # noqa: E402

RHO, G = 1000.0, 9.81
H = 0.6
W = 2.0 * H
C0 = 20.0 * math.sqrt(G * H)
C1 = RHO * C0 ** 2  # p = C1 mu = c0^2 (rho - rho0)
T_SCALE = math.sqrt(H / G)  # t = T * T_SCALE, T = t sqrt(g / H)
END_T = 2.5
VARIANTS = {"dam_break_marrone_40.k": 40, "dam_break_marrone_80.k": 80}  # particles across H


def tank_length(dx):
    """TrixiParticles' tank: floor(5.366 H / dx) dx (a whole number of spacings)."""
    return round(math.floor(5.366 * H / dx) * dx, 10)


def marrone_deck(per_height, end_T=END_T):
    dx = H / per_height
    nx, ny = 2 * per_height, per_height
    length = tank_length(dx)
    end_time = round(end_T * T_SCALE, 6)
    d = Deck(f"2D SPH dam break after Marrone et al. 2011: H = {H} m, W = 2H, {nx} x {ny} SPH")
    d.termination(end_time)
    d.timestep(0.3, "TSSFAC 0.3: dt = 0.3 h / (c + |v|).")
    d.control_sph()
    d.bulk_viscosity(0.0, 0.01, "As TrixiParticles' reference runs: alpha = 0.01, beta = 0.")
    d.section_sph(sphini=round(2.0 * dx, 10), hmin=0.2, hmax=2.0,
                  why="h0 = SPHINI = 2 dx: support 4 dx, as their Wendland C2 with h = 2 dx.")
    d.part(1, "water column", 1, 1, 1)
    d.add("*MAT_NULL",
          "$ PC = -1e20: negative pressures kept, as in TrixiParticles' WCSPH fluid.",
          ruler("mid", "ro", "pc", "mu", "terod", "cerod", "ym", "pr"),
          card(1, RHO, -1.0e20, 0.0, 0.0, 0.0, 0.0, 0.0))
    d.add("*EOS_LINEAR_POLYNOMIAL",
          "$ p = C1 mu = c0^2 (rho - rho0): their Cole EOS with exponent 1;",
          f"$ c0 = 20 sqrt(g H) = {C0:.4f} m/s.",
          ruler("eosid", "c0", "c1", "c2", "c3", "c4", "c5", "c6"),
          card(1, 0.0, C1, 0.0, 0.0, 0.0, 0.0, 0.0),
          ruler("e0", "v0"),
          card(0.0, 1.0))
    d.gravity(G, [(0.0, 1.0), (100.0, 1.0)], "Constant gravity from t = 0.")
    d.symmetry_plane("Tank floor y = 0", (0.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    d.symmetry_plane("Back wall x = 0", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    d.symmetry_plane(f"Far wall x = {length}", (length, 0.0, 0.0),
                     (round(length - 1.0, 10), 0.0, 0.0))
    mass = RHO * dx * dx
    points = [(x, y, 1, mass) for y in lattice(ny, dx) for x in lattice(nx, dx)]
    d.particles(points, [f"{nx} x {ny} particles on a square lattice of spacing H/{per_height} = {dx:g} m,",
                         f"half a spacing from the walls. End time t sqrt(g/H) = {end_T}: t = {end_time} s.",
                         "Mass RO dx^2."])
    return d


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for name, per_height in VARIANTS.items():
        path = marrone_deck(per_height).write(here, name)
        print(f"wrote {path}: {2 * per_height ** 2} particles, C1 = {C1:g} Pa, c0 = {C0:.3f} m/s")


if __name__ == "__main__":
    main()
