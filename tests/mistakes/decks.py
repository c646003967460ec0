"""Decks as lines and blocks, and how sphdeck reads them (check findings, dump values).

The seeded-mistakes test plants one mistake at a time into a copy of a deck. This module knows just
enough about the two formats to find where a mistake can go: keyword/header lines, comment lines, the
data lines of each block, the fixed grids of the bulk blocks (*NODE, *ELEMENT_SPH, set lists) that
`sphdeck dump` does not list value by value. Everything else about a value (its field, whether it is
a number) comes from `sphdeck dump`, so the plants follow sphdeck's own layouts.
"""
import json
import os
import re
import subprocess

TIMEOUT_S = 60

# Columns of the bulk cards in the standard LS-DYNA format (the keyword manual; `sphdeck keyword`).
DYNA_GRIDS = {
    "*NODE": [8, 16, 16, 16, 8, 8],
    "*ELEMENT_SPH": [8, 8, 16, 10],
}
SET_LIST_GRID = [10] * 8  # the id lines of *SET_NODE_LIST, *SET_PART_LIST... (after the SID card)
NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eEdD]?[+-]?\d+)?$")


class Block:
    """One keyword (LS-DYNA `*NAME`) or header (OpenRadioss `/A/B/id`) and its lines."""

    def __init__(self, name, line):
        self.name = name          # upper case, LS-DYNA format suffixes (+ - %) removed
        self.raw_name = name
        self.line = line          # 1-based line of the keyword/header
        self.data = []            # 1-based lines of data (no comments)
        self.end = line           # last line before the next block (comments included)
        self.suffix = ""


class Deck:
    """A deck file: its lines (without line ends), their ends, and its blocks."""

    def __init__(self, path, fmt):
        self.path = path
        self.fmt = fmt  # "dyna" or "radioss"
        with open(path, "rb") as f:
            text = f.read().decode("latin-1")
        pieces = text.splitlines(keepends=True)
        self.lines = [p.rstrip("\r\n") for p in pieces]
        self.ends = [p[len(p.rstrip("\r\n")):] or "\n" for p in pieces]
        self.blocks = self._blocks()
        first = self.lines[0].upper() if self.lines else ""
        self.long_format = any(b.name == "*KEYWORD" and re.search(r"LONG|I10", self.lines[b.line - 1].upper())
                               for b in self.blocks) or "LONG" in first

    def is_comment(self, n):
        text = self.lines[n - 1]
        return text.startswith("$") if self.fmt == "dyna" else text.startswith("#")

    def _blocks(self):
        blocks = []
        head = "*" if self.fmt == "dyna" else "/"
        for n, text in enumerate(self.lines, 1):
            if text.startswith(head):
                word = text.split()[0] if text.split() else text
                block = Block(word.upper(), n)
                if self.fmt == "dyna":
                    block.name = word.upper().rstrip("+-%")
                    block.suffix = word[len(block.name):]
                if blocks:
                    blocks[-1].end = n - 1
                blocks.append(block)
            elif blocks and not self.is_comment(n) and (self.fmt == "dyna" or not text.startswith("#")):
                blocks[-1].data.append(n)
        if blocks:
            blocks[-1].end = len(self.lines)
        return blocks

    def block_of(self, n):
        for b in self.blocks:
            if b.line <= n <= b.end:
                return b
        return None

    def text(self, lines=None):
        lines = self.lines if lines is None else lines
        ends = self.ends + ["\n"] * max(0, len(lines) - len(self.ends))
        return "".join(l + ends[min(i, len(ends) - 1)] for i, l in enumerate(lines))


def grid_fields(text, widths):
    """The fields of a fixed-format line cut at the given widths (the rest of the line last)."""
    out, start = [], 0
    for w in widths:
        out.append(text[start:start + w].strip())
        start += w
    out.append(text[start:].strip())
    return tuple(out)


