#!/usr/bin/env python3
"""Keeps unity batches free of names that one file could lend, silently, to another file of its batch.

A unity build (cmake/speed_up.cmake) compiles a target's .cpp files in batches: each batch is one
generated file that #includes them in turn, so whatever a file declares at namespace scope stays in
sight of the files after it. A clash is a compile error at best ("redefinition of"); at worst a later
file's unqualified name finds the earlier file's helper instead of a header's: rules_preview.cpp's
file-local `max_listed = 20` once replaced particle_groups.hpp's 5 in rules_references.cpp and changed a
finding. A file lends the names it declares at namespace scope that no project header declares there:
helpers of anonymous namespaces, `static` functions, constants, types, aliases, using-declarations,
using-directives (where they would add overloads to a later file's own function), `using enum`, macros.
A later file borrows one when it, or a header it is the first of its batch to include, spells that name
in the lender's namespace or one nested in it (or qualified by the namespace's name).

--group SOURCE...  prints batches for a target's sources (cmake/speed_up.cmake forms them at configure
                   time): no file shares a batch with one it lends to or borrows from, and the files that
                   include the same costly third-party headers (CLI11, nlohmann-json...) go side by side.
--build TREE       checks the batches CMake wrote (CMakeFiles/*/Unity/*.cxx that compile_commands.json
                   names; the ctest unity-clashes): exit 0 when none clashes, 1 with the list, 77 when
                   the tree has no unity batches (skipped). A clash there means a helper was added since
                   the last configure: re-run cmake (it forms the batches around it) or rename it.

The parse is a tokenizer, not a compiler: it errs towards reporting (a later file's own local variable
of a lent name counts as a borrow), which only makes a batch smaller.
"""
import argparse
import functools
import glob
import json
import os
import pickle
import re
import sys

IDENT = re.compile(r"[A-Za-z_]\w*")
IDENT_START = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_")  # a token that starts so is one
TOKEN = re.compile(r'R"(?P<d>[^(\s]*)\((?:.|\n)*?\)(?P=d)"|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\''
                   r"|//[^\n]*|/\*(?:.|\n)*?\*/|::|->|[A-Za-z_]\w*|\d[\w.']*|\S")
KEYWORDS = {"const", "constexpr", "consteval", "constinit", "static", "inline", "extern", "thread_local",
            "volatile", "mutable", "unsigned", "signed", "long", "short", "int", "char", "bool", "double",
            "float", "void", "auto", "typename", "template", "struct", "class", "union", "enum", "using",
            "namespace", "typedef", "operator", "noexcept", "decltype", "std", "static_assert", "friend",
            "explicit", "virtual", "override", "final", "return", "requires", "concept"}


def preprocess(text):
    """The macro names the text #defines and still has defined at its end, and the text without its
    preprocessor lines (continuations joined)."""
    defined = {}
    kept = []
    includes = []
    system_includes = []
    lines = text.replace("\\\n", " ").split("\n")
    for line in lines:
        stripped = line.strip()
        if stripped.startswith("#"):
            inc = re.match(r'#\s*include\s+"([^"]+)"', stripped)
            if inc:
                includes.append(inc.group(1))
            system = re.match(r"#\s*include\s+<([^>]+)>", stripped)
            if system:
                system_includes.append(system.group(1))
            m = re.match(r"#\s*(define|undef)\s+(\w+)", stripped)
            if m and m.group(1) == "define":
                defined[m.group(2)] = stripped
            elif m:
                defined.pop(m.group(2), None)
            kept.append("")
        else:
            kept.append(line)
    return defined, includes, system_includes, "\n".join(kept)


def tokens(text):
    out = []
    append = out.append
    for m in TOKEN.finditer(text):
        t = m.group()
        c = t[0]
        if c == "/" and t[1:2] in ("/", "*"):  # a comment
            continue
        if c == '"' or c == "'" or (c == "R" and t[1:2] == '"'):  # a string or character literal
            append('"')
            continue
        append(t)
    return out


