#!/usr/bin/env python3
"""Writes grammar/radioss/generated/radioss_layouts.cpp from OpenRadioss' starter CFG files.

Usage: gen_radioss_layouts.py CFG_DIR [--commit SHA] > grammar/radioss/generated/radioss_layouts.cpp
CFG_DIR is hm_cfg_files/config/CFG of an OpenRadioss checkout (the radiossNNNN folders are read).

What is read, per file and per FORMAT(radiossNNNN) block:
- HEADER("/NAME/.../%d", ...): the keyword names. A `%s` segment takes the strings the block compares
  its variable with (`if(set_Type == "NODE")`); a width-limited one (`/MAT/%3s`, the reader's
  prefix match) takes the USER_NAMES the data_hierarchy.cfg files give the file; one compared with
  nothing ends the name (its segments are the deck's own).
- The cards, read as the starter imports them (IO_FLAG of the IMPORT assignment): CARD formats
  ("%10d%20lg%-10s", literal blanks), the title card, ASSIGNs of constants, `if/else` on those
  constants, on fields of earlier cards (kept as a condition the reader evaluates) or neutral
  (only assignments inside), and a trailing CARD_LIST / FREE_CARD_LIST (a repeated group). Anything
  else (CELL_LIST, LIST, FREE_OBJECT_LIST, an `if` on what cannot be known) ends the checked
  cards of the format: its lines stay unchecked.
Per keyword and format version the newest folder's copy wins.

Output: one sorted entry per name, `{"/NAME"sv, "body"sv}`; the body is lines:
  k<flags>                     flags: e engine keyword, i id in the header
  v<N>|t|<cards>              a format read from deck version N on; t: a title line follows the header
Cards are separated by ';': `<r><cond>=<fields>`, r is 1 (once) or r (repeated group) or x (the
rest of the block is not checked); cond is empty or `?FIELD<op>NUMBER` ('&'-joined);
fields `NAME:T:W` with T I (integer), R (real), S (text), B (blank) and W the width.
"""
import argparse
import os
import re
import sys
from collections import defaultdict

ENGINE_KEYS = [
    'RUN', 'TITLE', 'DT', 'TFILE', 'PRINT', 'RFILE', 'VERS', 'ALE', 'DEL', 'VEL', 'BCS', 'BCSR', 'INTER', 'DTIX',
    'IMPL', 'FUNCT', 'FLSEC', 'DYREL', 'KEREL', 'RBODY', 'ANIM', 'DEBUG', 'OUTP', 'ALESU', 'PROC', '@TFIL',
    'DELIN', 'PARIT', 'INIV', 'UPWM', 'MON', 'DT1', 'INCMP', 'TH', 'STOP', 'KILL', 'MADYM', 'SPMD', 'RAD2R',
    'DAMP', 'ATFIL', 'BTFIL', 'CTFIL', 'DTFIL', 'ETFIL', 'FTFIL', 'GTFIL', 'HTFIL', 'ITFIL', 'RERUN', 'FXINP',
    'EIG', 'FVMBA', 'STATE', 'SHVER', 'ABF', 'DTSDE', 'AABF', 'BABF', 'CABF', 'DABF', 'EABF', 'FABF', 'GABF',
    'HABF', 'IABF', 'UPWIN', 'THERM', 'H3D', 'REPOR', 'NEGVO', 'ADYRE', 'DT1TE', 'PERF', 'DYNAI', 'DTTSH',
    'MASS', 'SENS', 'VIPER', 'PROFI']


def engine_first_segment(segment):
    """The engine's REDKEY0: the first five characters of the first segment against KEY0."""
    return segment[:5] in ENGINE_KEYS


# ---------------------------------------------------------------- tokens and statements
TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[A-Za-z_@][A-Za-z0-9_@.]*|-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?|==|!=|<=|>=|&&|\|\||\S')


def strip_comments(text):
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if c == '"':
            j = i + 1
            while j < n and text[j] != '"' and text[j] != '\n':
                j += 1
            out.append(text[i:j + 1])
            i = j + 1
        elif text.startswith('//', i):
            j = text.find('\n', i)
            i = n if j < 0 else j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            i = n if j < 0 else j + 2
        else:
            out.append(c)
            i += 1
    return ''.join(out)


