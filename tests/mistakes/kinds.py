"""The kinds of mistakes people make when they edit a deck by hand, one small function each.

A kind takes a host (the deck, what sphdeck's dump reads from it, a seeded RNG) and yields candidate
plants. A plant is the mutated list of lines, the lines where the finding must be (in the mutant's
numbering), how original line numbers map into the mutant, and how to tell whether the mistake changes
what is read (`change`: "dump" compares `sphdeck dump` values before and after, "grid" compares the
fixed-column fields of the planted lines, None when the mistake always changes the deck). The runner
keeps the first few candidates whose mistake is real.
"""
import re

from decks import bulk_grid, grid_fields, grid_reading, is_number_text, tokens, SET_LIST_GRID, DYNA_GRIDS


class Plant:
    def __init__(self, kind, lines, targets, what, change=None, grid_lines=(), grid=None, line_map=None):
        self.kind = kind
        self.lines = lines            # the mutant's lines
        self.targets = set(targets)   # lines (mutant numbering) where a new error/warning must be; 0 = deck level
        self.what = what              # one line for the miss list
        self.change = change          # "dump", "grid" or None (always a change)
        self.grid_lines = grid_lines  # for "grid": the planted lines, and the grid each is read with
        self.grid = grid
        self.line_map = line_map or (lambda n: n)


def replaced(lines, n, text):
    out = list(lines)
    out[n - 1] = text
    return out


def data_lines_with_fields(host, block_filter=None):
    """Data lines of the host file that hold a field of the dump or of a known bulk grid."""
    cached = getattr(host, "data_lines_cache", None)
    if cached is not None and block_filter is None:
        return list(cached)
    out = []
    for b in host.deck.blocks:
        if block_filter and not block_filter(b):
            continue
        for n in b.data:
            text = host.deck.lines[n - 1]
            if not text.strip() or "\t" in text:
                continue
            if n in host.fields or bulk_grid(host.deck, b, n):
                out.append((b, n))
    if block_filter is None:
        host.data_lines_cache = list(out)
    return out


def number_tokens(host, b, n):
    """(start, end) of the words of line n that are numbers read into a numeric field."""
    text = host.deck.lines[n - 1]
    grid = bulk_grid(host.deck, b, n)
    starts = {f[3]: f for f in host.fields.get(n, []) if f[4] and isinstance(f[2], (int, float))
              and not isinstance(f[2], bool)}
    out = []
    for s, e in tokens(text):
        word = text[s:e]
        if not is_number_text(word):
            continue
        if grid or (s + 1) in starts:
            out.append((s, e))
    return out


def put_right_aligned(text, s, e, new):
    """Replace the word at [s, e) by `new`, keeping the word's last column (or its first when it is
    left-aligned in its field: a blank before it is missing); None when it does not fit."""
    if s >= e or e > len(text):
        return None
    if len(new) <= e - s:
        return text[:s] + new.rjust(e - s) + text[e:]
    grow = len(new) - (e - s)
    if s - grow >= 0 and text[s - grow:s].strip() == "" and (s - grow == 0 or text[s - grow - 1] == " "):
        return text[:s - grow] + new + text[e:]
    if text[e:e + grow].strip() == "":
        return text[:s] + new + text[e + grow:]
    return None


# ----------------------------------------------------------------------------------------------- kinds

def _misspelt(word, limit, letters, rng, known):
    """`word` with a letter at one of `letters` transposed (within the first `limit` characters), dropped or
    doubled; None when six tries give only names `known` accepts."""
    for _ in range(6):
        op = rng.choice(("swap", "drop", "double"))
        i = rng.choice(letters)
        if op == "swap":
            if i + 1 >= limit or not word[i + 1].isalpha() or word[i] == word[i + 1]:
                continue
            new = word[:i] + word[i + 1] + word[i] + word[i + 2:]
        elif op == "drop":
            new = word[:i] + word[i + 1:]
        else:
            new = word[:i] + word[i] + word[i:]
        if not known(new):
            return new
    return None


def keyword_typo(host, rng):
    """*CONTROL_SPH -> *CONTROL_SHP: a transposed, dropped or doubled letter in a keyword's name."""
    if host.deck.fmt != "dyna":
        return
    blocks = [b for b in host.deck.blocks if b.name not in ("*KEYWORD", "*END", "*COMMENT")]
    rng.shuffle(blocks)
    for b in blocks:
        text = host.deck.lines[b.line - 1]
        word = text.split()[0]
        core = "_".join(word.split("_")[:2])  # the name, not its options (_TITLE, _ID...)
        letters = [i for i in range(1, len(core)) if core[i].isalpha()]
        if len(letters) < 3:
            continue
        new = _misspelt(word, len(core), letters, rng, lambda w: w.upper().rstrip("+-%") in host.known_keywords)
        if new:
            yield Plant("keyword-typo", replaced(host.deck.lines, b.line, new + text[len(word):]),
                        [b.line], f"{word} -> {new}")


