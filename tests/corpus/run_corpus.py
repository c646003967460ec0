#!/usr/bin/env python3
"""The corpus check: sphdeck on real public decks, findings compared with an argued baseline.

Every error and warning sphdeck gives on a real deck is either a defect of the published deck, argued
in one row of tests/corpus/baseline.tsv, or a false alarm. The check fails on a finding the baseline
does not hold, on a count that changed, and on a baseline row that no longer fires, like ruff's
ecosystem check. Infos are counted but not compared.

    tests/corpus/run_corpus.py --sphdeck build/sphdeck            # ../shared/corpus or $SPHDECK_CORPUS
    tests/corpus/run_corpus.py --sphdeck build/sphdeck --corpus DIR --baseline my.tsv
    tests/corpus/run_corpus.py --sphdeck build/sphdeck --write-baseline new.tsv   # current findings

Decks: every *.k, *.key, *.dyn file (LS-DYNA) and every *_0000.rad file (OpenRadioss starter deck)
below the corpus folder. Where an OpenRadioss deck has the starter's listing beside it
(../reference/NAME_0000.out), the listing's error count is read: errors on decks the starter accepted
are counted apart in the summary.

Then format_check.py proves on every deck that `sphdeck format` changes no value (dump equal, no new finding,
a second run changes nothing); --no-format-check skips it.
"""
import argparse
import collections
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import time

import format_check

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.path.dirname(os.path.dirname(HERE))
DECK_TIMEOUT_S = 60
LSDYNA_SUFFIXES = (".k", ".key", ".dyn")


def find_decks(corpus):
    """(decks, number of empty files skipped): an empty file is a placeholder, not a deck."""
    decks = []
    empty = 0
    for root, dirs, files in os.walk(corpus):
        dirs.sort()
        for name in sorted(files):
            lower = name.lower()
            if lower.endswith(LSDYNA_SUFFIXES) or lower.endswith("_0000.rad"):
                path = os.path.join(root, name)
                if os.path.getsize(path) == 0:
                    empty += 1
                    continue
                decks.append(os.path.relpath(path, corpus))
    return decks, empty


def starter_errors(corpus, deck):
    """Errors the OpenRadioss starter printed for this deck, or None without a listing."""
    if not deck.lower().endswith("_0000.rad"):
        return None
    data_dir, name = os.path.split(os.path.join(corpus, deck))
    listing = os.path.join(os.path.dirname(data_dir), "reference", name[:-4] + ".out")
    if not os.path.isfile(listing):
        return None
    with open(listing, encoding="latin-1") as f:
        counts = re.findall(r"^\s*(\d+)\s+ERROR\(S\)\s*$", f.read(), re.M)
    return int(counts[-1]) if counts else None