def format_blocks(text):
    """(version, body tokens) of every FORMAT(radiossNNN) block."""
    for m in re.finditer(r'FORMAT\s*\(\s*radioss(\d+)\s*\)\s*\{', text):
        depth, i = 1, m.end()
        while i < len(text) and depth:
            if text[i] == '"':
                i = text.find('"', i + 1)
            elif text[i] == '{':
                depth += 1
            elif text[i] == '}':
                depth -= 1
            i += 1
        yield int(m.group(1)), TOKEN.findall(text[m.end():i - 1])


class Stmt:
    def __init__(self, kind, args=None, body=None, cond=None, other=None):
        self.kind, self.args, self.body, self.cond, self.other = kind, args or [], body or [], cond, other


def parse_block(tokens, i):
    stmts = []
    while i < len(tokens) and tokens[i] != '}':
        s, i = parse_stmt(tokens, i)
        if s:
            stmts.append(s)
    return stmts, i


def parse_body(tokens, i):
    if i < len(tokens) and tokens[i] == '{':
        body, i = parse_block(tokens, i + 1)
        return body, i + 1
    s, i = parse_stmt(tokens, i)
    return ([s] if s else []), i


def balanced(tokens, i):
    """tokens[i] == '(': the tokens inside and the index past ')'."""
    depth, j = 0, i
    while j < len(tokens):
        if tokens[j] == '(':
            depth += 1
        elif tokens[j] == ')':
            depth -= 1
            if depth == 0:
                return tokens[i + 1:j], j + 1
        j += 1
    return tokens[i + 1:], j


def split_args(tokens):
    args, cur, depth = [], [], 0
    for t in tokens:
        if t == ',' and depth == 0:
            args.append(cur)
            cur = []
            continue
        depth += t == '('
        depth -= t == ')'
        cur.append(t)
    if cur:
        args.append(cur)
    return args


def parse_stmt(tokens, i):
    t = tokens[i]
    if t == ';':
        return None, i + 1
    if t == 'if':
        cond, i = balanced(tokens, i + 1)
        body, i = parse_body(tokens, i)
        other = None
        if i < len(tokens) and tokens[i] == 'else':
            other, i = parse_body(tokens, i + 1)
        return Stmt('if', cond=cond, body=body, other=other), i
    if t == '{':
        body, i = parse_block(tokens, i + 1)
        return Stmt('block', body=body), i + 1
    if re.match(r'[A-Za-z_]', t):
        if i + 1 < len(tokens) and tokens[i + 1] == '(':
            inside, i = balanced(tokens, i + 1)
            s = Stmt(t, split_args(inside))
            if i < len(tokens) and tokens[i] == '{':
                s.body, i = parse_block(tokens, i + 1)
                i += 1
            return s, i
        return Stmt(t), i + 1
    return None, i + 1


# ---------------------------------------------------------------- conditions
class Unknown(Exception):
    pass


def literal(tok):
    if tok.startswith('"'):
        return tok[1:-1]
    try:
        return float(tok)
    except ValueError:
        return None


def eval_cond(tokens, env):
    """True/False when every name in `tokens` has a value in env; raises Unknown otherwise."""
    expr = []
    for t in tokens:
        if t == '&&':
            expr.append(' and ')
        elif t == '||':
            expr.append(' or ')
        elif t == '!':
            expr.append(' not ')
        elif t in ('==', '!=', '<', '>', '<=', '>=', '(', ')'):
            expr.append(t)
        elif t.startswith('"') or literal(t) is not None:
            expr.append(repr(literal(t)))
        elif t in ('NONE', 'FALSE'):
            expr.append('0.0')
        elif t == 'TRUE':
            expr.append('1.0')
        elif t in env:
            expr.append(repr(env[t]))
        else:
            raise Unknown(t)
    try:
        return bool(eval(''.join(expr), {}, {}))
    except Exception:
        raise Unknown('expression')