def declared_name(stmt):
    """(kind, name) that a namespace-scope statement declares, or None (a definition of a qualified
    name, an operator, a static_assert...)."""
    toks = without_template_head(list(stmt))
    if not toks or toks[0] in ("static_assert", "friend"):
        return None
    if toks[0] == "using":
        if len(toks) > 1 and toks[1] == "namespace":
            return ("using-directive", " ".join(toks))
        if len(toks) > 1 and toks[1] == "enum":
            return ("using-enum", toks[-1])
        if len(toks) > 2 and toks[2] == "=":
            return ("alias", toks[1])
        return ("using", toks[-1] if IDENT.fullmatch(toks[-1]) else None)
    if toks[0] == "typedef":
        names = [t for t in toks if IDENT.fullmatch(t) and t not in KEYWORDS]
        return ("alias", names[-1]) if names else None
    for i, t in enumerate(toks):
        if t in ("struct", "class", "union", "enum"):
            j = i + 1
            while j < len(toks) and toks[j] in ("class", "struct", "[", "]"):
                j += 1
            if j < len(toks) and IDENT.fullmatch(toks[j]) and (j + 1 == len(toks) or toks[j + 1] in (":", "{", ";", "final")):
                if j + 1 < len(toks) and toks[j + 1] == ";" or j + 1 == len(toks):
                    return None  # a forward declaration or an elaborated type: declares nothing new here
                return ("type", toks[j])
            break
    # A function or a variable: the name before the first top-level (, =, [, { or the end.
    depth = 0
    prev = None
    for i, t in enumerate(toks):
        if t == "<":
            depth += 1
        elif t == ">" and depth:
            depth -= 1
        elif depth == 0 and t in ("(", "=", "[", "{", ";", ","):
            break
        prev = i
    else:
        prev = len(toks) - 1
    if prev is None or not IDENT.fullmatch(toks[prev]) or toks[prev] in KEYWORDS:
        return None
    if prev > 0 and toks[prev - 1] in ("::", "operator", "~"):
        return None  # Foo::bar (a definition of a declared name) or an operator
    kind = "function" if prev + 1 < len(toks) and toks[prev + 1] == "(" else "variable"
    if kind == "function" and re.fullmatch(r"[A-Z][A-Z0-9_]+", toks[prev]):
        return None  # a macro's use (TEST_CASE("...") {), not a declaration
    return (kind, toks[prev])


def more_declarators(toks):
    """The names after the first of `double a = 1, b = 2;`: each identifier that follows a comma at
    the top level (outside (), <>, {} and [])."""
    names, depth = [], 0
    for k, t in enumerate(toks):
        if t in "(<{[":
            depth += 1
        elif t in ")>}]":
            depth -= 1
        elif t == "," and depth == 0 and k + 1 < len(toks) and IDENT.fullmatch(toks[k + 1]):
            names.append(toks[k + 1])
    return names


def without_template_head(toks):
    """The tokens after a leading `template <...>` (any number of them)."""
    while toks and toks[0] == "template":
        depth, i = 0, 1
        while i < len(toks):
            depth += toks[i] == "<"
            depth -= toks[i] == ">"
            i += 1
            if depth == 0:
                break
        toks = toks[i:]
    return toks


def is_function_head(head):
    """True when the tokens before a namespace-scope `{` open a function body: a ( before any =, and
    no class, struct, union or enum in front (after a `template <class F>`, whose `class` is no class)."""
    head = without_template_head(head)
    if not head or any(t in ("struct", "class", "union", "enum") for t in head[:3]):
        return False
    for t in head:
        if t == "=":
            return False
        if t == "(":
            return True
    return False