def grid_reading(text, widths):
    """What a bulk line means: its fields, or for the id lines of a *SET_..._LIST the ids it lists
    (a set's members do not depend on the field they sit in: an id moved one field on is the same set)."""
    fields = grid_fields(text, widths)
    if widths is SET_LIST_GRID:
        return tuple(sorted(f for f in fields[:-1] if f)), fields[-1]
    return fields


def bulk_grid(deck, block, n):
    """The grid of a data line of a bulk block, or None when this module does not know it."""
    if deck.fmt != "dyna" or deck.long_format or block.suffix:
        return None
    if block.name in DYNA_GRIDS:
        return DYNA_GRIDS[block.name]
    if block.name.startswith("*SET_") and block.name.endswith("_LIST") and block.data and n != block.data[0]:
        return SET_LIST_GRID
    return None


def tokens(text):
    """(start, end) 0-based spans of the blank-separated words of a line."""
    return [(m.start(), m.end()) for m in re.finditer(r"\S+", text)]


def run_sphdeck(sphdeck, args, include_dir):
    cmd = [sphdeck] + args + ["-I", include_dir]
    try:
        done = subprocess.run(cmd, capture_output=True, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return None, "timed out"
    if done.returncode not in (0, 1):
        err = done.stderr.decode("utf-8", "replace").strip().splitlines()
        return None, f"exit {done.returncode}: {err[-1] if err else ''}"
    try:
        return json.loads(done.stdout), None
    except json.JSONDecodeError as e:
        return None, f"not JSON: {e}"


def check(sphdeck, path, include_dir, reports=None):
    """Errors and warnings of `sphdeck check`: list of (file, line, code, severity, message). `reports`, a
    list, when given, receives the whole JSON report (fixes included)."""
    # --alone: a plant is a deck of its own; searching the scratch folder for decks that include it
    # (engine/include_context) would read every other plant, for every plant.
    report, problem = run_sphdeck(sphdeck, ["check", "--format", "json", "--no-config", "--alone", path], include_dir)
    if report is None:
        return None, problem
    if reports is not None:
        reports.append(report)
    found = []
    for d in report["diagnostics"]:
        if d["severity"] in ("error", "warning"):
            found.append((os.path.realpath(d["file"]) if d.get("file") else "", d.get("line") or 0,
                          d["code"], d["severity"], d["message"]))
    return found, None


def dump(sphdeck, path, include_dir):
    report, problem = run_sphdeck(sphdeck, ["dump", "--format", "json", path], include_dir)
    return report, problem


def _blank_is_zero(value):
    return 0 if value is None or (isinstance(value, (int, float)) and not isinstance(value, bool) and value == 0) \
        else value


def dump_values(report):
    """What the deck reads, without where: every keyword's field values, node and particle counts."""
    if report is None:
        return None
    out = []
    for k in report.get("keywords", []):
        # Values only: a blank read as its default and the default typed out read the same, and a blank
        # without a default (null: OpenRadioss reads blank cells as 0) the same as 0.
        out.append((k["name"], tuple((n, json.dumps(_blank_is_zero(f["value"]))) for n, f in k["fields"].items())))
    out.append(json.dumps(report.get("unknown_keywords"), sort_keys=True))
    out.append(json.dumps(report.get("nodes"), sort_keys=True))
    out.append(json.dumps(report.get("particles"), sort_keys=True))
    return out


def dump_fields(report, path):
    """{line: [(keyword, field, value, column, explicit, keyword index)]} of the fields the dump reads from this file."""
    out = {}
    if report is None:
        return out
    real = os.path.realpath(path)
    for index, k in enumerate(report.get("keywords", [])):
        if os.path.realpath(k.get("file", "")) != real:
            continue
        for name, f in k["fields"].items():
            if f.get("line"):
                out.setdefault(f["line"], []).append((k["name"], name, f["value"], f.get("column"), f["explicit"],
                                                      index))
    return out


def is_number_text(text):
    return bool(NUMBER.match(text))


def run_sphdeck_text(sphdeck, args):
    done = subprocess.run([sphdeck] + args, capture_output=True, timeout=TIMEOUT_S)
    return done.stdout.decode("utf-8", "replace"), done.returncode