def field_cond(tokens, fields):
    """A condition on numbers of earlier cards: `A == 1 && B > 0` -> 'A=1&B>0', or None."""
    parts, k = [], 0
    while k < len(tokens):
        if k + 2 >= len(tokens):
            return None
        name, op, value = tokens[k], tokens[k + 1], tokens[k + 2]
        number = 0.0 if value in ('NONE', 'FALSE') else literal(value)
        if name not in fields or op not in ('==', '!=', '<', '>', '<=', '>=') or not isinstance(number, float):
            return None
        parts.append(f"{name}{ {'==': '=', '!=': '!'}.get(op, op) }{number:g}")
        k += 3
        if k < len(tokens):
            if tokens[k] != '&&':
                return None
            k += 1
    return '&'.join(parts) if parts else None


def negate(cond):
    """The negation of a single comparison (else branches of one-comparison ifs), or None."""
    if cond is None or '&' in cond:
        return None
    for op, neg in (('<=', '>'), ('>=', '<'), ('=', '!'), ('!', '='), ('<', '>='), ('>', '<=')):
        k = cond.find(op)
        if k > 0:
            return cond[:k] + neg + cond[k + len(op):]
    return None


# ---------------------------------------------------------------- card formats
CELL = re.compile(r'%(-?)(\d*)(lg|lf|le|d|s|f|g|e)')


def parse_card(fmt, names):
    """Fields of a CARD format with its variables, or None when it cannot be cut."""
    fields, pos, k = [], 0, 0
    while pos < len(fmt):
        m = CELL.match(fmt, pos)
        if m:
            if not m.group(2):
                return None
            width = int(m.group(2))
            if k >= len(names):
                return None
            name = names[k]
            k += 1
            if name is None:
                return None
            conv = m.group(3)
            kind = 'I' if conv == 'd' else 'S' if conv == 's' else 'R'
            if name == '_BLANK_' or name.startswith('_'):
                kind, name = 'B', ''
            if name.startswith('PAIR:'):
                fields.append((name[5:] + '_x', kind, width))
                name = name[5:] + '_y'
            fields.append((name, kind, width))
            pos = m.end()
            continue
        if fmt[pos] == ' ':
            run = len(fmt[pos:]) - len(fmt[pos:].lstrip(' '))
            fields.append(('', 'B', run))
            pos += run
            continue
        return None
    return fields if k == len(names) else None


def card_args(stmt):
    if not stmt.args or len(stmt.args[0]) != 1 or not stmt.args[0][0].startswith('"'):
        return None, None
    names = []
    for a in stmt.args[1:]:
        if len(a) == 1:
            names.append(a[0])
        elif a[0] == 'CELL_PAIR' and len(a) == 4:  # two values in cells of the format's width
            names.append('PAIR:' + a[2])
        elif len(a) == 4 and a[1] == '[' and a[3] == ']':  # an array element X[i]
            names.append(a[0])
        else:
            names.append(None)  # CELL_COND, SCALAR_OR_STRING...: not followed
    return stmt.args[0][0][1:-1], names


def is_title_card(stmt):
    fmt, names = card_args(stmt)
    m = re.fullmatch(r'%-?(\d+)s', fmt or '')
    return m is not None and len(names) == 1 and int(m.group(1)) >= 40


NEUTRAL = {'COMMENT', 'ASSIGN', 'SUBOBJECTS', 'SUBOBJECT', 'CARD_PREREAD', 'HEADER', 'block'}


def neutral(stmts):
    for s in stmts:
        if s.kind == 'if':
            if not neutral(s.body) or not neutral(s.other or []):
                return False
        elif s.kind == 'block':
            if not neutral(s.body):
                return False
        elif s.kind not in NEUTRAL:
            return False
    return True


