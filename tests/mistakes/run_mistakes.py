#!/usr/bin/env python3
"""The seeded-mistakes test: plant typical hand-editing mistakes, one at a time, into working decks and
require a new error or warning on the line where each was planted.

    tests/mistakes/run_mistakes.py --sphdeck build/sphdeck            # shipped decks + ../shared/corpus
    tests/mistakes/run_mistakes.py --sphdeck build/sphdeck --verbose  # and every miss, with what came instead
    tests/mistakes/run_mistakes.py --no-corpus --kinds keyword-typo,width-8

Hosts: the shipped working decks (decks/**.k, decks/**.rad without `expect` comments and without errors
as they are) and the corpus decks (../shared/corpus or $SPHDECK_CORPUS; skipped when missing). For each
kind a seeded sample of hosts gets a few plants each; a plant that does not change what the deck reads
(checked with `sphdeck dump` or the fixed columns) is no mistake and is dropped. Each mutant is checked
with `sphdeck check --format json --no-config` beside a copy of the original (includes are found with -I
pointing at the original's folder). The test fails when a kind's rate is below its row in thresholds.tsv.
See tests/mistakes/README.md.
"""
import argparse
import collections
import concurrent.futures
import os
import random
import shutil
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(PROJECT, "tests", "corpus"))

import decks as dk  # noqa: E402
import kinds as kn  # noqa: E402
from run_corpus import find_decks  # noqa: E402

EXPECT_MARKS = ("expect:", "expect-deck:", "expect-above:")
# sph_mistakes_2d.k is the demo of mistakes; DK029_lone_value_silent.k is written with its numbers left in
# their fields to show where the right-aligned habit stops being evidence: a shift there is as silent.
NOT_HOSTS = ("decks/demo/sph_mistakes_2d.k", "decks/tests/dk/DK029_lone_value_silent.k")


class Host:
    def __init__(self, source, rel, path):
        self.source = source      # "shipped" or "corpus"
        self.rel = rel            # the name printed
        self.path = path          # the original
        self.fmt = "radioss" if path.lower().endswith(".rad") else "dyna"
        self.work = None          # the folder of its copies
        self.copy = None          # the copy of the original that is checked
        self.deck = None
        self.found = None         # errors and warnings of the original
        self.values = None        # what the original reads (dump)
        self.fields = {}
        self.all_fields = []
        self.known_keywords = set()
        self.problem = None


def shipped_hosts():
    out = []
    root = os.path.join(PROJECT, "decks")
    for folder, dirs, files in os.walk(root):
        dirs.sort()
        if os.path.basename(folder) == "include":
            continue
        for name in sorted(files):
            path = os.path.join(folder, name)
            rel = os.path.relpath(path, PROJECT)
            low = name.lower()
            if not (low.endswith(".k") or low.endswith(".rad")) or rel in NOT_HOSTS:
                continue
            if low.endswith(".rad") and low[-9:-4].startswith("_000") and not low.endswith("_0000.rad"):
                continue  # an engine file (_0001.rad), not a starter deck
            with open(path, encoding="latin-1") as f:
                text = f.read()
            if any(mark in text for mark in EXPECT_MARKS):
                continue  # a test deck that expects findings
            out.append(Host("shipped", rel, path))
    return out


def corpus_hosts(corpus):
    decks, _ = find_decks(corpus)
    return [Host("corpus", rel, os.path.join(corpus, rel)) for rel in decks]


def known_keywords(sphdeck):
    """The keyword names sphdeck knows: LS-DYNA's (`*...`) and OpenRadioss headers (`/...`) in one set."""
    known = set()
    for solver, mark in (("lsdyna", "*"), ("radioss", "/")):
        listing, _ = dk.run_sphdeck_text(sphdeck, ["keyword", "--list", "--solver", solver])
        for line in listing.splitlines():
            if line.startswith(mark):
                known.add(line.split()[0].upper())
    return known


def prepare(sphdeck, host, scratch, index, known):
    host.work = os.path.join(scratch, f"h{index}")
    os.makedirs(host.work)
    host.copy = os.path.join(host.work, os.path.basename(host.path))
    shutil.copyfile(host.path, host.copy)
    include = os.path.dirname(host.path)
    host.found, problem = dk.check(sphdeck, host.copy, include)
    if problem:
        host.problem = problem
        return host
    report, problem = dk.dump(sphdeck, host.copy, include)
    if problem:
        host.problem = problem
        return host
    host.values = dk.dump_values(report)
    host.fields = dk.dump_fields(report, host.copy)
    host.all_fields = [(k["name"], n, f["value"]) for k in report.get("keywords", []) for n, f in k["fields"].items()]
    host.deck = dk.Deck(host.copy, host.fmt)
    host.known_keywords = known
    return host