def declarations(toks, spelled=None):
    """Every namespace-scope declaration of the token list: (namespace path, anonymous?, static?, kind,
    name, statement text). `spelled` (a dict), when given, gets the names spelled unqualified in each
    namespace (members after . or -> left out)."""
    found = []
    # The namespaces open at this point, ("ns", name) each, and the braces open inside the innermost
    # (a function body, a class body, an initializer): only namespace scope declares what a file lends.
    stack = []
    blocks = 0
    path = ""  # ns_path(stack), kept as the stack changes
    stmt = []
    i = 0
    n = len(toks)
    while i < n:
        t = toks[i]
        if spelled is not None and t[0] in IDENT_START and not (i and toks[i - 1] in (".", "->", "::")):
            names = spelled.get(path)
            if names is None:
                names = spelled[path] = set()
            names.add(t)
        if blocks:
            if t == "{":
                blocks += 1
            elif t == "}":
                blocks -= 1
                if not blocks and is_function_head(stmt[: stmt.index("{")]):
                    # a function body ends the statement; a class body or an initializer runs to its ;
                    record(found, stack, stmt)
                    stmt = []
            i += 1
            continue
        if t == "namespace" and not stmt:
            j = i + 1
            name = []
            while j < n and toks[j] not in ("{", "=", ";"):
                name.append(toks[j])
                j += 1
            if j < n and toks[j] == "{":
                stack.append(("ns", "".join(name)))
                path = ns_path(stack)
                i = j + 1
                continue
            stmt = toks[i:j]
            i = j
            continue
        if t == "extern" and i + 2 < n and toks[i + 1] == '"' and toks[i + 2] == "{":
            stack.append(("ns", None))  # extern "C" { ... }: transparent
            i += 3
            continue
        if t == "}" and not stmt:
            if stack:
                stack.pop()
                path = ns_path(stack)
            i += 1
            continue
        if t == ";":
            if stmt:
                record(found, stack, stmt)
            stmt = []
            i += 1
            continue
        if t == "{":
            blocks = 1
            stmt = stmt + ["{"]
            i += 1
            continue
        stmt.append(t)
        i += 1
    return found


def record(found, stack, stmt):
    head = stmt[: stmt.index("{") + 1] if "{" in stmt else stmt
    if head and head[0] == "namespace":  # namespace alias
        if len(head) >= 3 and head[2] == "=":
            found.append((ns_path(stack), in_anon(stack), False, "alias", head[1], " ".join(head)))
        return
    decl = declared_name(head)
    if decl is None or decl[1] is None:
        return
    kind, name = decl
    found.append((ns_path(stack), in_anon(stack), "static" in head, kind, name, " ".join(head)))
    if kind == "variable":
        for more in more_declarators(head):
            found.append((ns_path(stack), in_anon(stack), "static" in head, kind, more, " ".join(head)))


def ns_path(stack):
    return "::".join(n for kind, n in stack if kind == "ns" and n)


def in_anon(stack):
    return any(kind == "ns" and n == "" for kind, n in stack)


def identifiers(toks):
    """The names a file spells unqualified, and (qualifier, name) for those after `::` (members after
    . or -> left out)."""
    plain, qualified = set(), set()
    for k, t in enumerate(toks):
        if t[0] not in IDENT_START or (k and toks[k - 1] in (".", "->")):
            continue
        if k > 1 and toks[k - 1] == "::":
            qualified.add((toks[k - 2], t))
        else:
            plain.add(t)
    return plain, qualified


class Source:
    def __init__(self, path):
        text = ""
        if os.path.exists(path):  # a generated source not yet written: checked once the build made it
            with open(path, encoding="utf-8", errors="replace") as f:
                text = f.read()
        self.macros, self.includes, self.system_includes, code = preprocess(text)
        self.toks = tokens(code)
        self.spelled_in = {}
        self.decls = declarations(self.toks, self.spelled_in)
        self.idents, self.qualified = identifiers(self.toks)
        self.joined = " ".join(self.toks)


# Parsed files by path, each with the (mtime, size) it was parsed at. With --cache it is kept in a file
# between runs: CMake runs this script at every configure (once for all targets, --group-targets), and a
# re-configure then parses only the files changed since (a configure runs on one core, before any compile).
PARSED = {}


def parsed(path):
    try:
        st = os.stat(path)
        stamp = (st.st_mtime_ns, st.st_size)
    except OSError:
        stamp = None  # a generated source not yet written: parsed as empty, never kept
    hit = PARSED.get(path)
    if hit is not None and stamp is not None and hit[0] == stamp:
        return hit[1]
    src = Source(path)
    if stamp is not None:
        PARSED[path] = (stamp, src)
    return src