def radioss_header_typo(host, rng):
    """OpenRadioss: a transposed, dropped or doubled letter in the first word of a header (`/SPHCEL` ->
    `/SPHCLE`, `/PROP/SPH/2` -> `/PORP/SPH/2`); never a first word of a header the starter knows."""
    if host.deck.fmt != "radioss":
        return
    heads = {k.split("/")[1] for k in host.known_keywords if k.startswith("/") and k.count("/") >= 1}
    blocks = [b for b in host.deck.blocks if b.name not in ("/BEGIN", "/END")]
    rng.shuffle(blocks)
    for b in blocks:
        text = host.deck.lines[b.line - 1]
        if not text.startswith("/"):
            continue
        parts = text[1:].split("/")[0].split()
        word = parts[0] if parts else ""  # none for //SUBMODEL
        letters = [i for i in range(len(word)) if word[i].isalpha()]
        if len(letters) < 3 or not heads:
            continue
        new = _misspelt(word, len(word), letters, rng, lambda w: w.upper() in heads)
        if new:
            yield Plant("radioss-header-typo", replaced(host.deck.lines, b.line, "/" + new + text[1 + len(word):]),
                        [b.line], f"/{word} -> /{new}")


def _shift(host, rng, kind, by):
    """A data line shifted `by` columns (right > 0, left < 0: leading blanks removed)."""
    if host.deck.fmt != "dyna":
        return
    skip = ("*TITLE", "*KEYWORD", "*COMMENT", "*PARAMETER", "*INCLUDE")
    lines = [(b, n) for b, n in data_lines_with_fields(host) if not b.name.startswith(skip)
             and "," not in host.deck.lines[n - 1] and "&" not in host.deck.lines[n - 1]]
    rng.shuffle(lines)
    for b, n in lines:
        text = host.deck.lines[n - 1]
        grid = bulk_grid(host.deck, b, n)
        if by > 0:
            new = " " * by + text
        else:
            if not text.startswith(" " * -by) or not _crosses_left(text, grid or [10] * 8, -by):
                continue
            new = text[-by:]
        if grid:
            yield Plant(kind, replaced(host.deck.lines, n, new), [n], f"{b.name} line {n}", "grid", [n], grid)
        else:
            if any(isinstance(f[2], str) for f in host.fields.get(n, [])):
                continue  # a title or name line: a shifted name is still the name
            yield Plant(kind, replaced(host.deck.lines, n, new), [n], f"{b.name} line {n}", "dump")


def _crosses_left(text, grid, by):
    """Whether some value would cross into the field before it when the line moves `by` columns left
    (a right-aligned value shorter than its field only moves inside it: no mistake). A first guess for
    cards (10-column fields assumed); `sphdeck dump` decides."""
    starts, at = set(), 0
    for w in grid:
        starts.update(range(at, at + by))
        at += w
    return any(s in starts and s >= by for s, _ in tokens(text))


def shift_right_1(host, rng):
    """A data line one column right of its fields (a blank typed at the start)."""
    return _shift(host, rng, "shift-right-1", 1)


def shift_right_3(host, rng):
    """A data line three columns right of its fields."""
    return _shift(host, rng, "shift-right-3", 3)


def shift_left_2(host, rng):
    """A data line two columns left of its fields (two leading blanks deleted)."""
    return _shift(host, rng, "shift-left-2", -2)


def _fit8(value):
    """A field's text rewritten for an 8-column field the way a person would (at most 7 characters)."""
    if len(value) <= 7:
        return value
    try:
        number = float(value.replace("d", "e").replace("D", "e"))
    except ValueError:
        return None
    if value.lstrip("+-").isdigit():
        return None
    for digits in range(6, 0, -1):
        text = f"{number:.{digits}g}"
        if len(text) <= 7:
            return text
    return None


WIDTH_8_MAX_LINES = 400