def check_deck(sphdeck, corpus, deck):
    """(deck, Counter of (code, severity), exit code, problem text or None)."""
    cmd = [sphdeck, "check", "--format", "json", "--no-config", os.path.join(corpus, deck)]
    try:
        done = subprocess.run(cmd, capture_output=True, timeout=DECK_TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return deck, collections.Counter(), None, f"timed out after {DECK_TIMEOUT_S} s"
    if done.returncode not in (0, 1):
        message = done.stderr.decode("utf-8", "replace").strip().splitlines()
        return deck, collections.Counter(), done.returncode, f"exit {done.returncode}: {message[-1] if message else ''}"
    try:
        report = json.loads(done.stdout)
    except json.JSONDecodeError as e:
        return deck, collections.Counter(), done.returncode, f"output is not JSON: {e}"
    found = collections.Counter()
    for d in report["diagnostics"]:
        found[(d["code"], d["severity"])] += 1
    return deck, found, done.returncode, None


def read_baseline(path):
    """{(deck, code): (count, reason, line number)}."""
    rows = {}
    if not os.path.isfile(path):
        return rows
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line.strip() or line.startswith("#"):
                continue
            parts = line.split("\t")
            if len(parts) != 4 or not parts[2].isdigit() or not parts[3].strip():
                sys.exit(f"{path}:{number}: a row is deck<TAB>code<TAB>count<TAB>reason")
            if parts[3].lstrip().upper().startswith("TODO"):
                sys.exit(f"{path}:{number}: {parts[0]} {parts[1]} has no reason yet: argue it or fix sphdeck")
            key = (parts[0], parts[1])
            if key in rows:
                sys.exit(f"{path}:{number}: {parts[0]} {parts[1]} is listed twice")
            rows[key] = (int(parts[2]), parts[3], number)
    return rows


def write_baseline(path, results, old):
    with open(path, "w", encoding="utf-8") as f:
        f.write("# deck\tcode\tcount\treason (one row per real defect of a published deck)\n")
        for deck in sorted(results):
            found = results[deck][0]
            for code in sorted({c for c, s in found if s in ("error", "warning")}):
                count = sum(n for (c, s), n in found.items() if c == code and s in ("error", "warning"))
                reason = old.get((deck, code), (0, "TODO: argue or fix", 0))[1]
                f.write(f"{deck}\t{code}\t{count}\t{reason}\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sphdeck", default=os.path.join(PROJECT, "build", "sphdeck"))
    parser.add_argument("--corpus", default=os.environ.get("SPHDECK_CORPUS",
                                                           os.path.join(PROJECT, "..", "shared", "corpus")))
    parser.add_argument("--baseline", default=os.path.join(HERE, "baseline.tsv"))
    parser.add_argument("--write-baseline", metavar="FILE", help="write the current findings as a baseline")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--verbose", action="store_true", help="list every deck's findings")
    parser.add_argument("--no-format-check", action="store_true",
                        help="skip the proof that `sphdeck format` changes no value (tests/corpus/format_check.py)")
    parser.add_argument("--no-fix-check", action="store_true",
                        help="leave out the check of `check --fix` on the decks (tests/corpus/fix_check.py)")
    parser.add_argument("--skip-missing", action="store_true",
                        help="exit 77 (skipped, for ctest) when the corpus folder is not there")
    args = parser.parse_args()

    corpus = os.path.abspath(args.corpus)
    if not os.path.isdir(corpus):
        print(f"corpus check: no corpus folder at {corpus} (set SPHDECK_CORPUS)", file=sys.stderr)
        return 77 if args.skip_missing else 2
    decks, empty = find_decks(corpus)
    if not decks:
        print(f"corpus check: no decks under {corpus}", file=sys.stderr)
        return 2
    start = time.monotonic()
    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for deck, found, code, problem in pool.map(lambda d: check_deck(args.sphdeck, corpus, d), decks):
            results[deck] = (found, code, problem)
    seconds = time.monotonic() - start

    baseline = read_baseline(args.baseline)
    if args.write_baseline:
        write_baseline(args.write_baseline, results, baseline)
        print(f"corpus check: wrote {args.write_baseline}")
        return 0

    failures = []
    by_code = collections.Counter()
    decks_with_errors = 0
    accepted = errors_on_accepted = accepted_with_errors = 0
    current = {}
    for deck in decks:
        found, _, problem = results[deck]
        if problem:
            failures.append(f"{deck}: {problem}")
        errors = sum(n for (c, s), n in found.items() if s == "error")
        decks_with_errors += errors > 0
        starter = starter_errors(corpus, deck)
        if starter == 0:
            accepted += 1
            errors_on_accepted += errors
            accepted_with_errors += errors > 0
        for (code, severity), n in found.items():
            by_code[(code, severity)] += n
            if severity in ("error", "warning"):
                current[(deck, code)] = current.get((deck, code), 0) + n
        if args.verbose and found:
            print(deck + ": " + ", ".join(f"{c} {s} x{n}" for (c, s), n in sorted(found.items())))

    for (deck, code), n in sorted(current.items()):
        row = baseline.get((deck, code))
        if row is None:
            failures.append(f"{deck}: {code} x{n} is not in the baseline (a false alarm, or a defect to argue there)")
        elif row[0] != n:
            failures.append(f"{deck}: {code} x{n}, the baseline (line {row[2]}) says x{row[0]}")
    for (deck, code), (n, _, line) in sorted(baseline.items(), key=lambda kv: kv[1][2]):
        if (deck, code) not in current:
            failures.append(f"{deck}: {code} no longer fires; remove baseline line {line}")

    print(f"corpus check: {len(decks)} decks under {corpus} in {seconds:.1f} s"
          + (f" ({empty} empty files skipped)" if empty else ""))
    print(f"  decks with errors: {decks_with_errors}; OpenRadioss decks the starter accepted: {accepted}, "
          f"{accepted_with_errors} of them with errors ({errors_on_accepted} errors)")
    for severity in ("error", "warning", "info"):
        codes = sorted((c, n) for (c, s), n in by_code.items() if s == severity)
        if codes:
            print(f"  {severity}s: " + ", ".join(f"{c} {n}" for c, n in codes))
    print(f"  baseline: {len(baseline)} rows, {sum(r[0] for r in baseline.values())} findings")
    if not args.no_format_check:
        format_start = time.monotonic()
        # Decks that share an include are formatted one after the other (format_check.sharing_groups).
        format_failures, format_summary = format_check.check_formatting(args.sphdeck, corpus, decks, args.jobs)
        failures += format_failures
        for line in format_summary:
            print(line)
        print(f"  format check: {time.monotonic() - format_start:.1f} s")
    if not args.no_fix_check:
        import fix_check  # tests/corpus/fix_check.py: no value changes except those a fix names
        failures += fix_check.check_fixes(os.path.abspath(args.sphdeck), corpus, decks, args.jobs)
    for failure in failures:
        print("FAIL " + failure)
    passed = 0 if failures else 1
    print(f"corpus: {passed} passed, {1 - passed} failed")
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
