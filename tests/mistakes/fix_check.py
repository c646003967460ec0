#!/usr/bin/env python3
"""`sphdeck check --fix` on the seeded mistakes (issue 27, "Done when"): plant a mistake of a kind whose
finding carries a fix, as run_mistakes.py plants it, keep the plants sphdeck catches on their line, run
`check --fix` on the mutant, and require that the fixed mutant has no error or warning the original did not
have (the planted finding gone, no new one). Counted per kind over all caught plants, and over the plants
whose finding on the planted line carries a fix (the gate: every one of those mended). Also counted: how
many fixed mutants read exactly what the original reads (`sphdeck dump` values equal: the fix restored
the author's values; bulk node and particle values are counted, not compared).

    tests/mistakes/fix_check.py --sphdeck build/sphdeck              # shipped decks + ../shared/corpus
    tests/mistakes/fix_check.py --sphdeck build/sphdeck --verbose    # and every plant left unfixed

The safe-fix kinds' plants that carry a fix must be mended at --min-rate (default 100%); the unsafe-fix
kinds (keyword, OpenRadioss header and parameter typos, a stray *END, a missing *PART heading, a lost keyword asterisk, a blank
line typed between cards; fixed with --unsafe-fixes) are reported only.
"""
import argparse
import collections
import concurrent.futures
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import decks as dk  # noqa: E402
import kinds as kn  # noqa: E402
import run_mistakes as rm  # noqa: E402

SAFE_FIX_KINDS = ["shift-right-1", "shift-right-3", "shift-left-2", "width-8", "radioss-straddle", "radioss-shift",
                  "digit-shift"]
UNSAFE_FIX_KINDS = ["keyword-typo", "radioss-header-typo", "parameter-typo", "stray-end", "missing-heading", "lost-asterisk", "blank-line",
                    "duplicated-line", "joined-lines", "split-line"]


def fix_mutant(sphdeck, path, include, unsafe):
    # --alone, as dk.check: the mutant is a deck of its own (no search of the scratch folder's other decks).
    cmd = [sphdeck, "check", "--fix", "--no-config", "--alone", "--format", "concise", path, "-I", include]
    if unsafe:
        cmd.insert(3, "--unsafe-fixes")
    done = subprocess.run(cmd, capture_output=True, timeout=dk.TIMEOUT_S)
    return done.returncode in (0, 1)


def carries_fix(report, targets, unsafe):
    """Whether a new error or warning on a planted line carries a fix --fix applies, from the mutant's
    `check --format json` report (the one run_mistakes.evaluate ran to see the plant caught)."""
    for d in report["diagnostics"]:
        if d["severity"] in ("error", "warning") and (d.get("line") or 0) in targets:
            if any(f.get("safe") or unsafe for f in d.get("fixes", [])):
                return True
    return False


def new_findings(host, plant, found, path):
    """Errors and warnings of the fixed mutant that the original does not have (lines mapped: through the
    plant's map, unless the fix gave the file back the original's line count, as DK032's inserted heading
    does for a deleted one)."""
    mine, real = os.path.realpath(host.copy), os.path.realpath(path)
    with open(host.copy, "rb") as a, open(path, "rb") as b:
        restored_lines = a.read().count(b"\n") == b.read().count(b"\n")
    before = collections.Counter()
    for file, line, code, severity, _ in host.found:
        if file == mine:
            line = line if restored_lines else plant.line_map(line)
            if line is None:
                continue
            file = real
        before[(file, line, code, severity)] += 1
    after = collections.Counter((f, l, c, s) for f, l, c, s, _ in found)
    return after - before


