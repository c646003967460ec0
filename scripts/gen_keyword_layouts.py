#!/usr/bin/env python3
"""Turn the LS-DYNA keyword layouts extracted from pydyna into sphdeck's generated C++ table.

    python3 scripts/gen_keyword_layouts.py /work/shared/reference/lsdyna-keyword-layouts.json \
        > grammar/keywords/generated/keyword_layouts.cpp

The input is `lsdyna-keyword-layouts.json` (see its `.md`: pydyna's generated classes, MIT). The
output is committed, so the build needs nothing from outside. One string per keyword, decoded at
run time only for the keywords a deck uses (grammar/keywords/generated_schema.cpp):

    line 1:  options, blank-separated ("TITLE ID MPP A B ...")
    then one line per card:  REPEAT|OPTION|CONDITION|FIELD,FIELD,...
      REPEAT    1 once, r repeated until the next keyword, gN first of a group of N cards that
                repeats until the next keyword, x layout unknown from here on (not checked)
      OPTION    - base card, * always read when present (*CONTACT cards A-G), else an option name
      CONDITION - none, else tests FIELD OP V1;V2... (OP one of == != < <= > >= in) joined by
                " and " (binds first) and " or ": "DOF in -11;-10;-9;9;10;11 or VAD == 4"
      FIELD     NAME:TYPE:OFFSET:WIDTH[:DEFAULT[:LINK]], TYPE one of I F A U (unused), LINK what
                the id names (PART, SET_NODE, DEFINE_CURVE...: the JSON's links)

Conservative by design (no false alarms on real decks): what the JSON cannot say for sure becomes
an `x` card, after which the block is not checked.
"""
import json
import re
import sys

NAME_OK = re.compile(r"^[A-Za-z0-9_/\-]+$")
CONTACT_OPTIONAL = set("ABCDEFG")  # read by LS-DYNA whenever the lines are there


def field_name(f):
    d = f.get("display_name")
    n = d if d and NAME_OK.match(d) else f["name"]
    n = n.lstrip("_") or n
    return n.upper()


LINKS = {}  # pydyna field name -> what its id names, for the keyword being written


# Fields pydyna types wrongly, by pydyna name: AMMGNM of *ALE_STRUCTURED_MULTI-MATERIAL_GROUP is the
# group's name (A10 in the manual; "vacuum", "air" in pydyna's own test deck standard/sale.k).
TYPE_FIXES = {"ammgnm": "str"}


def field_text(f, offset=None, width=None, name=None, ftype=None):
    t = ftype or TYPE_FIXES.get(f.get("name", ""), f["type"])
    code = {"int": "I", "float": "F", "str": "A", "bool": "A"}.get(t, "A")
    name = name or field_name(f)
    if name.startswith("UNUSED"):
        code = "U"
    off = f["offset"] if offset is None else offset
    w = f["width"] if width is None else width
    s = f"{name}:{code}:{off}:{w}"
    d = f.get("default")
    default = ""
    if code in "IF" and isinstance(d, (int, float)) and not isinstance(d, bool) and d != 0:
        default = repr(d)
    link = LINKS.get(f.get("name", ""), "") if code != "U" else ""
    if link:
        s += f":{default}:{link}"
    elif default:
        s += f":{default}"
    return s


def padded(fields):
    """Field texts, with unused 10-column slots up to column 80 so that values past pydyna's last
    field (newer versions add fields) are not reported as beyond the card."""
    out = [field_text(f) for f in fields]
    if fields and fields[-1]["type"] == "str":
        return out  # a trailing title or heading: its length is the card's
    end = max((f["offset"] + f["width"] for f in fields), default=0)
    while end < 80:
        w = min(10, 80 - end)
        out.append(f"UNUSED:U:{end}:{w}")
        end += w
    return out


SIMPLE = re.compile(r"^(abs\()?self\.(\w+)\)?\s*(==|!=|<=|>=|<|>|in)\s*(.+)$")
VALUE = r"(?:\[[^\]]*\]|-?\d+(?:\.\d*)?|None)"
TOKEN = re.compile(r"\s*(\(|\)|and\b|or\b|abs\(self\.\w+\)\s*(?:==|!=|<=|>=|<|>|in)\s*" + VALUE +
                   r"|self\.\w+(?:\s+is not None|\s*(?:==|!=|<=|>=|<|>|in)\s*" + VALUE + r")?)")


def number_list(text):
    text = text.strip()
    if text.startswith("[") and text.endswith("]"):
        text = text[1:-1]
    vals = []
    for v in text.split(","):
        v = v.strip()
        if not re.match(r"^-?\d+(\.\d*)?$", v):
            return None
        vals.append(float(v) if "." in v else int(v))
    return vals


def tokens(text):
    out, pos = [], 0
    while pos < len(text):
        m = TOKEN.match(text, pos)
        if not m or m.end() == pos:
            return None
        out.append(m.group(1))
        pos = m.end()
        while pos < len(text) and text[pos].isspace():
            pos += 1
    return out