def load_cache(path):
    try:
        with open(path, "rb") as f:
            PARSED.update(pickle.load(f))
    except (OSError, EOFError, pickle.UnpicklingError, AttributeError, ValueError, TypeError):
        pass  # no cache yet, or one written by another version of this script: parse again


def save_cache(path):
    tmp = f"{path}.{os.getpid()}"
    with open(tmp, "wb") as f:
        pickle.dump(PARSED, f, protocol=pickle.HIGHEST_PROTOCOL)
    os.replace(tmp, path)


def project_hpp_files(root):
    """The .hpp files under root, build trees and hidden folders left out (as glob's `**` leaves hidden
    ones), in glob's order; a path with "/build" in it counts as a build tree's."""
    found = []
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and not d.startswith("build"))
        found += [os.path.join(folder, f) for f in files if f.endswith(".hpp") and not f.startswith(".")]
    return sorted(p for p in found if "/build" not in p[len(root):])


class Headers:
    """What the project's headers declare at namespace scope: (namespace, name) pairs, the functions by
    namespace, the namespaces that declare each name, and the enumerators of each enum."""

    def __init__(self, root):
        self.names, self.functions, self.where, self.enumerators = set(), {}, {}, {}
        for path in project_hpp_files(root):
            src = parsed(path)
            for ns, _anon, _static, kind, name, _text in src.decls:
                self.names.add((ns, name))
                self.where.setdefault(name, set()).add(ns)
                if kind == "function":
                    self.functions.setdefault(ns, set()).add(name)
            text = " ".join(src.toks)
            for m in re.finditer(r"\benum (?:class |struct )?(\w+)(?: : [\w: ]+)? \{([^}]*)\}", text):
                names = re.findall(r"(?:^|, )\s*(\w+)", m.group(2).strip())
                self.enumerators.setdefault(m.group(1), set()).update(names)

    def same_entity(self, text, aliases=None):
        """True for `using A::B::N;` where the headers declare N in one namespace only, ending in A::B:
        a later file that spells N can mean nothing else. `aliases`: the file's namespace aliases
        (`namespace rad = grammar::radioss;` makes `using rad::CardSpec;` grammar::radioss's)."""
        parts = [t for t in text.split() if t not in ("using", "::", ";")]
        if len(parts) < 2:
            return False
        if aliases and parts[0] in aliases:
            parts = aliases[parts[0]] + parts[1:]
        qualifier, name = "::".join(parts[:-1]), parts[-1]
        where = self.where.get(name, set())
        return len(where) == 1 and (next(iter(where)) + "::").endswith(qualifier + "::")


def directive_functions(text, functions):
    """The header functions a `using namespace X;` at `scope` brings into sight: those of the namespaces
    that X names from there."""
    target = text.replace(" ", "")[len("usingnamespace"):]
    found = set()
    for ns, names in functions.items():
        if ns == target or ns.endswith("::" + target) or ns.startswith(target + "::"):
            found |= names
    return found


def lent_names(src, headers):
    """The names a file leaves in sight of the files after it, with what declares them."""
    lent = {}
    aliases = {name: [t for t in text.split("=", 1)[1].split() if t not in ("::", ";")]
               for _ns, _anon, _static, kind, name, text in src.decls
               if kind == "alias" and text.startswith("namespace ")}
    for ns, anon, static, kind, name, text in src.decls:
        if kind == "using-directive":
            lent[text] = (kind, ns, text)
            continue
        if kind == "using-enum":  # its enumerators
            for e in headers.enumerators.get(name, ()):
                lent.setdefault(e, (kind, ns, text))
            continue
        if kind == "using" and headers.same_entity(text, aliases):
            continue
        if kind == "function" and name == "main" and not ns:
            continue  # found only where nothing else of that name is
        if not anon and not static and (ns, name) in headers.names and kind not in ("using", "alias"):
            continue  # the definition of what a header declares: the same entity everywhere
        lent.setdefault(name, (kind, ns, text))
    for name, text in src.macros.items():
        if not re.search(r"_(HPP|H)_?$", name) and not name.startswith("DOCTEST_CONFIG"):
            lent.setdefault(name, ("macro", "", text))
    return lent