def fix_job(sphdeck, host, kind, unsafe, seed, per_deck, tries, scratch):
    """[(plant, fixable, fixed, restored, left)] for up to per_deck caught plants of one kind in one host."""
    rng = random.Random(f"{seed}:{kind.__name__}:{host.rel}")
    out = []
    include = os.path.dirname(host.path)
    for number, plant in enumerate(kind(host, rng) or ()):
        if number >= tries or len(out) >= per_deck:
            break
        where = os.path.join(scratch, f"{os.path.basename(host.work)}-fix-{kind.__name__}-{number}")
        try:
            reports = []
            outcome = rm.evaluate(sphdeck, host, plant, where, reports)
            if outcome is None or not outcome[0]:
                continue  # no mistake, or one sphdeck does not catch: nothing to fix
            path = os.path.join(where, os.path.basename(host.path))
            fixable = carries_fix(reports[-1], plant.targets, unsafe)
            if not fix_mutant(sphdeck, path, include, unsafe):
                out.append((plant, fixable, False, False, ["check --fix failed"]))
                continue
            found, problem = dk.check(sphdeck, path, include)
            if found is None:
                out.append((plant, fixable, False, False, [f"check failed: {problem}"]))
                continue
            left = new_findings(host, plant, found, path)
            report, _ = dk.dump(sphdeck, path, include)
            restored = report is not None and dk.dump_values(report) == host.values
            out.append((plant, fixable, not left, restored, [f"{c}@{l}" for (_, l, c, _) in sorted(left)]))
        finally:
            shutil.rmtree(where, ignore_errors=True)
    return host, kind, out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sphdeck", default=os.path.join(rm.PROJECT, "build", "sphdeck"))
    parser.add_argument("--corpus", default=os.environ.get("SPHDECK_CORPUS",
                                                           os.path.join(rm.PROJECT, "..", "shared", "corpus")))
    parser.add_argument("--no-corpus", action="store_true", help="the shipped decks only")
    parser.add_argument("--kinds", help="comma-separated kinds (default: the safe and unsafe fix kinds)")
    parser.add_argument("--seed", default="27")
    parser.add_argument("--per-deck", type=int, default=2)
    parser.add_argument("--hosts", type=int, default=8, help="decks per kind and source (default 8)")
    parser.add_argument("--min-rate", type=float, default=100.0, help="required rate of the safe-fix kinds")
    parser.add_argument("--jobs", type=int, default=min(4, (os.cpu_count() or 2) * 2))
    parser.add_argument("--verbose", action="store_true")
    args = parser.parse_args()
    sphdeck = os.path.abspath(args.sphdeck)
    if not os.access(sphdeck, os.X_OK):
        print(f"fix check: no sphdeck at {sphdeck}", file=sys.stderr)
        return 2
    names = SAFE_FIX_KINDS + UNSAFE_FIX_KINDS
    if args.kinds:
        names = [n for n in args.kinds.split(",") if n in names]
    by_name = dict(zip(kn.KIND_NAMES, kn.KINDS))
    kinds = [(by_name[n], n in UNSAFE_FIX_KINDS) for n in names if n in by_name]

    start = time.monotonic()
    hosts = rm.shipped_hosts()
    corpus = os.path.abspath(args.corpus)
    have_corpus = not args.no_corpus and os.path.isdir(corpus)
    if have_corpus:
        hosts += rm.corpus_hosts(corpus)
    known = rm.known_keywords(sphdeck)
    scratch = tempfile.mkdtemp(prefix="sphdeck-fix-check-")
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            # Candidate hosts per kind and source (a few more than needed: some are unusable), prepared
            # in parallel once each.
            candidates = {}
            for kind, _ in kinds:
                radioss_kind = kind.__name__.startswith("radioss")
                for source in ("shipped", "corpus"):
                    pool_hosts = [(i, h) for i, h in enumerate(hosts) if h.source == source
                                  and (h.fmt == "radioss") == radioss_kind]
                    random.Random(f"{args.seed}:{kind.__name__}:{source}").shuffle(pool_hosts)
                    candidates[(kind, source)] = pool_hosts[:3 * args.hosts]
            wanted = {i: h for picks in candidates.values() for i, h in picks}
            ready = dict(zip(wanted, pool.map(lambda ih: rm.prepare(sphdeck, ih[1], scratch, ih[0], known),
                                              wanted.items())))
            jobs = []
            for kind, unsafe in kinds:
                for source in ("shipped", "corpus"):
                    picked = []
                    for i, _ in candidates[(kind, source)]:
                        h = ready[i]
                        if len(picked) >= args.hosts:
                            break
                        if h.problem or (h.source == "shipped" and any(f[3] == "error" for f in h.found)):
                            continue
                        probe = kind(h, random.Random(0))
                        if probe is not None and next(iter(probe), None) is not None:
                            picked.append(h)
                    jobs += [pool.submit(fix_job, sphdeck, h, kind, unsafe, args.seed, args.per_deck, 8, scratch)
                             for h in picked]
            outcomes = [j.result() for j in jobs]
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    seconds = time.monotonic() - start

    # per kind: caught plants, fixed, values restored, plants whose finding carries a fix, those fixed
    table = collections.OrderedDict((n, [0, 0, 0, 0, 0]) for n in names)
    kind_names = dict(zip(kn.KINDS, kn.KIND_NAMES))
    misses = []
    for host, kind, results in outcomes:
        row = table[kind_names[kind]]
        for plant, fixable, fixed, restored, left in results:
            row[0] += 1
            row[1] += fixed
            row[2] += restored
            row[3] += fixable
            row[4] += fixable and fixed
            if not fixed:
                misses.append(f"{kind_names[kind]}: {host.rel}: {plant.what}; "
                              f"{'with' if fixable else 'no'} fix; left: {', '.join(left[:4])}")
    print(f"fix check: {sum(r[0] for r in table.values())} caught plants in {seconds:.1f} s with {sphdeck}"
          + ("" if have_corpus else " (no corpus)"))
    print(f"  {'kind':<18} {'fix':<7} {'plants':>6} {'fixed':>6} {'rate':>5} {'restored':>8} "
          f"{'with fix':>8} {'fixed':>6} {'rate':>5}")
    failures = []
    for name, (plants, fixed, restored, fixable, fixable_fixed) in table.items():
        unsafe = name in UNSAFE_FIX_KINDS
        rate = 100.0 * fixed / plants if plants else None
        fixable_rate = 100.0 * fixable_fixed / fixable if fixable else None
        verdict = ""
        # The gate: a plant whose finding carries a fix is mended by --fix with no new finding.
        if not unsafe and fixable_rate is not None and fixable_rate + 1e-9 < args.min_rate:
            verdict = "FAIL"
            failures.append(f"{name}: {fixable_rate:.0f}% of the plants with a fix < {args.min_rate:.0f}%")
        shown = lambda r: f"{r:.0f}%" if r is not None else "-"  # noqa: E731
        print(f"  {name:<18} {'unsafe' if unsafe else 'safe':<7} {plants:>6} {fixed:>6} {shown(rate):>5} "
              f"{restored:>8} {fixable:>8} {fixable_fixed:>6} {shown(fixable_rate):>5} {verdict}")
    if args.verbose:
        for miss in misses:
            print("UNFIXED " + miss)
    for failure in failures:
        print("FAIL " + failure)
    print(f"fix check: {'passed' if not failures else 'failed'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