def dnf(toks):
    """The condition as a list of clauses (or) of atoms (and); None when it does not parse."""
    pos = 0

    def expr():
        nonlocal pos
        clauses = term()
        while clauses is not None and pos < len(toks) and toks[pos] == "or":
            pos += 1
            more = term()
            clauses = None if more is None else clauses + more
        return clauses

    def term():
        nonlocal pos
        clauses = factor()
        while clauses is not None and pos < len(toks) and toks[pos] == "and":
            pos += 1
            more = factor()
            clauses = None if more is None else [a + b for a in clauses for b in more]
        return clauses

    def factor():
        nonlocal pos
        if pos >= len(toks):
            return None
        t = toks[pos]
        pos += 1
        if t == "(":
            inner = expr()
            if inner is None or pos >= len(toks) or toks[pos] != ")":
                return None
            pos += 1
            return inner
        if t in (")", "and", "or"):
            return None
        return [[t]]

    out = expr()
    return out if pos == len(toks) else None


def atom_text(atom, clause, names):
    """One test in the table's form; '' for a guard implied by the rest of its clause; None when
    it cannot be decided from the fields of earlier cards."""
    m = re.match(r"^self\.(\w+)( is not None)?$", atom)
    if m:  # "self.x" (x written and not 0) or "self.x is not None" (x written)
        name = m.group(1)
        if any(a != atom and f"self.{name}" in a for a in clause):
            return ""  # a guard: the other test on x compares a blank field through its default
        if m.group(2) or name not in names:
            return None  # "written at all" cannot be told from a default; a flag of the card itself
        return f"{names[name]} != 0"
    m = SIMPLE.match(atom)
    if not m:
        return None
    absolute, name, op, rest = m.group(1), m.group(2), m.group(3), m.group(4)
    if name not in names:
        return None
    vals = number_list(rest)
    if vals is None or (op != "in" and len(vals) != 1):
        return None
    if absolute:
        if op not in ("==", "in"):
            return None
        op = "in"
        vals = sorted(set(vals + [-v for v in vals]))
    return f"{names[name]} {op} {';'.join(repr(v) for v in vals)}"


def condition_text(cond, names):
    """The condition in the table's form, '' when there is none, None when it cannot be decided.
    `names` maps pydyna names to table names for the fields of earlier cards only: a card's
    presence cannot depend on its own fields. Several fields: " and " binds before " or "."""
    if cond is None:
        return ""
    c = cond.strip()
    m = re.match(r"^self\.(\w+) == None or self\.(\w+) == 0$", c)
    if m and m.group(1) == m.group(2):
        c = f"self.{m.group(1)} == 0"  # blank or 0: a blank field compares through its default
    toks = tokens(c)
    clauses = dnf(toks) if toks else None
    if not clauses:
        return None
    out = []
    for clause in clauses:
        tests = [atom_text(a, clause, names) for a in clause]
        if any(t is None for t in tests):
            return None
        tests = [t for t in tests if t]
        if not tests:
            return None
        out.append(" and ".join(tests))
    return " or ".join(out)


def card_lines(entry):
    names = {}  # pydyna name -> table name, for conditions
    cards = entry["cards"]
    out = []

    def stop(opt="-"):
        out.append(f"x|{opt}||")
        return opt not in ("-", "*")  # an option's unknown card stops only blocks with that option

    for i, c in enumerate(cards):
        last = i == len(cards) - 1 or all(
            d.get("option") and d.get("option") not in CONTACT_OPTIONAL for d in cards[i + 1:])
        opt = c.get("option") or "-"
        if opt in CONTACT_OPTIONAL and str(c.get("position", "")).startswith("post"):
            opt = "*"
        kind = c["kind"]
        if c.get("condition") and "has_nondefault_values" in c["condition"] and "[" in c["condition"]:
            cond = ""  # an optional trailing card: written only when it has values
        else:
            cond = condition_text(c.get("condition"), names)
        for f in c.get("fields", []):
            names.setdefault(f["name"], field_name(f))
        if cond is None:
            if stop(opt):
                continue
            return out
        if kind == "card":
            out.append(f"1|{opt}|{cond}|" + ",".join(padded(c["fields"])))
        elif kind == "table" and (c.get("count") is None or last):
            out.append(f"r|{opt}|{cond}|" + ",".join(padded(c["fields"])))
        elif kind == "series" and (c.get("count") is None or last) and not c.get("value_struct"):
            vt = c.get("value_type", "float")
            base = re.sub(r"\[\d+\]$", "", c["fields"][0]["name"]) if c["fields"] else c.get("name", "value")
            per, w = int(c["per_line"]), int(c["value_width"])
            fs = [field_text({"offset": 0, "width": w, "type": vt}, offset=k * w, width=w, name=base.upper())
                  for k in range(per)]
            out.append(f"r|{opt}|{cond}|" + ",".join(fs))
        elif kind == "table_group" and last and cond == "":
            lines = c["lines"]
            for k, line in enumerate(lines):
                fields = line["fields"] if isinstance(line, dict) else line
                rep = f"g{len(lines)}" if k == 0 else "1"
                out.append(f"{rep}|{opt}||" + ",".join(padded(fields)))
        elif kind == "card_set" and cond == "":
            for d in c["cards"]:
                if d["kind"] != "card" or d.get("condition") or d.get("option"):
                    break
                for f in d["fields"]:
                    names.setdefault(f["name"], field_name(f))
                out.append(f"1|{opt}||" + ",".join(padded(d["fields"])))
            if stop(opt):  # the set repeats, and its later cards depend on values: not followed
                continue
            return out
        else:
            if stop(opt):
                continue
            return out
    if not any(l[0] in "rg" or l.startswith("x|-|") for l in out):
        stop()  # lines past the last card: newer versions may read them; not reported
    return out


