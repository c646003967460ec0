#!/usr/bin/env python3
"""Write the Sod shock-tube decks sod_2d_<N>.k (N = 200, 400, 800 particles along the tube).

verification.md section 1: ideal gas, gamma = 1.4, left state (rho, u, p) = (1, 0, 1), right state
(0.125, 0, 0.1), diaphragm at x0 = 0.5 in x in [0, 1], compared at t = 0.2. LS-DYNA has no 1D SPH, so
the tube is a 2D strip (IDIM 2, plane strain) NY = 6 particle rows high, walled by four
*BOUNDARY_SPH_SYMMETRY_PLANE planes: y = 0 and y = 6 dx make the strip an infinite slab in y (mirror
ghosts), x = 0 and x = 1 close the ends (no wave reaches them before t = 0.2: the rarefaction head is at
0.263 and the shock at 0.850).

Equal spacing with a mass ratio of 8, not equal masses with a spacing ratio of 8: a square lattice has
the same rows on both sides of the diaphragm, so the y walls and the strip stay exact; both parts get the
same h0 (the kernel support does not jump at the diaphragm); the low-density side, where the shock and
the contact travel, is resolved as finely as the left; and the solver integrates density by continuity,
so the initial jump is carried by each part's RO with no smearing from a density sum. The price is the
known pressure blip at the contact where masses differ, which the L1 norms include.

Smoothing length h0 = SPHINI = 3 dx (not CSLH 1.2 x dx). The flow is one-dimensional but the particles
sit on a 2D lattice: the gas expanding through the rarefaction stretches the lattice along x only (by
rho_L / rho*_L = 2.35 at the tail), while DERIV 0 in 2D grows h only as rho^(-1/2) (sph-algorithms.md
section 3.1), so h / dx_x falls as sqrt(rho / rho_L). The kernel sums over a lattice (the density sum, the
gradient matrix B of section 5) are exact only for h large enough against the spacing, and their error
depends on h / dx alone, not on the resolution (verification.md section 9.2: "SPH with fixed h/dx reaches a
plateau set by kernel consistency"). With CSLH 1.2, h / dx_x falls to 0.78 in the expanded gas: L1(rho)
stalled at 0.031 / 0.029 (N = 200 / 400, observed order 0.1) and the fan's slope was wrong at every
resolution; with h0 = 2 dx (minimum 1.31) the fan's slope was still 12 % low at N = 200, 400 and 800 alike;
with h0 = 3 dx (minimum 3 x sqrt(0.426) = 1.96) the fan converges and L1(rho) falls at order 0.6-0.7
(docs/verification.md). SPHINI rather than CSLH 3, whose range check (1.05-1.3) is meant for ordinary decks.

Gas: two parts, each *MAT_NULL (RO = initial density) + *EOS_LINEAR_POLYNOMIAL with C4 = C5 = gamma - 1
= 0.4 and E0 = p / (gamma - 1) per reference volume: 2.5 on the left, 0.25 on the right, so the specific
energies are 2.5 and 2.0 (sph-algorithms.md section 10.1). Monaghan viscosity with the classic
alpha = 1, beta = 2 (Q2 = 1, Q1 = 2).

Standard library only; deterministic. Run `python3 decks/verification/make_sod.py`.
"""

import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the decks
from lsdyna_cards import Deck, card, lattice, ruler  # noqa: E402

GAMMA = 1.4
LEFT = (1.0, 0.0, 1.0)      # rho, u, p
RIGHT = (0.125, 0.0, 0.1)
X0, LENGTH, END_TIME = 0.5, 1.0, 0.2
ROWS = 6
H_OVER_DX = 3.0  # h0 / dx (SPHINI); see the docstring
RESOLUTIONS = (200, 400, 800)


def sod_deck(nx):
    dx = LENGTH / nx
    width = ROWS * dx
    d = Deck(f"2D SPH Sod shock tube, {nx} x {ROWS} particles, gamma 1.4, t = 0.2")
    d.termination(END_TIME)
    d.timestep(0.3, "TSSFAC 0.3: dt = 0.3 h / (c + |v|), room for the viscous term at shocks.")
    d.control_sph()
    d.bulk_viscosity(2.0, 1.0, "Classic Monaghan values for gas dynamics: alpha = 1, beta = 2.")
    d.section_sph(sphini=round(H_OVER_DX * dx, 12),
                  why=f"SPHINI = {H_OVER_DX:g} dx: h keeps ~2 spacings along x as the gas expands (make_sod.py).")
    for pid, name, state in ((1, "left gas (high pressure)", LEFT), (2, "right gas (low pressure)", RIGHT)):
        rho, _, p = state
        d.part(pid, name, 1, pid, pid)
        d.mat_null(pid, rho)
        d.add("*EOS_LINEAR_POLYNOMIAL",
              "$ Ideal gas: p = (C4 + C5 mu) E = (gamma - 1) rho e with C4 = C5 = gamma - 1;",
              f"$ E0 = p / (gamma - 1) = {p} / {GAMMA - 1:.1f} per reference volume (RO = {rho}).",
              ruler("eosid", "c0", "c1", "c2", "c3", "c4", "c5", "c6"),
              card(pid, 0.0, 0.0, 0.0, 0.0, GAMMA - 1, GAMMA - 1, 0.0),
              ruler("e0", "v0"),
              card(p / (GAMMA - 1), 1.0))
    d.symmetry_plane("Tube end x = 0", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    d.symmetry_plane(f"Tube end x = {LENGTH}", (LENGTH, 0.0, 0.0), (LENGTH - 1.0, 0.0, 0.0))
    d.symmetry_plane("Strip side y = 0", (0.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    d.symmetry_plane(f"Strip side y = {round(width, 10)}", (0.0, width, 0.0), (0.0, width - 1.0, 0.0))
    points = []
    for y in lattice(ROWS, dx):
        for x in lattice(nx, dx):
            left = x < X0
            rho = LEFT[0] if left else RIGHT[0]
            points.append((x, y, 1 if left else 2, rho * dx * dx))
    d.particles(points, [f"{nx} x {ROWS} particles on a square lattice of spacing {dx:g}, half a spacing",
                         f"from every wall; part 1 for x < {X0}, part 2 beyond. Mass RO dx^2."])
    return d


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for nx in RESOLUTIONS:
        path = sod_deck(nx).write(here, f"sod_2d_{nx}.k")
        print(f"wrote {path}: {nx * ROWS} particles")


if __name__ == "__main__":
    main()
