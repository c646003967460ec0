#!/usr/bin/env python3
"""`sphdeck check --fix` on the corpus decks (issue 27 item 3, the fix half): no value changes except
those a fix names.

For every corpus deck whose findings carry safe fixes (`check --diff` prints a diff), the deck's folder is
copied, `check --fix` runs on the copy, and:
  - every field `sphdeck dump` reads is the same in the fixed copy as in the original, except fields on
    the lines the fixes edited (the values the fixes name), and the keywords are the same;
  - the fixed copy has no error or warning the original did not have (per code, no count grows);
  - fixing again changes nothing (`check --diff` on the fixed copy prints nothing).
A deck whose fixes would edit a file outside its copied folder is skipped (never written in place).

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


def run(sphdeck, args):
    done = subprocess.run([sphdeck] + args, capture_output=True, timeout=TIMEOUT_S)
    return done.returncode, done.stdout, done.stderr.decode("utf-8", "replace")


def diff_files(diff):
    """The paths a unified diff names (its `+++ b/PATH` lines)."""
    return [line[6:] for line in diff.decode("latin-1").splitlines() if line.startswith("+++ b/")]


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
    code, diff, err = run(sphdeck, ["check", "--diff", "--no-config", original])
    if not diff:
        return rel, None, 0, 0
    folder = os.path.dirname(original)
    outside = [p for p in diff_files(diff) if not os.path.realpath(p if os.path.isabs(p) else os.path.join(os.getcwd(), p))
               .startswith(os.path.realpath(folder) + os.sep)]
    if outside:
        return rel, f"skipped: the fixes edit {outside[0]} outside the deck's folder", 0, 0
    work = tempfile.mkdtemp(dir=scratch)
    try:
        copy_folder = os.path.join(work, "deck")
        shutil.copytree(folder, copy_folder, symlinks=True)
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
                    if fb.get("line") in edited.get(source, ()):
                        continue  # a value on a line a fix rewrote: the value the fix names
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
