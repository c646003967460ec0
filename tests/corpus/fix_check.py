#!/usr/bin/env python3
"""`sphdeck check --fix` on the corpus decks (issue 27 item 3, the fix half): no value changes except
those a fix names.

For every corpus deck whose findings carry safe fixes (`check --diff` prints a diff), the deck's folder is
copied, `check --fix` runs on the copy, and:
  - the lines --fix changed are lines the findings' safe fixes name (`check --format json`'s fix edits);
  - every field `sphdeck dump` reads is the same in the fixed copy as in the original, except fields on
    the lines the fixes name, and the keywords are the same;
  - the fixed copy has no error or warning the original did not have (per code, no count grows);
  - fixing again changes nothing (`check --diff` on the fixed copy prints nothing).
The files the diff names are read as `git apply` run in the deck's folder reads them, and must be the files
`--fix` changed. A deck whose fixes would edit a file outside its copied folder is skipped (never written in
place); more than MOST_SKIPPED skipped decks fail the check.

    tests/corpus/fix_check.py --sphdeck build/sphdeck           # ../shared/corpus or $SPHDECK_CORPUS
Called by run_corpus.py after the findings check (--no-fix-check leaves it out).
"""
import argparse
import collections
import concurrent.futures
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.path.dirname(os.path.dirname(HERE))
TIMEOUT_S = 60
# A deck is skipped only when its fixes would edit a file the copy of its folder does not hold (an include
# elsewhere): rare, and a proof that skips more proves little, so more than this many is a failure.
MOST_SKIPPED = 2


def run(sphdeck, args, cwd=None):
    done = subprocess.run([sphdeck] + args, capture_output=True, timeout=TIMEOUT_S, cwd=cwd)
    return done.returncode, done.stdout, done.stderr.decode("utf-8", "replace")


def git_path(header):
    """The path of a `+++ ` header line as `git apply` reads it (the default -p1): a C-quoted name
    ("b/a\\tb.k") unquoted, a tab and what follows it (a timestamp) left out, the first component
    (b/) stripped; None for /dev/null (a file deleted) or a name with nothing after its first component."""
    name = header[4:]
    if name.startswith('"'):
        end, chars = 1, []
        while end < len(name) and name[end] != '"':
            if name[end] == "\\" and end + 1 < len(name):
                end += 1
                escaped = {"t": "\t", "n": "\n", '"': '"', "\\": "\\", "a": "\a", "b": "\b", "f": "\f",
                           "r": "\r", "v": "\v"}
                if name[end] in "01234567":
                    chars.append(chr(int(name[end:end + 3], 8)))
                    end += 3
                    continue
                chars.append(escaped.get(name[end], name[end]))
            else:
                chars.append(name[end])
            end += 1
        name = "".join(chars)
    else:
        name = name.split("\t", 1)[0]
    if name == "/dev/null" or "/" not in name.lstrip("/"):
        return None
    return name.lstrip("/").split("/", 1)[1]


def diff_files(diff, folder):
    """The files a unified diff made in `folder` names, as `git apply` run there would edit them: each
    `+++ ` path without its first component, relative to `folder` (git never reads a diff path as absolute:
    `+++ b/tmp/deck.k` is tmp/deck.k below the folder)."""
    paths = []
    for line in diff.decode("latin-1").splitlines():
        if line.startswith("+++ "):
            name = git_path(line)
            if name is not None:
                paths.append(os.path.normpath(os.path.join(folder, name)))
    return paths


def findings(sphdeck, deck):
    code, out, err = run(sphdeck, ["check", "--format", "json", "--no-config", deck])
    if code not in (0, 1):
        return None
    counts = collections.Counter()
    for d in json.loads(out)["diagnostics"]:
        if d["severity"] in ("error", "warning"):
            counts[d["code"]] += 1
    return counts


def dump(sphdeck, deck):
    code, out, _ = run(sphdeck, ["dump", "--format", "json", deck])
    return json.loads(out) if code in (0, 1) and out else None


def fix_named_lines(sphdeck, deck, folder):
    """{real path: line numbers} the safe fixes of the deck's findings edit (the fix `check --fix` takes of
    each finding: its first safe one), from `check --format json` run in the deck's folder."""
    code, out, _ = run(sphdeck, ["check", "--format", "json", "--no-config", os.path.basename(deck)], cwd=folder)
    named = collections.defaultdict(set)
    if code not in (0, 1):
        return named
    for d in json.loads(out)["diagnostics"]:
        fix = next((f for f in d.get("fixes", []) if f["safe"] and f["edits"]), None)
        for edit in fix["edits"] if fix else ():
            named[os.path.realpath(os.path.join(folder, edit["file"]))].add(edit["line"])
    return named


def changed_lines(original, fixed):
    """1-based numbers of the lines that differ between two files of the same number of lines."""
    with open(original, "rb") as f:
        a = f.read().split(b"\n")
    with open(fixed, "rb") as f:
        b = f.read().split(b"\n")
    if len(a) != len(b):
        return None
    return {n for n, (x, y) in enumerate(zip(a, b), 1) if x != y}


