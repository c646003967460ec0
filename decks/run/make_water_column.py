#!/usr/bin/env python3
"""Writes water_column_2d.k: a small 2D plane-strain dam break for `sphdeck run` (runs in about a second).

A 0.2 m x 0.4 m water column (SI units) on a floor (y = 0) against a left wall (x = 0), with a right
wall at x = 0.8 m; all three walls are *BOUNDARY_SPH_SYMMETRY_PLANE. Particles sit at the centres of
a square lattice of spacing DX, so the first layer is DX/2 from each wall and its mirror image DX
away. Water: *MAT_NULL RO = 1000 with *EOS_MURNAGHAN, gamma = 7, K0 chosen so that
c0 = sqrt(gamma K0 / RO) = 10 sqrt(2 g H) (sph-algorithms.md §10.3). Gravity: *LOAD_BODY_Y, SF = 9.81.
Usage: python3 make_water_column.py [DX]  (default 0.01: 800 particles)
"""
import math
import sys

DX = float(sys.argv[1]) if len(sys.argv) > 1 else 0.01
WIDTH, HEIGHT, TANK = 0.2, 0.4, 0.8
RHO, GAMMA, G = 1000.0, 7.0, 9.81
C0 = 10.0 * math.sqrt(2.0 * G * HEIGHT)
K0 = RHO * C0 * C0 / GAMMA
NX, NY = round(WIDTH / DX), round(HEIGHT / DX)


def f10(v):
    return f"{v:10.4g}" if isinstance(v, float) else f"{v:10d}"


lines = [
    "*KEYWORD",
    "*TITLE",
    f"2D water column {WIDTH} m x {HEIGHT} m, {NX * NY} particles, spacing {DX} m (make_water_column.py)",
    "*CONTROL_TERMINATION",
    "$#  endtim",
    f10(0.1),
    "*CONTROL_TIMESTEP",
    "$#  dtinit    tssfac",
    f10(0.0) + f10(0.3),
    "*CONTROL_SPH",
    "$#    ncbs     boxid        dt      idim    memory      form     start      maxv",
    f10(1) + f10(0) + f10(1.0e20) + f10(2) + f10(150) + f10(0) + f10(0.0) + f10(1.0e15),
    "*CONTROL_BULK_VISCOSITY",
    "$ Q1 = Q2 = 1.0 as the *CONTROL_SPH manual advises with the Monaghan viscosity",
    f10(1.0) + f10(1.0),
    "*SECTION_SPH",
    "$#   secid      cslh      hmin      hmax    sphini",
    f10(1) + f10(1.2) + f10(0.2) + f10(2.0) + f10(0.0),
    "*PART",
    "water",
    "$#     pid     secid       mid     eosid",
    f10(1) + f10(1) + f10(1) + f10(1),
    "*MAT_NULL",
    "$#     mid        ro        pc",
    f10(1) + f10(RHO) + f10(0.0),
    "*EOS_MURNAGHAN",
    "$#   eosid     gamma        k0        v0",
    f10(1) + f10(GAMMA) + f"{K0:10.4g}" + f10(1.0),
    "*LOAD_BODY_Y",
    "$ the base accelerates along +Y: gravity pulls the water along -Y",
    f10(1) + f10(G),
    "*DEFINE_CURVE",
    f10(1),
    f"{0.0:20.4f}{1.0:20.4f}",
    f"{100.0:20.4f}{1.0:20.4f}",
]
for tail, head in (((0, 0, 0), (0, 1, 0)), ((0, 0, 0), (1, 0, 0)), ((TANK, 0, 0), (TANK - 1, 0, 0))):
    lines += ["*BOUNDARY_SPH_SYMMETRY_PLANE", "".join(f10(float(v)) for v in tail + head)]
lines.append("*NODE")
nodes, elements = [], []
mass = RHO * DX * DX  # plane strain: mass per unit thickness
for j in range(NY):
    for i in range(NX):
        nid = j * NX + i + 1
        nodes.append(f"{nid:8d}{(i + 0.5) * DX:16.8f}{(j + 0.5) * DX:16.8f}{0.0:16.8f}")
        elements.append(f"{nid:8d}{1:8d}{mass:16.8e}")
lines += nodes + ["*ELEMENT_SPH"] + elements + ["*END"]
sys.stdout.write("\n".join(lines) + "\n")
