"""Fixed-format LS-DYNA card helpers shared by the verification deck generators (standard library only).

The same conventions as decks/demo/make_dam_break.py: 8 fields of 10 columns, *NODE as I8,3E16,2I8,
*ELEMENT_SPH as I8,I8,E16, every card preceded by an LS-PrePost style `$#` ruler, no line over 80
columns, and numbers written as the shortest text that reads back as the value.
"""

import os


def real(v, width):
    """Shortest text for v that reads back as v, with a '.' and at least one blank before it."""
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
    # Values like 280285.7142857 do not fit exactly: keep as many digits as the field holds.
    for digits in range(room, 0, -1):
        text = f"{v:.{digits}g}"
        if "." not in text and "e" not in text:
            text += ".0"
        if len(text) <= room:
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


class Deck:
    """Collects the lines of one deck; the keyword helpers write the cards every verification deck shares."""

    def __init__(self, title):
        self.lines = ["*KEYWORD", "*TITLE", ruler("title", widths=[80]), title]

    def add(self, *lines):
        self.lines.extend(lines)

    def termination(self, end_time):
        self.add("*CONTROL_TERMINATION",
                 ruler("endtim", "endcyc", "dtmin", "endeng", "endmas", "nosol"),
                 card(end_time, 0, 0.0, 0.0, 1.0e8, 0))

    def timestep(self, tssfac, why):
        self.add("*CONTROL_TIMESTEP", f"$ {why}",
                 ruler("dtinit", "tssfac", "isdo", "tslimt", "dt2ms", "lctm", "erode", "ms1st"),
                 card(0.0, tssfac, 0, 0.0, 0.0, 0, 0, 0))

    def control_sph(self, form=0, why="FORM 0: the default (standard) formulation."):
        self.add("*CONTROL_SPH",
                 f"$ IDIM 2: 2D plane strain. {why}",
                 ruler("ncbs", "boxid", "dt", "idim", "memory", "form", "start", "maxv"),
                 card(1, 0, 1.0e20, 2, 150, form, 0.0, 1.0e15),
                 ruler("cont", "deriv", "ini", "ishow", "ierod", "icont", "iavis", "isymp"),
                 card(0, 0, 0, 0, 0, 0, 0, 100),
                 ruler("ithk", "istab", "ql"),
                 card(0, 0, 0.01))

    def bulk_viscosity(self, q1, q2, why):
        self.add("*CONTROL_BULK_VISCOSITY",
                 "$ Monaghan viscosity (IAVIS 0): Q1 scales the quadratic term (beta),",
                 "$ Q2 the linear one (alpha); sph-algorithms.md section 6.1.",
                 f"$ {why}",
                 ruler("q1", "q2", "type"),
                 card(q1, q2, 1))

    def section_sph(self, secid=1, cslh=1.2, sphini=None, why=None, hmin=0.2, hmax=2.0):
        """CSLH times the largest nearest-neighbour distance gives h0, unless SPHINI sets h0 itself
        (CSLH is then left blank: LS-DYNA ignores it). HMIN and HMAX default to LS-DYNA's 0.2 and 2.0."""
        comment = [f"$ {why}"] if why else []
        self.add("*SECTION_SPH", *comment,
                 ruler("secid", "cslh", "hmin", "hmax", "sphini", "death", "start"),
                 card(secid, "" if sphini else cslh, hmin, hmax, sphini or 0.0, 1.0e20, 0.0))

    def part(self, pid, title, secid, mid, eosid):
        self.add("*PART", ruler("title", widths=[70]), title,
                 ruler("pid", "secid", "mid", "eosid", "hgid", "grav", "adpopt", "tmid"),
                 card(pid, secid, mid, eosid, 0, 0, 0, 0))

    def mat_null(self, mid, rho):
        self.add("*MAT_NULL",
                 ruler("mid", "ro", "pc", "mu", "terod", "cerod", "ym", "pr"),
                 card(mid, rho, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0))

    def symmetry_plane(self, name, tail, head):
        self.add("*BOUNDARY_SPH_SYMMETRY_PLANE",
                 f"$ {name}; the normal (tail -> head) points into the particles.",
                 ruler("vtx", "vty", "vtz", "vhx", "vhy", "vhz"),
                 card(*tail, *head))

    def gravity(self, g, curve_points, why):
        self.add("*LOAD_BODY_Y",
                 "$ *LOAD_BODY gives the acceleration of the base; the load on the material acts",
                 f"$ the opposite way, so SF = +{g} along Y pulls the water towards -Y (down).",
                 ruler("lcid", "sf", "lciddr", "xc", "yc", "zc", "cid"),
                 card(1, g, 0, 0.0, 0.0, 0.0, 0),
                 "*DEFINE_CURVE", f"$ {why}",
                 ruler("lcid", "sidr", "sfa", "sfo", "offa", "offo", "dattyp"),
                 card(1, 0, 1.0, 1.0, 0.0, 0.0, 0),
                 ruler("a1", "o1", widths=[20, 20]))
        for t, value in curve_points:
            self.add(card(t, value, width=20))

    def particles(self, points, note):
        """points: (x, y, part id, mass per unit thickness) in node order."""
        self.add("*NODE", *[f"$ {n}" for n in note],
                 ruler("nid", "x", "y", "z", "tc", "rc", widths=[8, 16, 16, 16, 8, 8]))
        for nid, (x, y, _, _) in enumerate(points, 1):
            self.add(field(nid, 8) + field(x, 16) + field(y, 16) + field(0.0, 16) + field(0, 8) + field(0, 8))
        self.add("*ELEMENT_SPH", "$ 2D (IDIM 2): MASS is per unit thickness.",
                 ruler("nid", "pid", "mass", widths=[8, 8, 16]))
        for nid, (_, _, pid, mass) in enumerate(points, 1):
            self.add(field(nid, 8) + field(pid, 8) + field(mass, 16))

    def write(self, directory, name):
        self.lines.append("*END")
        for number, line in enumerate(self.lines, 1):
            if len(line) > 80:
                raise SystemExit(f"{name}: line {number} is {len(line)} columns long: {line!r}")
        path = os.path.join(directory, name)
        with open(path, "w", encoding="ascii", newline="\n") as f:
            f.write("\n".join(self.lines) + "\n")
        return path


def lattice(count, spacing, origin=0.0):
    """Lattice coordinates (k + 1/2) * spacing from `origin`: nothing on a wall, every particle a
    spacing away from its mirror image."""
    return [round(origin + (k + 0.5) * spacing, 10) for k in range(count)]