def solid_nodes(first, count, offset):
    return ",".join(f"N{first + k}:I:{offset + 8 * k}:8::NODE" for k in range(count))


# Keywords pydyna does not generate, written here by hand from the LS-DYNA manual (same format).
# *ELEMENT_SOLID (manual vol. I, *ELEMENT_SOLID): since R9 one element is two lines, EID PID (I8)
# then N1-N10 (I8); the older one-line form EID PID N1-N8 (10 I8) is still read. LS-DYNA tells
# them apart by the first line: nodes after PID make it the one-line form. So the node line is
# read only when N1 of the first line is blank (0 is no node). Node ids are not followed (mesh
# connectivity is the mesher's: model/id_links.cpp); PID is, to *PART.
HAND_WRITTEN = {
    "*ELEMENT_SOLID": "\n".join([
        "",
        "g2|-||EID:I:0:8,PID:I:8:8::PART," + solid_nodes(1, 8, 16),
        "1|-|N1 == 0|" + solid_nodes(1, 10, 0),
    ]),
}


# *ELEMENT_SHELL_{THICKNESS,BETA,MCID}...: the THIC5-THIC8 card belongs to 8-node shells only, whose
# mid-side nodes N5-N8 (pydyna: "Mid side nodal point 5") are given; a 4-node shell is two lines
# (OpenRadioss' Keyword971 shell.cfg reads *ELEMENT_SHELL_THICKNESS as the node card and the
# THIC1-4/BETA card, nothing more). pydyna reads the card always, so 4-node shells drift out of step.
EIGHT_NODE_CARD = "N5 != 0 or N6 != 0 or N7 != 0 or N8 != 0"


def eight_node_thickness(lines):
    out = []
    for line in lines:
        rep, opt, cond, fields = line.split("|", 3)
        if fields.startswith("THIC5:") and cond == "":
            cond = EIGHT_NODE_CARD
        out.append("|".join([rep, opt, cond, fields]))
    return out


def cxx_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def main():
    data = json.load(open(sys.argv[1]))
    src = data["source"]
    kws = data["keywords"]
    rows = []
    for name in sorted(kws):
        e = kws[name]
        LINKS.clear()
        LINKS.update(e.get("links", {}))
        lines = card_lines(e)
        if name.upper().startswith("*ELEMENT_SHELL"):
            lines = eight_node_thickness(lines)
        body = " ".join(e.get("options", [])) + "\n" + "\n".join(lines)
        # Keyword names are case-insensitive and looked up upper-cased; pydyna spells two with
        # lower-case letters (*MAT_115_o, *MAT_249_UDfiber).
        rows.append((name.upper(), body))
    for name, body in HAND_WRITTEN.items():
        if name not in kws:
            rows.append((name, body))
    rows.sort()
    print("// GENERATED by scripts/gen_keyword_layouts.py from lsdyna-keyword-layouts.json; do not edit.")
    print(f"// Source: github.com/{src['repository']} at {src['commit']}, {src['path']}")
    print(f"// (pydyna's generated keyword classes). License: {src['license']}; {src['copyright']}")
    print("// The license text is in grammar/keywords/generated/LICENSE-pydyna. Known errors of these layouts")
    print("// and how sphdeck guards against them: grammar/keywords/generated/README.md; hand-written tables win.")
    print('#include "grammar/keywords/generated_layouts.hpp"')
    print()
    print("namespace sphdeck::keywords::generated {")
    print()
    print("namespace {")
    print("using namespace std::string_view_literals;")
    print("// \"...\"sv: the length comes with the literal, so no strlen runs at compile time (clang's")
    print("// constexpr step limit stops a strlen over 3,684 long literals).")
    print("constexpr LayoutEntry kLayouts[] = {")
    for name, body in rows:
        print(f"    {{{cxx_string(name)}sv, {cxx_string(body)}sv}},")
    print("};")
    print("}  // namespace")
    print()
    print("std::span<const LayoutEntry> layouts() { return kLayouts; }")
    print()
    print("}  // namespace sphdeck::keywords::generated")


if __name__ == "__main__":
    main()