@functools.lru_cache(maxsize=None)
def resolved_include(folder, root, inc):
    """The file `#include "inc"` names from a file in `folder`: beside it, else under root; None."""
    for base in (folder, root):
        cand = os.path.normpath(os.path.join(base, inc))
        if os.path.isfile(cand):
            return cand
    return None


def project_headers(src_path, cache, root, seen):
    """The project headers a file includes, transitively, in first-inclusion order, those in `seen`
    left out (a header is parsed once a batch: where it is first included)."""
    order = []

    def visit(path):
        if path not in cache:
            cache[path] = parsed(path)
        for inc in cache[path].includes:
            cand = resolved_include(os.path.dirname(path), root, inc)
            if cand is not None and cand not in seen:
                seen.add(cand)
                visit(cand)
                order.append(cand)

    visit(src_path)
    return order


def parse_batch(path):
    with open(path, encoding="utf-8") as f:
        return re.findall(r'#include\s+"([^"]+)"', f.read())


def inside(where, ns):
    """True when code in namespace `where` looks names up in `ns` too: `ns` is `where` or encloses it."""
    return not ns or where == ns or where.startswith(ns + "::")


def merge_spelled(sources):
    """The names spelled in each namespace over several files, and their qualified names."""
    spelled, qualified = {}, set()
    for src in sources:
        for where, names in src.spelled_in.items():
            spelled.setdefault(where, set()).update(names)
        qualified |= src.qualified
    return spelled, qualified


def lends(src_a, lent, src_b, spelled, qualified, headers):
    """The names of `lent` (src_a's) that src_b, or the headers it brings, would see: (name, kind, ns, text)."""
    found = []
    directives_b = {text for _ns, _a, _s, kind, _n, text in src_b.decls if kind == "using-directive"}
    own_functions = {n for n_ns, _a, _s, k, n, _t in src_b.decls
                     if k == "function" and (n_ns, n) not in headers.names}  # not a header's, defined here
    for name, (kind, ns, text) in sorted(lent.items()):
        if kind == "using-directive":
            # Its names join the lookup at the directive's scope: silent only where they add
            # overloads to a function of the later file's own of the same name.
            if name in directives_b:
                continue
            for f in sorted(directive_functions(text, headers.functions) & own_functions):
                found.append((f, kind, ns, text))
            continue
        if kind == "alias" and text.startswith("namespace "):
            # A namespace alias is found only before `::` (or in a using-directive): a later file's own
            # variable of that name hides it, and its own alias of another namespace would not compile.
            if not any(q == name for q, _n in qualified) and f"namespace {name} " not in src_b.joined + " ":
                continue
        last = ns.split("::")[-1]
        if not any(name in names and inside(where, ns) for where, names in spelled.items()) \
                and (last, name) not in qualified:
            continue
        if kind in ("using", "alias") and text in src_b.joined:
            continue  # the same using-declaration or alias: the same entity
        found.append((name, kind, ns, text))
    return found


def check(build, root):
    """Every clash in the batches CMake wrote under `build`: exit status and report lines."""
    batches = sorted(glob.glob(os.path.join(build, "**", "Unity", "unity_*.cxx"), recursive=True))
    commands = os.path.join(build, "compile_commands.json")
    if os.path.exists(commands):  # what the build compiles now, not the batches of an earlier configure
        with open(commands, encoding="utf-8") as f:
            compiled = {os.path.normpath(entry["file"]) for entry in json.load(f)}
        batches = [b for b in batches if os.path.normpath(b) in compiled]
    if not batches:
        print(f"no unity batches under {build}: skipped (a build without SPHDECK_UNITY_BUILD)")
        return 77
    headers = Headers(root)
    cache = {}
    clashes = []
    files = 0
    for batch in batches:
        members = parse_batch(batch)
        files += len(members)
        # The headers each member parses first in this batch: their names can be lent to as well.
        seen, new_headers = set(), {}
        for m in members:
            new_headers[m] = project_headers(m, cache, root, seen)
        for a_index, a in enumerate(members):
            lent = lent_names(cache[a], headers)
            for b in members[a_index + 1:]:
                spelled, qualified = merge_spelled([cache[b]] + [cache[h] for h in new_headers[b]])
                for name, kind, ns, text in lends(cache[a], lent, cache[b], spelled, qualified, headers):
                    clashes.append((batch, a, b, name, kind, ns, text))
    rel = lambda p: os.path.relpath(p, root)
    for batch, a, b, name, kind, ns, text in clashes:
        print(f"{rel(a)}: {kind} `{name}` ({ns or 'global'}) is in sight of {rel(b)} in "
              f"{os.path.relpath(batch, build)}: {text[:90]}")
    print(f"{len(batches)} unity batches, {files} files: {len(clashes)} clash(es)")
    if clashes:
        print("Re-run cmake (it forms the batches around the clashes it sees), or rename the helper.")
    return 1 if clashes else 0