class Linear:
    """The cards of one FORMAT block as the starter imports them."""

    def __init__(self):
        self.cards = []      # (repeat, cond, fields)
        self.title = False
        self.stopped = False
        self.fields = set()  # numbers of cards read once so far (conditions may use them)
        self.allow_title = True
        self.subobjects = False  # cards read through other CFG objects: the end is not known

    def stop(self):
        if not self.stopped:
            self.cards.append(('x', '', []))
            self.stopped = True

    def run(self, stmts, env, cond='', last=True):
        for idx, s in enumerate(stmts):
            if self.stopped:
                return
            rest_neutral = neutral(stmts[idx + 1:])
            self.step(s, env, cond, last and rest_neutral)

    def step(self, s, env, cond, last):
        if s.kind == 'ASSIGN':
            if len(s.args) >= 2 and len(s.args[0]) == 1:
                mode = s.args[2][0] if len(s.args) > 2 and s.args[2] else ''
                value = literal(s.args[1][0]) if len(s.args[1]) == 1 else None
                if mode != 'EXPORT':
                    if value is None:
                        env.pop(s.args[0][0], None)
                    else:
                        env[s.args[0][0]] = value
            return
        if s.kind in ('SUBOBJECTS', 'SUBOBJECT'):
            self.subobjects = True
            return
        if s.kind in NEUTRAL:
            return
        if s.kind == 'block':
            return self.run(s.body, env, cond, last)
        if s.kind == 'CARD':
            fmt, names = card_args(s)
            if fmt is None:
                return self.stop()
            if not self.cards and not cond and self.allow_title and not self.title and is_title_card(s):
                self.title = True
                return
            fields = parse_card(fmt, names)
            if fields is None:
                return self.stop()
            self.cards.append(('1', cond, fields))
            if not cond:
                self.fields.update(n for n, k, w in fields if k in 'IR' and n)
            return
        if s.kind == 'FREE_CARD' and len(s.args) >= 2:
            # FREE_CARD(flag, format, ...): a card the starter reads when the line is there (the flag
            # says whether it was); checked as a card when it comes last, nothing after it to shift.
            fmt, names = card_args(Stmt('CARD', s.args[1:]))
            names = ['ID' if n == '_ID_' else n for n in names or []]  # the /FAIL's own id card
            fields = parse_card(fmt, names) if fmt is not None and last else None
            if fields is None:
                return self.stop()
            self.cards.append(('1', cond, fields))
            return
        if s.kind == 'BLANK':
            self.cards.append(('1', cond, [('', 'B', 100)]))
            return
        if s.kind == 'if':
            try:
                taken = eval_cond(s.cond, env)
                branch, other = (s.body, s.other or []) if taken else (s.other or [], s.body)
                # The export branches write the header and the title, the import one reads neither
                # (/MAT/%3s, mat116.cfg): the title line is read all the same.
                if self.allow_title and not self.cards and not self.title and \
                        not titled_header(branch) and titled_header(other):
                    self.title = True
                return self.run(branch, env, cond, last)
            except Unknown:
                pass
            if neutral(s.body) and neutral(s.other or []):
                return
            merged = self.merge(s, env, cond)
            if merged is not None:
                self.cards += merged
                return
            # A condition on numbers of earlier cards: each branch's plain cards under it.
            yes = field_cond(s.cond, self.fields)
            no = negate(yes) if s.other else ''
            if yes and no is not None and not cond and plain(s.body) and plain(s.other or []):
                self.run(s.body, env, '?' + yes, last)
                if s.other:
                    self.run(s.other, env, '?' + no, last)
                return
            return self.stop()
        if s.kind in ('CARD_LIST', 'FREE_CARD_LIST') and last and not cond:
            cards = [c for c in s.body if c.kind == 'CARD']
            if cards and all(c.kind in ('CARD', 'COMMENT') for c in s.body):
                cut = []
                for c in cards:
                    fmt, names = card_args(c)
                    fields = parse_card(fmt, names) if fmt is not None else None
                    if fields is None:
                        return self.stop()
                    cut.append(fields)
                for fields in cut:
                    self.cards.append(('r', '', fields))
                self.stopped = True  # nothing may follow a repeated group
                return
        return self.stop()

    def merge(self, s, env, cond):
        """Both branches of an `if` that cannot be decided, when they read the same cards but for
        trailing fields or blank cells: one list of cards; None otherwise."""
        branches = []
        for stmts in (s.body, s.other or []):
            sub = Linear()
            sub.fields = set(self.fields)
            sub.allow_title = False  # no title card inside a branch
            sub.run(stmts, dict(env), cond, False)
            if sub.stopped or any(r != '1' for r, _, _ in sub.cards):
                return None
            branches.append(sub.cards)
        a, b = branches
        if len(a) != len(b):
            return None
        out = []
        for (_, ca, fa), (_, cb, fb) in zip(a, b):
            fields = compatible(fa, fb)
            if fields is None or ca != cb:
                return None
            out.append(('1', ca, fields))
        return out