def width_8(host, rng):
    """A *NODE / *ELEMENT_SPH / *SET_..._LIST block written in 8-column fields where 10 or 16 are read."""
    if host.deck.fmt != "dyna" or host.deck.long_format:
        return
    # Blocks of at most WIDTH_8_MAX_LINES lines: a person types or pastes a small block; the big
    # generated ones would only slow the test down (every line of the mutant is a finding today).
    blocks = [b for b in host.deck.blocks if not b.suffix and len(b.data) <= WIDTH_8_MAX_LINES and (
        b.name in DYNA_GRIDS or (b.name.startswith("*SET_") and b.name.endswith("_LIST") and len(b.data) >= 2))]
    rng.shuffle(blocks)
    for b in blocks:
        data = b.data if b.name in DYNA_GRIDS else b.data[1:]
        grid = DYNA_GRIDS.get(b.name, SET_LIST_GRID)
        lines = list(host.deck.lines)
        ok = True
        for n in data:
            text = lines[n - 1]
            if "," in text or "&" in text or "\t" in text:
                ok = False
                break
            fields = list(grid_fields(text, grid))
            rest = fields.pop()
            while fields and not fields[-1]:
                fields.pop()
            cells = [_fit8(f) if f else "" for f in fields]
            if any(c is None for c in cells):
                ok = False
                break
            lines[n - 1] = "".join(c.rjust(8) for c in cells) + ((" " + rest) if rest else "")
        if ok and data:
            # The block's first data line (a set's SID card, not rewritten) or the first rewritten line
            # whose reading changes (an *ELEMENT_SPH line 8 wide reads the same until MASS is long).
            first = next((n for n in data if grid_reading(lines[n - 1], grid) != grid_reading(host.deck.lines[n - 1], grid)),
                         data[0])
            yield Plant("width-8", lines, {b.data[0], first}, f"{b.name} block at line {b.line} ({len(data)} lines)",
                        "grid", data, grid)


def letter_o(host, rng):
    """`O` typed for `0` in a number."""
    lines = data_lines_with_fields(host)
    rng.shuffle(lines)
    for b, n in lines:  # lazily: big decks have 1e5 lines
        zeros = [i for s, e in number_tokens(host, b, n) for i in range(s, e) if host.deck.lines[n - 1][i] == "0"]
        if not zeros:
            continue
        i = rng.choice(zeros)
        text = host.deck.lines[n - 1]
        yield Plant("letter-O", replaced(host.deck.lines, n, text[:i] + "O" + text[i + 1:]), [n],
                    f"{b.name} line {n}: {text[max(0, i - 4):i + 4].strip()!r}")


def decimal_comma(host, rng):
    """`1,5` for `1.5` (a decimal comma; in LS-DYNA a comma makes the line free format)."""
    lines = data_lines_with_fields(host)
    rng.shuffle(lines)
    for b, n in lines:  # lazily: big decks have 1e5 lines
        text = host.deck.lines[n - 1]
        if "," in text:
            continue
        dots = []
        for s, e in number_tokens(host, b, n):
            dot = text.find(".", s, e)
            if dot > s and text[dot - 1].isdigit() and dot + 1 < e and text[dot + 1].isdigit():
                dots.append(dot)
        if not dots:
            continue
        dot = rng.choice(dots)
        yield Plant("decimal-comma", replaced(host.deck.lines, n, text[:dot] + "," + text[dot + 1:]), [n],
                    f"{b.name} line {n}: {text.split()[0] if text.split() else ''}...")


REFERENCE_FIELDS_DYNA = {"*PART": ("SECID", "MID", "EOSID")}
REFERENCE_FIELDS_RADIOSS = ("prop_ID", "mat_ID")