def evaluate(sphdeck, host, plant, where, reports=None):
    """None when the plant changes nothing that is read (or its line is not clean to begin with); else (caught, new findings, on-target ones).
    `reports`, a list, when given, receives the mutant's `check --format json` report (dk.check)."""
    mine = os.path.realpath(host.copy)
    if any(file == mine and line and plant.line_map(line) in plant.targets for file, line, *_ in host.found):
        return None  # the line has an error or warning already: not a working line to break
    os.makedirs(where)
    path = os.path.join(where, os.path.basename(host.path))
    with open(path, "wb") as f:
        f.write(host.deck.text(plant.lines).encode("latin-1"))
    include = os.path.dirname(host.path)
    if plant.change == "dump":
        report, _ = dk.dump(sphdeck, path, include)
        if report is not None and dk.dump_values(report) == host.values:
            return None
    elif plant.change == "grid":
        if all(dk.grid_reading(host.deck.lines[n - 1], plant.grid) == dk.grid_reading(plant.lines[n - 1], plant.grid)
               for n in plant.grid_lines):
            return None
    found, problem = dk.check(sphdeck, path, include, reports)
    if found is None:
        return False, [f"sphdeck failed: {problem}"], []
    real = os.path.realpath(path)
    before = collections.Counter()
    for file, line, code, severity, _ in host.found:
        if file == mine:
            line = plant.line_map(line)
            if line is None:
                continue
            file = real
        before[(file, line, code, severity)] += 1
    after = collections.Counter((f, l, c, s) for f, l, c, s, _ in found)
    messages = {(f, l, c, s): m for f, l, c, s, m in found}
    new = after - before
    on_target = [k for k in new if (k[0] == real and k[1] in plant.targets) or (0 in plant.targets and k[1] == 0)]
    described = []
    for key, count in sorted(new.items(), key=lambda kv: (kv[0][1], kv[0][2])):
        where_ = f"{key[1]}" if key[0] == real else f"{os.path.basename(key[0])}:{key[1]}"
        described.append(f"{key[2]} {key[3]}@{where_}{' x' + str(count) if count > 1 else ''}: {messages[key][:90]}")
    return bool(on_target), described, on_target


def plant_job(sphdeck, host, kind, seed, per_deck, tries, scratch):
    """Up to per_deck real plants of one kind in one host: [(plant, caught, described)], no-op count."""
    rng = random.Random(f"{seed}:{kind.__name__}:{host.rel}")
    results, noops = [], 0
    for number, plant in enumerate(kind(host, rng) or ()):
        if number >= tries or len(results) >= per_deck:
            break
        where = os.path.join(scratch, f"{os.path.basename(host.work)}-{kind.__name__}-{number}")
        outcome = evaluate(sphdeck, host, plant, where)
        shutil.rmtree(where, ignore_errors=True)
        if outcome is None:
            noops += 1
            continue
        caught, described, _ = outcome
        results.append((plant, caught, described))
    return host, kind, results, noops