def compatible(a, b):
    """One card for two branches' cards: same cells where both have one (a blank cell takes the
    other's field), the longer card's extra fields read as optional trailing values."""
    out = []
    for k in range(max(len(a), len(b))):
        if k >= len(a) or k >= len(b):
            out.append((a if k < len(a) else b)[k])
            continue
        (na, ka, wa), (nb, kb, wb) = a[k], b[k]
        if wa != wb:
            return None
        if ka == kb:
            out.append(a[k] if na == nb else (na + '/' + nb, ka, wa))
        elif ka == 'B':
            out.append(b[k])
        elif kb == 'B':
            out.append(a[k])
        else:
            return None
    return out


def titled_header(stmts):
    """A HEADER followed by a title card, in these statements or an `if` among them."""
    for k, s in enumerate(stmts):
        if s.kind == 'HEADER' and k + 1 < len(stmts) and stmts[k + 1].kind == 'CARD' and is_title_card(stmts[k + 1]):
            return True
        if s.kind == 'if' and (titled_header(s.body) or titled_header(s.other or [])):
            return True
    return False


def plain(stmts):
    """Statements of only cards and neutral ones (a conditional card's branch)."""
    return all(s.kind in NEUTRAL or s.kind == 'CARD' for s in stmts)


# ---------------------------------------------------------------- names
def header_calls(stmts):
    for s in stmts:
        if s.kind == 'HEADER' and s.args and len(s.args[0]) == 1 and s.args[0][0].startswith('"'):
            yield s
        for sub in (s.body, s.other or []):
            yield from header_calls(sub)


def comparisons(tokens):
    """var -> strings it is compared with (`var == "X"`) anywhere in the block."""
    out = defaultdict(set)
    for k in range(len(tokens) - 2):
        if tokens[k + 1] in ('==', '!=') and tokens[k + 2].startswith('"') and re.match(r'[A-Za-z_]', tokens[k]):
            value = tokens[k + 2][1:-1].strip()
            if value:
                out[tokens[k]].add(value)
    return out


def header_names(stmt, compared, user_names):
    """(name, has_id) of one HEADER call; several when a segment takes a set of strings."""
    fmt = stmt.args[0][0][1:-1]
    variables = [a[0] if len(a) == 1 else '?' for a in stmt.args[1:]]
    if not fmt.startswith('/'):
        return []
    names, k, has_id, shared = [''], 0, False, False
    wildcard = []
    segments = fmt[1:].rstrip('/').split('/')
    if '' in segments:
        return []
    for segment in segments:
        m = re.fullmatch(r'%(-?)(\d*)(s|d)', segment)
        if not m:
            if '%' in segment:
                return []  # a prefix match inside a segment (/MAT/PLAS_%5s): other HEADERs name it
            names = [n + '/' + segment for n in names]
            continue
        var = variables[k] if k < len(variables) else '?'
        k += 1
        if m.group(3) == 'd' or var in ('_ID_', 'TITLE'):
            has_id = has_id or m.group(3) == 'd'
            break
        if m.group(2):  # a prefix match: the names the hierarchy gives the file
            if not user_names:
                return []  # the export branch's HEADERs name the keyword
            names = [n + '/' + u for n in names for u in sorted(user_names)]
            break
        values = sorted(v for v in compared.get(var, ()) if re.fullmatch(r'[A-Z0-9_\-+]+', v))
        if not values and user_names:
            # The names the hierarchy gives the file, below this header's literal path
            # (USER_NAMES of /FAIL/JOHNSON: FAIL_JOHNSON, JOHNSON).
            path = '_'.join(n for n in names[0].split('/') if n)
            values = sorted({u[len(path) + 1:] if u.startswith(path + '_') else u for u in user_names
                             if '_' not in (u[len(path) + 1:] if u.startswith(path + '_') else u)})
            values = [v for v in values if v]
        if not values:
            wildcard.append(True)
            # The deck's own segment: when literal segments follow it, several files share the
            # name (/PARAMETER/%s/REAL/%d), so the name says nothing of the layout.
            later = segments[segments.index(segment) + 1:]
            shared = any('%' not in later_segment for later_segment in later)
            break
        names = [n + '/' + v for n in names for v in values]
    return [(n, has_id, shared, bool(wildcard)) for n in names if n]