# The third-party headers whose inline code costs most to compile (-ftime-trace), costliest first.
COSTLY_HEADERS = ("CLI/CLI.hpp", "nlohmann/json.hpp", "tao/pegtl.hpp", "toml++/toml.h", "doctest/doctest.h")


def group(sources, batch_size, root, headers=None):
    """Batches for `sources` (in their order) such that no file shares a batch with a file that lends it
    a name or borrows one from it (either order, the headers each brings counted): greedy, first fit."""
    headers = headers or Headers(root)
    cache = {}
    info = {}
    headers_of = {}
    for src in sources:
        hdrs = headers_of[src] = project_headers(src, cache, root, set())
        spelled, qualified = merge_spelled([cache[src]] + [cache[h] for h in hdrs])
        info[src] = (lent_names(cache[src], headers), spelled, qualified)

    def clash(a, b):
        for x, y in ((a, b), (b, a)):
            lent = info[x][0]
            if lent and lends(cache[x], lent, cache[y], info[y][1], info[y][2], headers):
                return True
        return False

    # The files that use the same costly headers go first and side by side, so that those headers'
    # inline code is compiled in as few batches as possible.
    def costly(src):
        used = set(cache[src].system_includes)
        for h in headers_of[src]:
            used.update(cache[h].system_includes)
        return tuple(h for h in COSTLY_HEADERS if h in used)

    weight = {src: costly(src) for src in sources}
    ordered = sorted(sources, key=lambda src: (-len(weight[src]), weight[src]))

    batches = []
    for src in ordered:
        for batch in batches:
            if len(batch) < batch_size and not any(clash(src, other) for other in batch):
                batch.append(src)
                break
        else:
            batches.append([src])
    return batches


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", help="check the build tree's batches (CMakeFiles/*/Unity/*.cxx)")
    ap.add_argument("--group", nargs="+", metavar="SOURCE",
                    help="print batches for these sources, one `index|path` line a file (cmake/speed_up.cmake)")
    ap.add_argument("--group-targets", metavar="FILE",
                    help="the same for several targets: FILE has a `target|batch size|source` line a file; "
                         "prints `target|index|path` lines")
    ap.add_argument("--batch-size", type=int, default=16, help="sources per batch (--group)")
    ap.add_argument("--cache", help="a file that keeps the parsed sources between runs (the build tree's)")
    ap.add_argument("--source", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    args = ap.parse_args()
    root = os.path.abspath(args.source)
    if args.group or args.group_targets:
        if args.cache:
            load_cache(args.cache)
        if args.group:
            for index, batch in enumerate(group(args.group, args.batch_size, root)):
                for src in batch:
                    print(f"{index}|{src}")
        else:
            sources_of, size_of = {}, {}  # target -> its sources, in the order given; its batch size
            with open(args.group_targets, encoding="utf-8") as f:
                for line in f:
                    fields = line.rstrip("\n").split("|", 2)
                    if len(fields) == 3:
                        target, size, path = fields
                        sources_of.setdefault(target, []).append(path)
                        size_of[target] = int(size)
            headers = Headers(root)
            for target, sources in sources_of.items():
                for index, batch in enumerate(group(sources, size_of[target], root, headers)):
                    for src in batch:
                        print(f"{target}|{index}|{src}")
        if args.cache:
            save_cache(args.cache)
        return 0
    if not args.build:
        ap.error("--build or --group")
    return check(args.build, root)


if __name__ == "__main__":
    sys.exit(main())