def _unused_id(host, rng):
    """An id no number of the deck spells: 4 digits when one is free, else more."""
    if getattr(host, "numbers_cache", None) is None:
        host.numbers_cache = set(re.findall(r"\d+", "\n".join(host.deck.lines)))
    for low in (9000, 90000, 900000, 9000000):
        for _ in range(50):
            candidate = str(rng.randrange(low, low + low // 9))
            if candidate not in host.numbers_cache:
                return candidate
    return "98765432"


def missing_id(host, rng):
    """An id that does not exist: a part's section, material or EOS, a particle's part, a set."""
    if any(code == "DK010" for _, _, code, _, _ in host.found):
        return  # an include is missing: it may define any id, so references are not checked (DK010 says so)
    cands = []
    for n, fields in host.fields.items():
        b = host.deck.block_of(n)
        if b is None:
            continue
        for kw, name, value, col, explicit, _ in fields:
            if not explicit or not isinstance(value, int) or isinstance(value, bool) or value <= 0:
                continue
            wanted = (host.deck.fmt == "dyna" and kw.startswith("*PART") and name in ("SECID", "MID", "EOSID")) or (
                host.deck.fmt == "dyna" and name in ("NSID", "PSID", "SSID") and not kw.startswith("*SET")) or (
                host.deck.fmt == "radioss" and kw.startswith("/PART") and name in REFERENCE_FIELDS_RADIOSS)
            if wanted:
                cands.append((n, col - 1, f"{kw} {name}"))
    for b in host.deck.blocks:
        if b.name == "*ELEMENT_SPH" and not host.deck.long_format and not b.suffix:
            for n in b.data[:50]:
                text = host.deck.lines[n - 1]
                pid = text[8:16]
                if pid.strip().isdigit() and pid.strip() != "0":
                    cands.append((n, 8 + len(pid) - len(pid.lstrip()), "*ELEMENT_SPH PID"))
    rng.shuffle(cands)
    for n, start, what in cands:
        text = host.deck.lines[n - 1]
        end = start
        while end < len(text) and not text[end].isspace():
            end += 1
        new_id = _unused_id(host, rng)
        new = put_right_aligned(text, start, end, new_id)
        if new is not None:
            yield Plant("missing-id", replaced(host.deck.lines, n, new), [n],
                        f"{what} line {n}: {text[start:end]} -> {new_id}")


def zero_density(host, rng):
    """Density 0 in the material a part uses (LS-DYNA RO, OpenRadioss RHO_I)."""
    used = set()
    for fields in host.all_fields:
        kw, name, value = fields
        if (kw.startswith("*PART") and name == "MID") or (kw.startswith("/PART") and name == "mat_ID"):
            used.add(value)
    cands = []
    for n, fields in host.fields.items():
        for kw, name, value, col, explicit, index in fields:
            if not explicit or not isinstance(value, (int, float)) or value == 0:
                continue
            if host.deck.fmt == "dyna" and kw.startswith("*MAT") and name == "RO":
                mid = next((f[2] for fs in host.fields.values() for f in fs if f[5] == index and f[1] == "MID"), None)
                if mid in used:
                    cands.append((n, col - 1, kw))
            if host.deck.fmt == "radioss" and kw.startswith("/MAT") and name.upper() in ("RHO_I", "RHO"):
                try:
                    mid = int(kw.rstrip("/").split("/")[-1])
                except ValueError:
                    continue
                if mid in used:
                    cands.append((n, col - 1, kw))
    rng.shuffle(cands)
    for n, start, kw in cands:
        text = host.deck.lines[n - 1]
        end = start
        while end < len(text) and not text[end].isspace():
            end += 1
        new = put_right_aligned(text, start, end, "0.0")
        if new is not None:
            yield Plant("zero-density", replaced(host.deck.lines, n, new), [n], f"{kw} line {n}: {text[start:end]} -> 0.0")


def _node_coordinates(host):
    out = []
    for b in host.deck.blocks:
        if b.name != "*NODE":
            continue
        if b.suffix or host.deck.long_format:
            return None
        for n in b.data:
            text = host.deck.lines[n - 1]
            try:
                if "," in text:
                    parts = [p.strip() for p in text.split(",")]
                    xyz = [float(p or 0) for p in parts[1:4]]
                else:
                    f = grid_fields(text, DYNA_GRIDS["*NODE"])
                    xyz = [float(v or 0) for v in f[1:4]]
            except ValueError:
                return None
            out.append(xyz)
    return out


def no_control_sph(host, rng):
    """*CONTROL_SPH deleted from a 2D deck (IDIM 2) whose particles all lie in one plane."""
    if host.deck.fmt != "dyna":
        return
    control = [b for b in host.deck.blocks if b.name == "*CONTROL_SPH"]
    spheres = [b for b in host.deck.blocks if b.name == "*ELEMENT_SPH"]
    if len(control) != 1 or not spheres:
        return
    idim = [f[2] for fs in host.fields.values() for f in fs if f[0] == "*CONTROL_SPH" and f[1] == "IDIM"]
    if not idim or idim[0] not in (2, -2):
        return
    xyz = _node_coordinates(host)
    if not xyz:
        return
    size = max(max(p[i] for p in xyz) - min(p[i] for p in xyz) for i in range(3)) or 1.0
    if not any(max(p[i] for p in xyz) - min(p[i] for p in xyz) <= 1e-9 * size for i in range(3)):
        return
    b = control[0]
    gone = b.end - b.line + 1
    lines = host.deck.lines[:b.line - 1] + host.deck.lines[b.end:]
    after = lambda n: n if n < b.line else n - gone
    # Where the finding may be: deck level, the line *CONTROL_SPH stood on (now the next keyword), or
    # the keyword line of the first *SECTION_SPH, *ELEMENT_SPH, *DEFINE_SPH_... Not a particle's line:
    # the symptom (SPH113 "a unit mistake?" on the first particle) lands there.
    targets = {0, b.line}
    for name in ("*SECTION_SPH", "*ELEMENT_SPH", "*DEFINE_SPH_"):
        first = next((x for x in host.deck.blocks if x.name.startswith(name)), None)
        if first:
            targets.add(after(first.line))
    yield Plant("no-control-sph", lines, targets, f"*CONTROL_SPH at line {b.line} deleted",
                line_map=lambda n: None if b.line <= n <= b.end else after(n))


def parameter_typo(host, rng):
    """A parameter reference misspelt: &endt -> &endx."""
    text = "\n".join(host.deck.lines).lower()
    # Only references to a parameter this file defines: a module checked alone reads names its
    # includer defines, undefined before the plant as after.
    defined = " ".join(host.deck.lines[n - 1] for b in host.deck.blocks if "PARAMETER" in b.name
                       for n in b.data).lower()
    cands = []
    for b in host.deck.blocks:
        if "PARAMETER" in b.name:
            continue
        for n in b.data:
            for m in re.finditer(r"&([A-Za-z_][A-Za-z0-9_]*)", host.deck.lines[n - 1]):
                if re.search(r"\b" + re.escape(m.group(1).lower()) + r"\b", defined):
                    cands.append((b, n, m.start(1), m.end(1)))
    rng.shuffle(cands)
    for b, n, s, e in cands:
        line = host.deck.lines[n - 1]
        name = line[s:e]
        last = name[-1]
        for sub in ("x", "q", "z") if last.isalpha() else ("7", "8", "9"):
            new = name[:-1] + (sub.upper() if last.isupper() else sub)
            if new.lower() != name.lower() and new.lower() not in text:
                yield Plant("parameter-typo", replaced(host.deck.lines, n, line[:s] + new + line[e:]), [n],
                            f"{b.name} line {n}: &{name} -> &{new}")
                break


def radioss_straddle(host, rng):
    """OpenRadioss: a value written across the boundary of its cell (`2.4` as `2.` | `4`)."""
    if host.deck.fmt != "radioss":
        return
    cands = []
    for n, fields in host.fields.items():
        text = host.deck.lines[n - 1]
        for kw, name, value, col, explicit, _ in fields:
            if not explicit or not isinstance(value, (int, float)) or isinstance(value, bool):
                continue
            s = col - 1
            e = s
            while e < len(text) and not text[e].isspace():
                e += 1
            if e - s >= 2 and s < len(text):
                cands.append((n, s, e, f"{kw} {name}"))
    rng.shuffle(cands)
    for n, s, e, what in cands:
        text = host.deck.lines[n - 1]
        k = rng.randrange(1, e - s)
        if text[e:e + k].strip():
            continue
        new = text[:s] + " " * k + text[s:e] + text[e + k:]
        yield Plant("radioss-straddle", replaced(host.deck.lines, n, new), [n], f"{what} line {n}: {text[s:e]}", "dump")


def radioss_shift(host, rng):
    """OpenRadioss: a /PROP or /MAT line shifted one column right."""
    if host.deck.fmt != "radioss":
        return
    lines = [n for n, fields in host.fields.items()
             if any(f[0].startswith(("/PROP", "/MAT")) and not isinstance(f[2], str) for f in fields)]
    rng.shuffle(lines)
    for n in lines:
        text = host.deck.lines[n - 1]
        yield Plant("radioss-shift", replaced(host.deck.lines, n, " " + text), [n],
                    f"{host.deck.block_of(n).name} line {n}", "dump")


def tab_in_line(host, rng):
    """A tab typed in a fixed-format line: the blanks before a value replaced by one tab (an editor's Tab
    key where the field's columns were meant). Most such tabs change nothing read (the value stays in
    its field, the solver counting a tab as one column): those are dropped as no-ops."""
    lines = [(b, n) for b, n in data_lines_with_fields(host) if "," not in host.deck.lines[n - 1]]
    rng.shuffle(lines)
    for b, n in lines:
        text = host.deck.lines[n - 1]
        words = tokens(text)
        gaps = [(words[i - 1][1], words[i][0]) for i in range(1, len(words)) if words[i][0] - words[i - 1][1] >= 2]
        if not gaps:
            continue
        s, e = rng.choice(gaps)
        yield Plant("tab-in-line", replaced(host.deck.lines, n, text[:s] + "\t" + text[e:]), [n],
                    f"{b.name} line {n}: tab at column {s + 1}", "dump")


def duplicated_block(host, rng):
    """A *PART / *SECTION_SPH / *MAT_ block (OpenRadioss /PART, /PROP, /MAT) copied and pasted with its id unchanged."""
    prefixes = ("*PART", "*SECTION_SPH", "*MAT_") if host.deck.fmt == "dyna" else ("/PART/", "/PROP/", "/MAT/")
    # *MAT_ADD_... (erosion, damage, thermal expansion...) adds options to a material named by its MID: it
    # defines no id of its own, so a second copy is not a duplicate id (whether it adds or replaces
    # criteria, the manual does not say), and it is left out like *PART_CONTACT.
    blocks = [b for b in host.deck.blocks if b.name.startswith(prefixes) and b.data
              and b.name not in ("*PART_CONTACT",) and not b.name.startswith("*MAT_ADD_")]
    rng.shuffle(blocks)
    for b in blocks:
        copy = host.deck.lines[b.line - 1:b.end]
        lines = host.deck.lines[:b.end] + copy + host.deck.lines[b.end:]
        size = len(copy)
        targets = range(b.end + 1, b.end + size + 1)
        yield Plant("duplicated-block", lines, targets, f"{b.name} at line {b.line} pasted twice",
                    line_map=lambda n, end=b.end, size=size: n if n <= end else n + size)


# Blocks that define or load nothing: the deck's frame and text (the finding names the blocks that do).
INERT_DYNA = ("*KEYWORD", "*END", "*COMMENT", "*TITLE", "*INCLUDE")
INERT_RADIOSS = ("/BEGIN", "/END", "/TITLE", "/DUMMY", "/ASSEMBLY", "/POSITION")


def stray_end(host, rng):
    """*END (OpenRadioss /END) pasted before a block that defines or loads something: the rest is dropped."""
    inert, end = (INERT_DYNA, "*END") if host.deck.fmt == "dyna" else (INERT_RADIOSS, "/END")
    blocks = [b for b in host.deck.blocks[1:] if not b.name.startswith(inert)]
    if host.deck.fmt == "radioss":  # the starter deck's blocks after /BEGIN
        begin = next((b for b in host.deck.blocks if b.name.startswith("/BEGIN")), None)
        blocks = [b for b in blocks if begin and b.line > begin.line]
    rng.shuffle(blocks)
    for b in blocks:
        at = b.line
        lines = host.deck.lines[:at - 1] + [end] + host.deck.lines[at - 1:]
        yield Plant("stray-end", lines, [at], f"{end} before {b.name} at line {at}",
                    line_map=lambda n, at=at: n if n < at else n + 1)


def missing_heading(host, rng):
    """The heading line of a *PART left out: its PID/SECID/MID line is read as the heading."""
    if host.deck.fmt != "dyna":
        return
    blocks = [b for b in host.deck.blocks if b.name in ("*PART", "*PART_INERTIA", "*PART_CONTACT")
              and len(b.data) >= 2 and not b.suffix]
    rng.shuffle(blocks)
    for b in blocks:
        h = b.data[0]
        card = host.deck.lines[b.data[1] - 1]
        if not re.match(r"^[ 0-9,]+$", card) or len(card.split()) < 2:
            continue  # the card 2 read as numbers only (a parameter reference reads as text too)
        lines = host.deck.lines[:h - 1] + host.deck.lines[h:]
        yield Plant("missing-heading", lines, [b.data[1] - 1], f"{b.name} at line {b.line}: heading deleted",
                    line_map=lambda n, h=h: n if n < h else (None if n == h else n - 1))


def lost_asterisk(host, rng):
    """A keyword line that lost its '*' (`PART` for `*PART`)."""
    if host.deck.fmt != "dyna":
        return
    blocks = [b for b in host.deck.blocks[1:] if not b.name.startswith(INERT_DYNA) and not b.suffix
              and host.deck.lines[b.line - 1].strip() == host.deck.lines[b.line - 1][:len(b.name)].strip()]
    rng.shuffle(blocks)
    for b in blocks:
        text = host.deck.lines[b.line - 1]
        yield Plant("lost-asterisk", replaced(host.deck.lines, b.line, text[1:]), [b.line], f"{b.name} -> {text[1:].strip()}")


# Keywords whose data lines are repeated lines (nodes, particles, sets, curves), text or the reader's own.
READ_AS_LINES = ("*NODE", "*ELEMENT", "*SET_", "*DEFINE_CURVE", "*DEFINE_TABLE", "*PARAMETER", "*KEYWORD", "*END",
                 "*COMMENT", "*TITLE", "*INCLUDE", "*DATABASE_HISTORY", "*INITIAL_")


# Keywords whose data lines are entries of a list (a symmetry plane, an hourglass set, a constraint a line):
# one deleted is an entry less, which nothing tells from intent.
ENTRY_LINES = ("*BOUNDARY_SPH_SYMMETRY_PLANE", "*HOURGLASS", "*BOUNDARY_SPC", "*BOUNDARY_PRESCRIBED", "*LOAD_")


def blank_line(host, rng):
    """A blank line typed between a keyword's cards for spacing (after its keyword line or between two of its
    data lines): LS-DYNA reads it as a card of defaults, and the cards after it one card late. Blocks of repeated
    lines (nodes, particles, sets), text and reader keywords are left alone; a blank line that changes nothing
    read (before an optional card of defaults) is a no-op."""
    if host.deck.fmt != "dyna":
        return
    blocks = [b for b in host.deck.blocks if b.data and not b.name.startswith(READ_AS_LINES)]
    rng.shuffle(blocks)
    for b in blocks:
        k = rng.randrange(len(b.data))
        n = b.data[k]  # the blank line goes above data line n
        lines = host.deck.lines[:n - 1] + [""] + host.deck.lines[n - 1:]
        # Above a blank line (an empty *PART heading), either of the two is the one too many.
        targets = [n, n + 1] if not host.deck.lines[n - 1].strip() else [n]
        yield Plant("blank-line", lines, targets, f"{b.name} at line {b.line}: blank line above data line {n}", "dump",
                    line_map=lambda m, n=n: m if m < n else m + 1)


def deleted_card(host, rng):
    """A data line deleted from a keyword whose cards are read once (a card selected and cut, its `$#` ruler
    left standing): the lines after it are read one card early. Not the block's last data line (that leaves
    a card of defaults, which nothing tells from intent); the blocks of blank_line. The finding belongs on the
    data line that now stands where the deleted one stood."""
    if host.deck.fmt != "dyna":
        return
    blocks = [b for b in host.deck.blocks if len(b.data) >= 2 and not b.name.startswith(READ_AS_LINES + ENTRY_LINES)]
    rng.shuffle(blocks)
    for b in blocks:
        k = rng.randrange(len(b.data) - 1)
        n, after = b.data[k], b.data[k + 1]
        if not host.deck.lines[n - 1].strip() or not host.deck.lines[after - 1].strip():
            continue  # a blank card (an empty heading) deleted, or one left to stand in
        if b.name.startswith("*PART") and k % 2 == 0:
            continue  # a *PART heading: the kind missing-heading
        lines = host.deck.lines[:n - 1] + host.deck.lines[n:]
        yield Plant("deleted-card", lines, [after - 1], f"{b.name} at line {b.line}: data line {n} deleted", "dump",
                    line_map=lambda m, n=n: m if m < n else (None if m == n else m - 1))


def duplicated_line(host, rng):
    """A data line of a keyword whose cards are read once pasted twice (a copy slip): the copy is read as the
    next card and every line after it one card late. The blocks of blank_line; not a *PART's lines (a part
    pasted whole is duplicated-block's). The finding belongs on the copy."""
    if host.deck.fmt != "dyna":
        return
    blocks = [b for b in host.deck.blocks if b.data and not b.name.startswith(READ_AS_LINES)
              and not b.name.startswith("*PART")]
    rng.shuffle(blocks)
    for b in blocks:
        n = b.data[rng.randrange(len(b.data))]
        if not host.deck.lines[n - 1].strip():
            continue  # a blank card pasted twice: blank-line's
        lines = host.deck.lines[:n] + [host.deck.lines[n - 1]] + host.deck.lines[n:]
        yield Plant("duplicated-line", lines, [n + 1], f"{b.name} at line {b.line}: data line {n} pasted twice",
                    "dump", line_map=lambda m, n=n: m if m <= n else m + 1)


def off_plane(host, rng):
    """A particle's node of a 2D deck (IDIM 2 or -2, every node at z = 0) given a z off the plane."""
    if host.deck.fmt != "dyna" or host.deck.long_format:
        return
    idim = [f[2] for fs in host.fields.values() for f in fs if f[0] == "*CONTROL_SPH" and f[1] == "IDIM"]
    if not idim or idim[0] not in (2, -2):
        return
    particles = set()
    for b in host.deck.blocks:
        if b.name == "*ELEMENT_SPH" and not b.suffix:
            for n in b.data[:2000]:
                nid = host.deck.lines[n - 1][:8].strip()
                if nid.isdigit():
                    particles.add(nid)
    cands = []
    for b in host.deck.blocks:
        if b.name != "*NODE" or b.suffix:
            continue
        for n in b.data:
            text = host.deck.lines[n - 1]
            if "," in text or "\t" in text:
                continue
            f = grid_fields(text, DYNA_GRIDS["*NODE"])
            try:
                if f[0] in particles and float(f[3] or 0) == 0.0:
                    cands.append((b, n, f))
            except ValueError:
                continue
    rng.shuffle(cands)
    for b, n, f in cands:
        text = host.deck.lines[n - 1].ljust(56)
        # The y typed again as z (a copy slip), or a unit when y is 0.
        z = f[2] if f[2] and float(f[2]) != 0.0 else "1.0"
        new = (text[:40] + z.rjust(16) + text[56:]).rstrip()
        yield Plant("off-plane", replaced(host.deck.lines, n, new), [n], f"*NODE line {n}: z = {z}", "grid", [n],
                    DYNA_GRIDS["*NODE"])


def digit_shift(host, rng):
    """A card line whose values are all one digit shifted one column right: each value wholly in the next
    field, nothing straddles (`         6         0` typed `          6         0`)."""
    if host.deck.fmt != "dyna":
        return
    skip = ("*TITLE", "*KEYWORD", "*COMMENT", "*PARAMETER", "*INCLUDE")
    lines = [(b, n) for b, n in data_lines_with_fields(host) if not b.name.startswith(skip)
             and not bulk_grid(host.deck, b, n)]
    rng.shuffle(lines)
    for b, n in lines:
        text = host.deck.lines[n - 1]
        words = text.split()
        if len(words) < 2 or "," in text or not all(len(w) == 1 and w.isdigit() for w in words):
            continue
        if any(isinstance(f[2], str) for f in host.fields.get(n, [])):
            continue
        yield Plant("digit-shift", replaced(host.deck.lines, n, " " + text), [n], f"{b.name} line {n}", "dump")


def joined_lines(host, rng):
    """Two data lines of a block made one (the line end between them deleted): the second line's text goes on
    from the first's last character, past its fields or into its blank ones, and the block loses a line. Blocks
    whose cards are read once, and *NODE, *ELEMENT_SPH and *DEFINE_CURVE lines (their first 400)."""
    if host.deck.fmt != "dyna":
        return
    cands = []
    for b in host.deck.blocks:
        if b.name.startswith(READ_AS_LINES) and b.name not in ("*NODE", "*ELEMENT_SPH", "*DEFINE_CURVE"):
            continue
        for n, after in zip(b.data[:400], b.data[1:401]):
            if after == n + 1 and host.deck.lines[n - 1].strip() and host.deck.lines[after - 1].strip():
                cands.append((b, n))
    rng.shuffle(cands)
    for b, n in cands:
        joined = host.deck.lines[n - 1] + host.deck.lines[n]
        if "," in joined or "\t" in joined:
            continue
        lines = host.deck.lines[:n - 1] + [joined] + host.deck.lines[n + 1:]
        yield Plant("joined-lines", lines, [n], f"{b.name} at line {b.line}: data lines {n} and {n + 1} joined", "dump",
                    line_map=lambda m, n=n: m if m <= n else (None if m == n + 1 else m - 1))


def split_line(host, rng):
    """A data line broken in two before one of its values (Enter typed in the blanks before it): the rest of the
    line starts a line of its own at column 1, read as the next card."""
    if host.deck.fmt != "dyna":
        return
    cands = [(b, n) for b, n in data_lines_with_fields(host) if not b.name.startswith(READ_AS_LINES)]
    rng.shuffle(cands)
    for b, n in cands:
        text = host.deck.lines[n - 1]
        words = tokens(text)
        if len(words) < 2 or "," in text or "\t" in text:
            continue
        i = rng.randrange(1, len(words))
        at = rng.randrange(words[i - 1][1], words[i][0] + 1)  # anywhere in the blanks before word i
        lines = host.deck.lines[:n - 1] + [text[:at].rstrip(), text[at:]] + host.deck.lines[n:]
        yield Plant("split-line", lines, [n, n + 1], f"{b.name} at line {b.line}: data line {n} split at column "
                    f"{at + 1}", "dump", line_map=lambda m, n=n: m if m <= n else m + 1)


KINDS = [keyword_typo, radioss_header_typo, shift_right_1, shift_right_3, shift_left_2, width_8, letter_o, decimal_comma,
         missing_id, zero_density, no_control_sph, parameter_typo, radioss_straddle, radioss_shift,
         duplicated_block, tab_in_line, stray_end, missing_heading, lost_asterisk, off_plane, digit_shift, blank_line,
         deleted_card, duplicated_line, joined_lines, split_line]
KIND_NAMES = ["keyword-typo", "radioss-header-typo", "shift-right-1", "shift-right-3", "shift-left-2", "width-8", "letter-O",
              "decimal-comma", "missing-id", "zero-density", "no-control-sph", "parameter-typo",
              "radioss-straddle", "radioss-shift", "duplicated-block", "tab-in-line", "stray-end",
              "missing-heading", "lost-asterisk", "off-plane", "digit-shift", "blank-line",
              "deleted-card", "duplicated-line", "joined-lines", "split-line"]