def hierarchy_user_names(cfg):
    """file path (relative to its version folder) -> USER_NAMES of its HIERARCHY entries."""
    out = defaultdict(set)
    for folder in os.listdir(cfg):
        path = os.path.join(cfg, folder, 'data_hierarchy.cfg')
        if not folder.startswith('radioss') or not os.path.exists(path):
            continue
        text = strip_comments(open(path, encoding='latin-1').read())
        for m in re.finditer(r'FILE\s*=\s*"([^"]+)"\s*;(?:(?!HIERARCHY|FILE\s*=).)*?USER_NAMES\s*=\s*\(([^)]*)\)',
                             text, re.S):
            for u in m.group(2).split(','):
                u = u.strip()
                if re.fullmatch(r'[A-Z0-9_\-+]+', u):
                    out[m.group(1)].add(u)
        for m in re.finditer(r'USER_NAMES\s*=\s*\(([^)]*)\)\s*;(?:(?!HIERARCHY|USER_NAMES).)*?FILE\s*=\s*"([^"]+)"',
                             text, re.S):
            for u in m.group(1).split(','):
                u = u.strip()
                if re.fullmatch(r'[A-Z0-9_\-+]+', u):
                    out[m.group(2)].add(u)
    return out


# ---------------------------------------------------------------- id links
# The kind of id an ATTRIBUTES field names (its VALUE or ARRAY type, and SUBTYPES for sets):
# F function or table, S sensor, Y skew or frame, G node group, U surface, M material, P property,
# C part.
LINK_TYPES = {'FUNCT': 'F', 'CURVE': 'F', 'FUNC': 'F', 'SENSOR': 'S', 'SYSTEM': 'Y', 'MAT': 'M',
              'MATERIAL': 'M', 'PROP': 'P', 'COMPONENT': 'C'}
ATTRIBUTE = re.compile(r'\b(\w+)\s*=\s*(?:VALUE|ARRAY\s*\[[^\]]*\])\s*\(\s*(\w+)\s*,[^;{]*?\)\s*(?:;|(\{[^}]*\}))')


def attribute_links(text):
    """field -> link kind of the file's ATTRIBUTES blocks."""
    out = {}
    for m in re.finditer(r'ATTRIBUTES\s*\([^)]*\)\s*\{', text):
        depth, i = 1, m.end()
        while i < len(text) and depth:
            depth += text[i] == '{'
            depth -= text[i] == '}'
            i += 1
        for a in ATTRIBUTE.finditer(text[m.end():i]):
            name, kind, extra = a.group(1), a.group(2), a.group(3) or ''
            if kind in LINK_TYPES:
                out[name] = LINK_TYPES[kind]
            elif kind == 'SETS':
                sub = re.search(r'SUBTYPES\s*=\s*\(([^)]*)\)', extra)
                subtypes = [t.strip() for t in sub.group(1).split(',')] if sub else []
                if subtypes == ['/SETS/GRNOD']:
                    out[name] = 'G'
                elif subtypes and all(t in ('/SETS/SURF', '/SETS/SURF_IDPOOL') for t in subtypes):
                    out[name] = 'U'
    return out


def with_links(cards, links):
    out = []
    for repeat, cond, fields in cards:
        out.append((repeat, cond, [(n, k, w, links.get(n, '') if k == 'I' else '') for n, k, w in fields]))
    return out


