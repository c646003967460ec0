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
      CONDITION - none, else FIELD OP V1;V2... with OP one of == != < <= > >= in
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


def field_text(f, offset=None, width=None, name=None, ftype=None):
    t = ftype or f["type"]
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


def condition_text(cond, names):
    """The condition in the table's form, '' when there is none, None when it cannot be decided."""
    if cond is None:
        return ""
    c = cond.strip()
    # "self.x and abs(self.x) == 1", "self.x is not None and self.x < 0": the guard only says the
    # field is written; a blank field compares through its default below.
    m = re.match(r"^self\.(\w+)( is not None)? and (.+)$", c)
    if m and f"self.{m.group(1)}" in m.group(3) and " and " not in m.group(3) and " or " not in m.group(3):
        c = m.group(3).strip()
    m = re.match(r"^self\.(\w+) == None or self\.(\w+) == 0$", c)
    if m and m.group(1) == m.group(2):
        c = f"self.{m.group(1)} == 0"
    if " and " in c or " or " in c or "(" in c.replace("abs(", ""):
        return None
    m = SIMPLE.match(c)
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
        for f in c.get("fields", []):
            names.setdefault(f["name"], field_name(f))
        kind = c["kind"]
        if c.get("condition") and "has_nondefault_values" in c["condition"] and "[" in c["condition"]:
            cond = ""  # an optional trailing card: written only when it has values
        else:
            cond = condition_text(c.get("condition"), names)
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
        body = " ".join(e.get("options", [])) + "\n" + "\n".join(card_lines(e))
        rows.append((name, body))
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
