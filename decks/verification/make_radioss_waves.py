#!/usr/bin/env python3
"""Writes radioss_waves_0000.rad and radioss_waves_0001.rad: the set-up of OpenRadioss's QA case
qa-tests/miniqa/SPH/WavesCompression (public OpenRadioss/OpenRadioss repository), written here from
its figures (the QA deck itself is licensed CC BY-NC 4.0 and is not copied): a copper-like cube of
1296 particles (units kg, mm, ms) on a lattice of spacing d = 1.283001 / 4 in x, y and z, particle
(ix, iy, iz) at (-4d + ix d, -4d + iy d, iz d) for ix, iy in 0..8, iz in 0..31 with ix + iy + iz
even; /MAT/HYDPLA (rho 8.93, E 0), /EOS/POLYNOMIAL (C1 1.3), /PROP/TYPE34 (mp 0.58936189, qa 2,
qb 1, Order -1), /INIVEL/TRA vz -0.03815 on every particle above z = 0, /SPHBCS TIED at z = 0 and
SLIDE at x = +-4d and y = +-4d (each with the particles on its plane as kinematic group); engine
deck: /RUN 30.1, /DT/NODA/CST 0.67. The engine's listing of that case is the reference of
`sphdeck verify radioss-waves` (verify/radioss_waves_reference.hpp).

Usage: python3 make_radioss_waves.py [--quick]   (--quick: the engine deck ends at 5.0)
Standard library only, deterministic.
"""
import sys

D = 1.283001 / 4
L = 4 * D


def f20(v):
    return f"{v:20.10g}"


def main():
    quick = "--quick" in sys.argv
    name = "radioss_waves_quick" if quick else "radioss_waves"
    nodes = []
    for ix in range(9):
        for iy in range(9):
            for iz in range(32):
                if (ix + iy + iz) % 2 == 0:
                    nodes.append((len(nodes) + 1, -L + ix * D, -L + iy * D, iz * D))
    eps = 1e-9

    def members(test):
        return [n[0] for n in nodes if test(n)]

    groups = {
        1: ("moving", members(lambda n: n[3] > eps)),
        2: ("z = 0", members(lambda n: abs(n[3]) < eps)),
        5: ("x = +L", members(lambda n: abs(n[1] - L) < eps)),
        6: ("x = -L", members(lambda n: abs(n[1] + L) < eps)),
        7: ("y = +L", members(lambda n: abs(n[2] - L) < eps)),
        8: ("y = -L", members(lambda n: abs(n[2] + L) < eps)),
    }
    out = ["#RADIOSS STARTER",
           "# Written by make_radioss_waves.py from the figures of OpenRadioss's QA case",
           "# qa-tests/miniqa/SPH/WavesCompression (see the script's docstring).",
           "/BEGIN", name, "      2019         0",
           "                  kg                  mm                  ms",
           "                  kg                  mm                  ms",
           "/TITLE", "SPH cube against tied and sliding symmetry planes",
           "/MAT/HYDPLA/1", "copper-like", f20(8.93), f20(0) + f20(0), "".join(f20(0) for _ in range(5)), f20(0),
           "/EOS/POLYNOMIAL/1", "polynomial", f20(0) + f20(1.29999995) + f20(0) + f20(0),
           "".join(f20(0) for _ in range(5)),
           "/PART/1", "cube", "         1         1         0",
           "/PROP/TYPE34/1", "sph", f20(0.58936189) + f20(2) + f20(1) + f20(0) + "         0         0",
           "        -1" + f20(0) + f20(0)]
    frames = [(1, (0, 0, 0), (0, 1, 0)), (2, (L, 0, 0), (0, -1, 0)), (3, (-L, 0, 0), (0, 1, 0)),
              (4, (0, L, 0), (0, -1, 0)), (5, (0, -L, 0), (0, 1, 0))]
    for fid, o, y1 in frames:
        out += [f"/FRAME/FIX/{fid}", "frame", "".join(f20(v) for v in o), "".join(f20(v) for v in y1),
                "".join(f20(v) for v in (0, 0, 1))]
    out.append("/NODE")
    out += [f"{n[0]:10d}{f20(n[1])}{f20(n[2])}{f20(n[3])}" for n in nodes]
    for gid, (title, ids) in groups.items():
        out += [f"/GRNOD/NODE/{gid}", title]
        for k in range(0, len(ids), 10):
            out.append("".join(f"{i:10d}" for i in ids[k:k + 10]))
    out += ["/SPHCEL/1"] + [f"{n[0]:10d}" for n in nodes]
    out += ["/INIVEL/TRA/1", "moving", f20(0) + f20(0) + f20(-0.0381500006) + "         1         0"]
    out += ["/SPHGLO", f20(0.1)]
    for sid, kind, axis, frame, group, ilev in [(1, "TIED", "Z", 1, 2, 1), (2, "SLIDE", "X", 2, 5, 0),
                                                (3, "SLIDE", "X", 3, 6, 0), (4, "SLIDE", "Y", 4, 7, 0),
                                                (5, "SLIDE", "Y", 5, 8, 0)]:
        out += [f"/SPHBCS/{kind}/{sid}", "symmetry", f"{axis:>10}{frame:10d}{group:10d}{ilev:20d}"]
    out.append("/END")
    with open(f"{name}_0000.rad", "w") as f:
        f.write("\n".join(out) + "\n")
    engine = ["/RUN/" + name + "/1", f20(5.0 if quick else 30.1), "/DT/NODA/CST/0", "0.67 0", "/TFILE/4", "0.01",
              "/ANIM/DT", "0 3", "/END"]
    with open(f"{name}_0001.rad", "w") as f:
        f.write("\n".join(engine) + "\n")


if __name__ == "__main__":
    main()