# ---------------------------------------------------------------- writing
def encode_card(card):
    repeat, cond, fields = card
    body = ','.join(f"{n}:{k}:{w}" + (f":{link}" if link else '') for n, k, w, link in fields)
    return f"{repeat}{cond}={body}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('cfg')
    ap.add_argument('--commit', default='unknown')
    opts = ap.parse_args()
    folders = sorted((f for f in os.listdir(opts.cfg) if re.fullmatch(r'radioss\d+', f)),
                     key=lambda f: int(f[7:]))
    user_names = hierarchy_user_names(opts.cfg)
    # name -> {'engine', 'id', formats: {version: (folder_rank, title, cards)}}
    table = {}
    for rank, folder in enumerate(folders):
        base = os.path.join(opts.cfg, folder)
        for root, _, files in os.walk(base):
            for f in sorted(files):
                if not f.endswith('.cfg') or f in ('data_hierarchy.cfg', 'hm_data_hierarchy.cfg'):
                    continue
                rel = os.path.relpath(os.path.join(root, f), base)
                text = strip_comments(open(os.path.join(root, f), encoding='latin-1').read())
                engine_file = f.startswith('eng_')
                links = attribute_links(text)
                for version, tokens in format_blocks(text):
                    try:
                        stmts, _ = parse_block(tokens, 0)
                    except (IndexError, RecursionError):
                        continue
                    compared = comparisons(tokens)
                    names = []
                    for h in header_calls(stmts):
                        names += header_names(h, compared, user_names.get(rel, set()))
                    if not names:
                        continue
                    lin = Linear()
                    env = {}
                    lin.run(stmts, env)
                    if not lin.cards or lin.subobjects:
                        lin.stop()
                    known = sum(1 for c in lin.cards if c[0] != 'x')
                    for name, has_id, shared, wild in names:
                        first = name.split('/')[1]
                        engine = engine_first_segment(first) and (engine_file or f.startswith(('anim_', 'state_')))
                        e = table.setdefault(name, {'engine': engine, 'id': False, 'formats': {}, 'shared': False})
                        e['shared'] = e['shared'] or shared
                        e['wild'] = e.get('wild', False) or wild
                        e['id'] = e['id'] or has_id
                        e['engine'] = e['engine'] and engine
                        old = e['formats'].get(version)
                        if old is None or old[0] <= (known, rank):
                            e['formats'][version] = ((known, rank), lin.title, with_links(lin.cards, links))
    out = sys.stdout
    out.write('// GENERATED by scripts/gen_radioss_layouts.py from OpenRadioss hm_cfg_files/config/CFG/radioss*; '
              'do not edit.\n')
    out.write(f'// Source: github.com/OpenRadioss/OpenRadioss at {opts.commit} (the starter\'s CFG files).\n')
    out.write('// License of the CFG files: "CFG Files and Library", Copyright (C) Siemens (SISW), limited permission\n'
              '// to use and modify CFG in connection with OpenRadioss (their header); OpenRadioss itself is AGPL-3.0.\n'
              '// This table holds facts read from them: keyword names, field names, columns and types.\n'
              '// Format of the entries: scripts/gen_radioss_layouts.py; notes: grammar/radioss/generated/README.md.\n')
    out.write('#include "grammar/radioss/generated_layouts.hpp"\n\nnamespace sphdeck::grammar::radioss::generated {\n\n')
    out.write('namespace {\nusing namespace std::string_view_literals;\nconstexpr LayoutEntry kLayouts[] = {\n')
    for name in sorted(table):
        e = table[name]
        lines = ['k' + ('e' if e['engine'] else '') + ('i' if e['id'] else '') + ('w' if e.get('wild') else '')]
        for version in sorted(e['formats'], reverse=True):
            _, title, cards = e['formats'][version]
            if e['shared']:
                title, cards = False, [('x', '', [])]
            lines.append(f"v{version}|{'t' if title else ''}|" + ';'.join(encode_card(c) for c in cards))
        body = '\\n'.join(lines).replace('"', '\\"')
        out.write(f'    {{"{name}"sv, "{body}"sv}},\n')
    out.write('};\n}  // namespace\n\nstd::span<const LayoutEntry> layouts() { return kLayouts; }\n\n'
              '}  // namespace sphdeck::grammar::radioss::generated\n')
    sys.stderr.write(f"{len(table)} keywords\n")


if __name__ == '__main__':
    main()