def check_one(sphdeck, corpus, rel, scratch):
    """(rel, problem or None, files changed, lines changed); problem None when the deck has nothing to fix."""
    original = os.path.join(corpus, rel)
    folder = os.path.dirname(original)
    # Run in the deck's folder, as a user would before `git apply`: the diff names files from there.
    code, diff, err = run(sphdeck, ["check", "--diff", "--no-config", os.path.basename(original)], cwd=folder)
    if not diff:
        return rel, None, 0, 0
    named = diff_files(diff, folder)
    inside = os.path.realpath(folder) + os.sep
    outside = [p for p in named if not os.path.realpath(p).startswith(inside) or not os.path.isfile(p)]
    if outside:
        return rel, f"skipped: the fixes edit {outside[0]}, not a file below the deck's folder", 0, 0
    work = tempfile.mkdtemp(dir=scratch)
    try:
        copy_folder = os.path.join(work, "deck")
        shutil.copytree(folder, copy_folder)  # links followed: --fix writes a link's target, never the corpus
        copy = os.path.join(copy_folder, os.path.basename(original))
        run(sphdeck, ["check", "--fix", "--no-config", "--format", "concise", copy])
        problems = []
        # Which lines of which files the fixes edited, by the original's path.
        edited = {}
        for root, _, files in os.walk(copy_folder):
            for name in files:
                fixed_file = os.path.join(root, name)
                source = os.path.join(folder, os.path.relpath(fixed_file, copy_folder))
                if os.path.isfile(source) and not os.path.islink(fixed_file):
                    lines = changed_lines(source, fixed_file)
                    if lines is None:
                        problems.append(f"{os.path.relpath(fixed_file, copy_folder)}: the fix changed its line count")
                    elif lines:
                        edited[os.path.realpath(source)] = lines
        named_real = {os.path.realpath(p) for p in named}
        if named_real != set(edited):
            problems.append("--diff names " + ", ".join(sorted(os.path.relpath(p, folder) for p in named_real)) +
                            "; --fix changed " + ", ".join(sorted(os.path.relpath(p, folder) for p in edited)))
        # The lines the findings' fixes name: --fix may change those and no other.
        fix_lines = fix_named_lines(sphdeck, original, folder)
        for source, lines in sorted(edited.items()):
            unnamed = sorted(lines - fix_lines.get(source, set()))
            if unnamed:
                problems.append(f"--fix changed {len(unnamed)} line(s) of {os.path.relpath(source, folder)} no fix "
                                f"names (line {unnamed[0]} first)")
        before, after = dump(sphdeck, original), dump(sphdeck, copy)
        if before is None or after is None:
            problems.append("dump failed")
        elif [k["name"] for k in before["keywords"]] != [k["name"] for k in after["keywords"]]:
            problems.append("the fixed deck reads other keywords")
        else:
            for kb, ka in zip(before["keywords"], after["keywords"]):
                source = os.path.realpath(kb.get("file", ""))
                for name, fb in kb["fields"].items():
                    fa = ka["fields"].get(name)
                    if fa is not None and fa["value"] == fb["value"]:
                        continue
                    if fb.get("line") in fix_lines.get(source, ()):
                        continue  # a value on a line a fix names
                    problems.append(f"{kb['name']} {name} (line {fb.get('line')}) changed from {fb['value']!r} to "
                                    f"{None if fa is None else fa['value']!r} on a line no fix edited")
            for key in ("unknown_keywords", "nodes", "particles"):
                if before.get(key) != after.get(key):
                    problems.append(f"dump's {key} changed")
        found_before, found_after = findings(sphdeck, original), findings(sphdeck, copy)
        if found_before is None or found_after is None:
            problems.append("check failed")
        else:
            grown = {c: n for c, n in (found_after - found_before).items() if n}
            if grown:
                problems.append("new findings after the fix: " + ", ".join(f"{c} +{n}" for c, n in sorted(grown.items())))
        _, again, _ = run(sphdeck, ["check", "--diff", "--no-config", copy])
        if again:
            problems.append("a second --fix would change the deck again")
        return rel, "; ".join(problems[:3]) if problems else "", len(edited), sum(len(v) for v in edited.values())
    finally:
        shutil.rmtree(work, ignore_errors=True)


def check_fixes(sphdeck, corpus, decks, jobs):
    """Runs the check on `decks` (paths relative to `corpus`); prints a summary, returns the failures."""
    start = time.monotonic()
    scratch = tempfile.mkdtemp(prefix="sphdeck-corpus-fix-")
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
            results = list(pool.map(lambda d: check_one(sphdeck, corpus, d, scratch), decks))
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    fixed = [(rel, files, lines) for rel, problem, files, lines in results if problem == ""]
    skipped = [(rel, problem) for rel, problem, _, _ in results if problem and problem.startswith("skipped")]
    failures = [f"{rel}: --fix: {problem}" for rel, problem, _, _ in results
                if problem and not problem.startswith("skipped")]
    print(f"  check --fix: {len(fixed) + len(failures)} of {len(decks)} decks carry safe fixes; "
          f"{sum(f for _, f, _ in fixed)} files, {sum(n for _, _, n in fixed)} lines changed; "
          f"{len(failures)} change a value no fix names or add a finding; {len(skipped)} skipped "
          f"({time.monotonic() - start:.1f} s)")
    for rel, problem in skipped:
        print(f"    {rel}: {problem}")
    if len(skipped) > MOST_SKIPPED:
        failures.append(f"--fix: {len(skipped)} decks skipped, more than {MOST_SKIPPED}: the proof leaves them out")
    return failures


def main():
    sys.path.insert(0, HERE)
    from run_corpus import find_decks  # noqa: E402
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sphdeck", default=os.path.join(PROJECT, "build", "sphdeck"))
    parser.add_argument("--corpus", default=os.environ.get("SPHDECK_CORPUS",
                                                           os.path.join(PROJECT, "..", "shared", "corpus")))
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    args = parser.parse_args()
    corpus = os.path.abspath(args.corpus)
    decks, _ = find_decks(corpus)
    failures = check_fixes(os.path.abspath(args.sphdeck), corpus, decks, args.jobs)
    for failure in failures:
        print("FAIL " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