def read_thresholds(path):
    rows = {}
    if not os.path.isfile(path):
        return rows
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if not line.strip() or line.startswith("#"):
                continue
            parts = line.rstrip("\n").split("\t")
            if len(parts) < 3:
                sys.exit(f"{path}:{number}: a row is kind<TAB>shipped %<TAB>corpus %")
            rows[parts[0]] = tuple(None if p.strip() == "-" else float(p) for p in parts[1:3])
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sphdeck", default=os.path.join(PROJECT, "build", "sphdeck"))
    parser.add_argument("--corpus", default=os.environ.get("SPHDECK_CORPUS",
                                                           os.path.join(PROJECT, "..", "shared", "corpus")))
    parser.add_argument("--no-corpus", action="store_true", help="the shipped decks only")
    parser.add_argument("--thresholds", default=os.path.join(HERE, "thresholds.tsv"))
    parser.add_argument("--kinds", help="comma-separated kinds (default: all)")
    parser.add_argument("--seed", default="25")
    parser.add_argument("--per-deck", type=int, default=2, help="plants per deck and kind (default 2)")
    parser.add_argument("--shipped-hosts", type=int, default=40, help="shipped decks per kind (default 40)")
    parser.add_argument("--corpus-hosts", type=int, default=50, help="corpus decks per kind (default 50)")
    parser.add_argument("--jobs", type=int, default=min(4, (os.cpu_count() or 2) * 2))
    parser.add_argument("--verbose", action="store_true", help="list every miss: deck:line and what came instead")
    parser.add_argument("--show-caught", action="store_true",
                        help="list every caught plant too, with its new findings (is the cause named?)")
    parser.add_argument("--markdown", action="store_true", help="print the rate table as markdown")
    args = parser.parse_args()
    sphdeck = os.path.abspath(args.sphdeck)
    if not os.access(sphdeck, os.X_OK):
        print(f"seeded mistakes: no sphdeck at {sphdeck}", file=sys.stderr)
        return 2
    kinds = kn.KINDS
    if args.kinds:
        wanted = set(args.kinds.split(","))
        unknown = wanted - set(kn.KIND_NAMES)
        if unknown:
            print(f"seeded mistakes: unknown kinds {sorted(unknown)}; kinds: {', '.join(kn.KIND_NAMES)}",
                  file=sys.stderr)
            return 2
        kinds = [k for k, name in zip(kn.KINDS, kn.KIND_NAMES) if name in wanted]

    start = time.monotonic()
    hosts = shipped_hosts()
    corpus = os.path.abspath(args.corpus)
    have_corpus = not args.no_corpus and os.path.isdir(corpus)
    if not args.no_corpus and not have_corpus:
        print(f"seeded mistakes: no corpus at {corpus}: shipped decks only", file=sys.stderr)
    if have_corpus:
        hosts += corpus_hosts(corpus)
    known = known_keywords(sphdeck)

    scratch = tempfile.mkdtemp(prefix="sphdeck-mistakes-")
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            ready = list(pool.map(lambda ih: prepare(sphdeck, ih[1], scratch, ih[0], known), enumerate(hosts)))
            usable = [h for h in ready if not h.problem and not (
                h.source == "shipped" and any(f[3] == "error" for f in h.found))]
            jobs = []
            for kind in kinds:
                for source, cap in (("shipped", args.shipped_hosts), ("corpus", args.corpus_hosts)):
                    pool_hosts = [h for h in usable if h.source == source]
                    random.Random(f"{args.seed}:{kind.__name__}:{source}").shuffle(pool_hosts)
                    picked = []
                    for h in pool_hosts:
                        if len(picked) >= cap:
                            break
                        probe = kind(h, random.Random(0))
                        if probe is not None and next(iter(probe), None) is not None:
                            picked.append(h)
                    jobs += [pool.submit(plant_job, sphdeck, h, kind, args.seed, args.per_deck, 8, scratch)
                             for h in picked]
            outcomes = [j.result() for j in jobs]
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    seconds = time.monotonic() - start

    names = dict(zip(kn.KINDS, kn.KIND_NAMES))
    table = collections.OrderedDict()
    misses, catches = [], []
    for kind in kinds:
        for source in ("shipped", "corpus"):
            table[(names[kind], source)] = [0, 0, 0, 0, 0]  # plants, caught, no-ops, decks, new findings
    for host, kind, results, noops in outcomes:
        row = table[(names[kind], host.source)]
        row[2] += noops
        row[3] += bool(results)
        for plant, caught, described in results:
            row[0] += 1
            row[1] += caught
            row[4] += len(described)
            lines = ",".join(str(t) for t in sorted(plant.targets))
            shown = ("; ".join(described[:4]) + (f"; ... {len(described) - 4} more" if len(described) > 4 else "")
                     if described else "nothing new")
            if not caught:
                misses.append(f"{names[kind]}: {host.rel}:{lines}: {plant.what}; instead: {shown}")
            else:
                catches.append(f"{names[kind]}: {host.rel}:{lines}: {plant.what}; found: {shown}")

    thresholds = read_thresholds(args.thresholds)
    failures = []
    print(f"seeded mistakes: {sum(r[0] for r in table.values())} plants in "
          f"{len({h.rel for h, _, r, _ in outcomes if r})} decks in {seconds:.1f} s with {sphdeck}"
          + ("" if have_corpus else " (no corpus)"))
    skipped = [h for h in ready if h.problem]
    if skipped:
        print(f"  {len(skipped)} decks skipped (sphdeck could not read them): "
              + ", ".join(f"{h.rel} ({h.problem})" for h in skipped[:5]))
    if args.markdown:
        print("| kind | decks | plants | caught on the line | rate | new findings per plant | dropped as no-ops |")
        print("|---|---|---|---|---|---|---|")
    else:
        print(f"  {'kind':<18} {'source':<8} {'decks':>5} {'plants':>6} {'caught':>6} {'rate':>6} "
              f"{'new/plant':>9} {'no-ops':>6}  threshold")
    for (kind, source), (plants, caught, noops, decks, new) in table.items():
        if source == "corpus" and not have_corpus:
            continue
        rate = 100.0 * caught / plants if plants else None
        minimum = thresholds.get(kind, (None, None))[0 if source == "shipped" else 1]
        verdict = ""
        if minimum is not None and plants and rate + 1e-9 < minimum:
            verdict = "FAIL"
            failures.append(f"{kind} ({source}): {rate:.0f}% < {minimum:.0f}%")
        rate_text = f"{rate:.0f}%" if rate is not None else "-"
        per = f"{new / plants:.1f}" if plants else "-"
        if args.markdown:
            print(f"| {kind} ({source}) | {decks} | {plants} | {caught} | {rate_text} | {per} | {noops} |")
        else:
            print(f"  {kind:<18} {source:<8} {decks:>5} {plants:>6} {caught:>6} {rate_text:>6} {per:>9} {noops:>6}"
                  f"  {'-' if minimum is None else f'{minimum:.0f}%'} {verdict}")
    if args.verbose:
        for miss in misses:
            print("MISS " + miss)
    if args.show_caught:
        for catch in catches:
            print("CAUGHT " + catch)
    for failure in failures:
        print("FAIL " + failure)
    print(f"seeded mistakes: {'passed' if not failures else 'failed'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
