#!/usr/bin/env python3
"""Write dam_break_2d.k, a 2D SPH dam break as an LS-DYNA keyword deck (SI units: m, kg, s).

A water column 0.6 m wide and 1.2 m high stands in the left corner of a 3.22 m wide tank and collapses
under gravity. The tank walls are three *BOUNDARY_SPH_SYMMETRY_PLANE planes; the particles sit on a
square lattice of spacing DX whose first row and column are DX/2 away from the walls, so every particle
is DX away from its own mirror image.

Every card is written in fixed format: 8 fields of 10 columns, *NODE as I8,3E16,2I8 and *ELEMENT_SPH
as I8,I8,E16 (NEND left blank), each card preceded by an LS-PrePost style `$#` ruler.

Standard library only. Run `python3 decks/demo/make_dam_break.py`; the deck is written next to this
script. The output is deterministic: running the script again gives the same file byte for byte.
"""

import math
import os

# --- case parameters ---------------------------------------------------------------------------
RHO = 1000.0           # water density, kg/m^3
GAMMA = 7.0            # Murnaghan (Tait) exponent for water
G = 9.81               # gravity, m/s^2
COLUMN_W = 0.6         # water column width, m
COLUMN_H = 1.2         # water column height, m
TANK_L = 3.22          # distance between the left and the right wall, m
DX = 0.015             # particle spacing, m
NX = round(COLUMN_W / DX)   # 40 particles across
NY = round(COLUMN_H / DX)   # 80 particles high
END_TIME = 1.0         # s

# Largest speed of the collapse: free fall from the column height.
V_MAX = math.sqrt(2.0 * G * COLUMN_H)
# Weakly compressible SPH: c0 = sqrt(GAMMA*K0/RHO) >= 10 * V_MAX keeps density variations near 1 %.
# K0 = RHO * (10 V_MAX)^2 / GAMMA, rounded UP to two significant digits so the factor stays >= 10.
_k0_exact = RHO * (10.0 * V_MAX) ** 2 / GAMMA
_k0_step = 10.0 ** (math.floor(math.log10(_k0_exact)) - 1)
K0 = math.ceil(_k0_exact / _k0_step) * _k0_step
C0 = math.sqrt(GAMMA * K0 / RHO)
# 2D plane strain (IDIM = 2): mass per unit thickness of one lattice cell.
MASS = RHO * DX * DX


# --- fixed-format helpers ----------------------------------------------------------------------
def real(v, width):
    """Shortest text for v that reads back as v, with a '.' and at least one blank before it in
    a `width`-column field (so no two fields ever touch)."""
    v = round(float(v), 12)
    if v == 0.0:
        return "0.0"
    room = width - 1
    if 1e-4 <= abs(v) < 1e7:
        text = repr(v)
        if len(text) <= room:
            return text
    for digits in range(0, room):          # scientific: 1.0e+20, 3.4e+05, 1.25e-06 ...
        mant, exp = f"{v:.{digits}e}".split("e")
        if "." not in mant:
            mant += ".0"
        text = f"{mant}e{int(exp):+03d}"
        if float(text) == v and len(text) <= room:
            return text
    raise ValueError(f"{v} does not fit in {width} columns")


def field(value, width):
    if isinstance(value, str):
        text = value
    elif isinstance(value, int):
        text = str(value)
    else:
        text = real(value, width)
    if len(text) > width:
        raise ValueError(f"{text!r} overflows a {width}-column field")
    return text.rjust(width)


def card(*values, width=10):
    return "".join(field(v, width) for v in values)


def ruler(*names, widths=None):
    """LS-PrePost style ruler: names right-aligned in their fields, `$#` over the first two columns."""
    widths = widths or [10] * len(names)
    text = "".join(n.rjust(w) for n, w in zip(names, widths))
    return "$#" + text[2:]


# --- the deck ----------------------------------------------------------------------------------
def deck_lines():
    out = []
    add = out.append

    add("*KEYWORD")
    add("*TITLE")
    add(ruler("title", widths=[80]))
    add("2D SPH dam break: 0.6 m x 1.2 m water column, 3.22 m tank, SI units (m, kg, s)")

    add("*CONTROL_TERMINATION")
    add(ruler("endtim", "endcyc", "dtmin", "endeng", "endmas", "nosol"))
    add(card(END_TIME, 0, 0.0, 0.0, 1.0e8, 0))

    add("*CONTROL_TIMESTEP")
    add(ruler("dtinit", "tssfac", "isdo", "tslimt", "dt2ms", "lctm", "erode", "ms1st"))
    add(card(0.0, 0.9, 0, 0.0, 0.0, 0, 0, 0))

    add("*CONTROL_SPH")
    add("$ IDIM 2: 2D plane strain. FORM 15: enhanced fluid form, recommended for fluids.")
    add(ruler("ncbs", "boxid", "dt", "idim", "memory", "form", "start", "maxv"))
    add(card(1, 0, 1.0e20, 2, 150, 15, 0.0, 1.0e15))
    add(ruler("cont", "deriv", "ini", "ishow", "ierod", "icont", "iavis", "isymp"))
    add(card(0, 0, 0, 0, 0, 0, 0, 100))
    add(ruler("ithk", "istab", "ql"))
    add(card(0, 0, 0.01))

    add("*CONTROL_BULK_VISCOSITY")
    add("$ Q1 = Q2 = 1.0, as the *CONTROL_SPH manual advises for Monaghan viscosity.")
    add(ruler("q1", "q2", "type"))
    add(card(1.0, 1.0, 1))

    add("*SECTION_SPH")
    add(ruler("secid", "cslh", "hmin", "hmax", "sphini", "death", "start"))
    add(card(1, 1.2, 0.2, 2.0, 0.0, 1.0e20, 0.0))

    add("*PART")
    add(ruler("title", widths=[70]))
    add("water column")
    add(ruler("pid", "secid", "mid", "eosid", "hgid", "grav", "adpopt", "tmid"))
    add(card(1, 1, 1, 1, 0, 0, 0, 0))

    add("*MAT_NULL")
    add(ruler("mid", "ro", "pc", "mu", "terod", "cerod", "ym", "pr"))
    add(card(1, RHO, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0))

    add("*EOS_MURNAGHAN")
    add(f"$ Largest expected speed, free fall from the top: sqrt(2 g H) = {V_MAX:.3f} m/s.")
    add("$ K0 = RO*(10*sqrt(2 g H))^2/GAMMA, rounded up to two digits, so that")
    add(f"$ c0 = sqrt(GAMMA*K0/RO) = {C0:.2f} m/s = {C0 / V_MAX:.2f} x sqrt(2 g H).")
    add(ruler("eosid", "gamma", "k0", "v0"))
    add(card(1, GAMMA, K0, 1.0))

    add("*LOAD_BODY_Y")
    add("$ *LOAD_BODY gives the acceleration of the base; the load on the material acts")
    add(f"$ the opposite way, so SF = +{G} along Y pulls the water towards -Y (down).")
    add(ruler("lcid", "sf", "lciddr", "xc", "yc", "zc", "cid"))
    add(card(1, G, 0, 0.0, 0.0, 0.0, 0))

    add("*DEFINE_CURVE")
    add("$ Constant gravity: scale 1.0 from t = 0 to t = 100 s, well past ENDTIM.")
    add(ruler("lcid", "sidr", "sfa", "sfo", "offa", "offo", "dattyp"))
    add(card(1, 0, 1.0, 1.0, 0.0, 0.0, 0))
    add(ruler("a1", "o1", widths=[20, 20]))
    add(card(0.0, 1.0, width=20))
    add(card(100.0, 1.0, width=20))

    walls = [
        ("floor y = 0, normal +y", (0.0, 0.0, 0.0), (0.0, 1.0, 0.0)),
        ("left wall x = 0, normal +x", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0)),
        (f"right wall x = {TANK_L}, normal -x", (TANK_L, 0.0, 0.0), (TANK_L - 1.0, 0.0, 0.0)),
    ]
    for name, tail, head in walls:
        add("*BOUNDARY_SPH_SYMMETRY_PLANE")
        add(f"$ Tank {name}. Tail on the plane, head 1 m along the")
        add("$ normal, which points into the fluid.")
        add(ruler("vtx", "vty", "vtz", "vhx", "vhy", "vhz"))
        add(card(*tail, *head))

    # Lattice points at (i + 1/2) DX, (j + 1/2) DX: nothing on or behind a wall.
    def coord(k):
        return round((k + 0.5) * DX, 10)

    add("*NODE")
    add(f"$ {NX} x {NY} = {NX * NY} particles on a square lattice of spacing {DX} m;")
    add(f"$ the first row and column lie {DX / 2} m (half a spacing) from the walls.")
    add(ruler("nid", "x", "y", "z", "tc", "rc", widths=[8, 16, 16, 16, 8, 8]))
    nid = 0
    for j in range(NY):
        for i in range(NX):
            nid += 1
            add(field(nid, 8) + field(coord(i), 16) + field(coord(j), 16) + field(0.0, 16)
                + field(0, 8) + field(0, 8))

    add("*ELEMENT_SPH")
    add("$ 2D (IDIM 2): MASS is per unit thickness,")
    add(f"$ RO*DX^2 = {real(RHO, 16)}*{DX}^2 = {real(MASS, 16)} kg/m.")
    add(ruler("nid", "pid", "mass", widths=[8, 8, 16]))
    for n in range(1, NX * NY + 1):
        add(field(n, 8) + field(1, 8) + field(MASS, 16))

    add("*END")
    return out


def main():
    lines = deck_lines()
    for number, line in enumerate(lines, 1):
        if len(line) > 80:
            raise SystemExit(f"line {number} is {len(line)} columns long: {line!r}")
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "dam_break_2d.k")
    with open(path, "w", encoding="ascii", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {path}: {NX * NY} particles, K0 = {K0:g} Pa, c0 = {C0:.2f} m/s "
          f"({C0 / V_MAX:.2f} x sqrt(2 g H) = {V_MAX:.3f} m/s), mass {MASS:g} kg/m")


if __name__ == "__main__":
    main()
