"""The corpus check's proof that `sphdeck format` changes no value (issue 27 item 3), called by run_corpus.py.

The corpus is copied to a temporary folder; there every deck is formatted (its own file, then with
--includes its included files), and for every deck
  - `sphdeck dump` of the formatted deck equals the original's in every value (positions aside: the
    keys line, column, end_column and file are dropped),
  - the formatted deck has no finding (code, severity, file, line) the original did not have,
  - formatting again changes nothing (`format --check --includes` exits 0).
It reports how many decks and include files format changed, and the lines changed by kind.

Run alone on another folder (ctest `format-check-test-decks` runs it on decks/tests, decks wrong on purpose):
    tests/corpus/format_check.py --sphdeck build/sphdeck --decks decks/tests
"""
import collections
import concurrent.futures
import filecmp
import json
import os
import re
import shutil
import subprocess
import tempfile

TIMEOUT_S = 60
# The findings before and after formatting, each deck checked --alone: whether a deck is included by
# another is not what formatting changes (the including deck's own check reads the include, formatted,
# in context), and the search for including decks (engine/include_context) was three quarters of this
# proof's time: every deck file of the folders up to the project root read for each check.
CHECK = ["check", "--format", "json", "--no-config", "--alone"]
POSITION_KEYS = {"line", "column", "end_column", "file"}


def run(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return None


def without_positions(value):
    if isinstance(value, dict):
        return {k: without_positions(v) for k, v in value.items() if k not in POSITION_KEYS}
    if isinstance(value, list):
        return [without_positions(v) for v in value]
    return value


CARD_POSITION = re.compile(rb',"file":\d+,"line":\d+')


class Dump:
    """`dump --cards` with positions left out: the model part parsed, the card lines (some million values
    on the biggest decks) compared as text with their file and line cut out, parsed only to name a
    difference."""

    def __init__(self, stdout):
        model, cards = stdout.rsplit(b',"cards":', 1)
        self.model = without_positions(json.loads(model + b"}"))
        self.files = self.model.pop("card_files", None)  # every file the deck reads: its own and its includes
        self.cards = CARD_POSITION.sub(b"", cards)

    def __eq__(self, other):
        return isinstance(other, Dump) and self.model == other.model and self.cards == other.cards

    def difference(self, other):
        where = first_difference(self.model, other.model)
        if where:
            return where
        return first_difference(json.loads(self.cards.rstrip()[:-1]), json.loads(other.cards.rstrip()[:-1]), "$.cards")


def dump(sphdeck, deck):
    """The model dump and every card line's values (`dump --cards`), positions left out."""
    done = run([sphdeck, "dump", "--cards", deck])
    if done is None or done.returncode != 0:
        return None
    return Dump(done.stdout)


def findings(sphdeck, deck, root):
    done = run([sphdeck] + CHECK + [deck])
    if done is None or done.returncode not in (0, 1):
        return None
    found = collections.Counter()
    for d in json.loads(done.stdout)["diagnostics"]:
        name = os.path.relpath(os.path.realpath(d["file"]), os.path.realpath(root)) if d["file"] else None
        found[(d["code"], d["severity"], name, d["line"])] += 1
    return found


def findings_by_block(sphdeck, deck, root, by_line=None):
    """Findings by (code, severity, file, n-th keyword line of the file): `$#` lines added move lines.
    `by_line` (a Counter), when given, also receives them by (code, severity, file, line)."""
    done = run([sphdeck] + CHECK + [deck])
    if done is None or done.returncode not in (0, 1):
        return None
    keyword_lines = {}
    found = collections.Counter()
    for d in json.loads(done.stdout)["diagnostics"]:
        path = d["file"]
        name = os.path.relpath(os.path.realpath(path), os.path.realpath(root)) if path else None
        block = None
        if path:
            full = os.path.abspath(path)  # findings name files as given or from the working folder
            if full not in keyword_lines:
                try:
                    with open(full, "rb") as f:
                        keyword_lines[full] = [i + 1 for i, l in enumerate(f.read().split(b"\n"))
                                               if l[:1] in (b"*", b"/")]
                except OSError:
                    keyword_lines[full] = []
            block = sum(1 for k in keyword_lines[full] if k <= d["line"])
        found[(d["code"], d["severity"], name, block)] += 1
        if by_line is not None:
            by_line[(d["code"], d["severity"], name, d["line"])] += 1
    return found


def first_difference(a, b, path="$"):
    """Where two dumps differ first, for the failure message."""
    if type(a) is not type(b):
        return path
    if isinstance(a, dict):
        for k in list(a) + [k for k in b if k not in a]:
            if k not in a or k not in b:
                return f"{path}.{k}"
            where = first_difference(a[k], b[k], f"{path}.{k}")
            if where:
                return where
        return None
    if isinstance(a, (list, tuple)):
        if len(a) != len(b):
            return f"{path} (length {len(a)} vs {len(b)})"
        for i, (x, y) in enumerate(zip(a, b)):
            where = first_difference(x, y, f"{path}[{i}]")
            if where:
                return where
        return None
    return None if a == b else f"{path}: {a!r} vs {b!r}"


CHANGE = re.compile(r"(\d+) ([a-z ]+?)(?:,|\))")


def format_main(sphdeck, deck):
    """Formats the deck's own file; the lines changed by kind (from the summary line)."""
    done = run([sphdeck, "format", deck])
    if done is None or done.returncode != 0:
        return None
    summary = done.stderr.decode("utf-8", "replace")
    kinds = collections.Counter()
    if "(lines: " in summary:
        for n, kind in CHANGE.findall(summary.split("(lines: ", 1)[1]):
            kinds[kind] += int(n)
    kept = re.search(r"(\d+) card lines? left as written", summary)
    if kept:
        kinds["left as written"] += int(kept.group(1))
    return kinds


def sharing_groups(decks, files_of, root):
    """The decks in groups that share no file (a deck's own file or an include), each group in the order of
    `decks`: formatting two decks of one group at once would race on their shared includes, decks of
    different groups never touch the same file. One group of all decks when a deck's files are unknown."""
    if any(files_of[d] is None for d in decks):
        return [list(decks)]
    parent = {d: d for d in decks}

    def top(d):
        while parent[d] != d:
            parent[d] = parent[parent[d]]
            d = parent[d]
        return d

    owner = {}
    for deck in decks:
        for name in files_of[deck] + [os.path.join(root, deck)]:
            real = os.path.realpath(name)
            if real in owner:
                parent[top(deck)] = top(owner[real])
            else:
                owner[real] = deck
    groups = {}
    for deck in decks:
        groups.setdefault(top(deck), []).append(deck)
    return list(groups.values())


def check_formatting(sphdeck, corpus, decks, jobs):
    """(failures, summary lines)."""
    failures = []
    with tempfile.TemporaryDirectory(prefix="sphdeck-format-") as tmp:
        copy = os.path.join(tmp, "corpus")
        # Links followed: the copy shares no file with the corpus (format writes a link's target).
        shutil.copytree(corpus, copy)
        pool = concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs))
        original = os.path.abspath(corpus)
        def read_original(deck):
            by_line = collections.Counter()
            by_block = findings_by_block(sphdeck, os.path.join(original, deck), original, by_line)
            return (dump(sphdeck, os.path.join(original, deck)), by_line if by_block is not None else None), by_block

        both = dict(zip(decks, pool.map(read_original, decks)))
        before = {d: both[d][0] for d in decks}
        before_by_block = {d: both[d][1] for d in decks}
        # The steps that write (format) run the decks of a group one after the other, the groups side by side.
        groups = sharing_groups(decks, {d: before[d][0].files if before[d][0] else None for d in decks}, original)

        def writing(step):
            """[step(deck) for deck in decks], no two decks that share a file at the same time."""
            done = {}
            for group_done in pool.map(lambda group: [(d, step(d)) for d in group], groups):
                done.update(group_done)
            return [done[d] for d in decks]

        kinds_of = dict(zip(decks, writing(lambda d: format_main(sphdeck, os.path.join(copy, d)))))
        included = writing(lambda d: run([sphdeck, "format", "--includes", os.path.join(copy, d)]))
        after = dict(zip(decks, pool.map(
            lambda d: (dump(sphdeck, os.path.join(copy, d)), findings(sphdeck, os.path.join(copy, d), copy)), decks)))
        again = dict(zip(decks, pool.map(
            lambda d: run([sphdeck, "format", "--check", "--includes", os.path.join(copy, d)]), decks)))
        # What the default format changed (before the options below add their lines).
        changed_decks = sum(1 for d in decks if not filecmp.cmp(os.path.join(original, d), os.path.join(copy, d),
                                                                shallow=False))
        changed_files = 0
        for root, _, files in os.walk(copy):
            for name in files:
                path = os.path.join(root, name)
                source = os.path.join(original, os.path.relpath(path, copy))
                if os.path.isfile(source) and not filecmp.cmp(source, path, shallow=False):
                    changed_files += 1
        # The options that add lines and rewrite free ones, on the formatted copy: the same three proofs.
        extra = ["--headers", "--to", "fixed", "--includes"]
        extra_done = writing(lambda d: run([sphdeck, "format", *extra, os.path.join(copy, d)]))
        extra_after = dict(zip(decks, pool.map(
            lambda d: (dump(sphdeck, os.path.join(copy, d)), findings_by_block(sphdeck, os.path.join(copy, d), copy)),
            decks)))
        extra_again = dict(zip(decks, pool.map(
            lambda d: run([sphdeck, "format", "--check", *extra, os.path.join(copy, d)]), decks)))
        pool.shutdown()

        kinds = collections.Counter()
        for deck in decks:
            if kinds_of[deck] is None:
                failures.append(f"format: {deck}: format failed")
                continue
            kinds.update(kinds_of[deck])
        for deck, done in zip(decks, included):
            if done is None or done.returncode != 0:
                failures.append(f"format: {deck}: format --includes failed")
        for deck in decks:
            (dump_before, found_before), (dump_after, found_after) = before[deck], after[deck]
            if dump_before is not None and dump_after != dump_before:
                where = dump_before.difference(dump_after) if dump_after is not None else "dump failed"
                failures.append(f"format: {deck}: a value changed: {where}")
            if found_before is not None and found_after is not None:
                new = found_after - found_before
                if new:
                    (code, severity, name, line), _ = sorted(new.items())[0]
                    failures.append(f"format: {deck}: new finding {code} ({severity}) at {name}:{line}")
            done = again[deck]
            if done is None or done.returncode != 0:
                failures.append(f"format: {deck}: formatting twice changes the deck (not idempotent)")

        for deck, done in zip(decks, extra_done):
            dump_before, found_before = before[deck][0], before_by_block[deck]
            dump_after, found_after = extra_after[deck]
            if done is None or done.returncode != 0:
                failures.append(f"format: {deck}: format {' '.join(extra)} failed")
            if dump_before is not None and dump_after != dump_before:
                where = dump_before.difference(dump_after) if dump_after is not None else "dump failed"
                failures.append(f"format {' '.join(extra)}: {deck}: a value changed: {where}")
            if found_before is not None and found_after is not None:
                new = found_after - found_before
                if new:
                    (code, severity, name, block), _ = sorted(new.items())[0]
                    failures.append(f"format {' '.join(extra)}: {deck}: new finding {code} ({severity}) in {name} "
                                    f"block {block}")
            if extra_again[deck] is None or extra_again[deck].returncode != 0:
                failures.append(f"format {' '.join(extra)}: {deck}: formatting twice changes the deck")

    summary = [f"  format: {changed_decks} of {len(decks)} decks changed, {changed_files} files with --includes; "
               "lines: " + (", ".join(f"{n} {k}" for k, n in sorted(kinds.items())) or "none")]
    return failures, summary


def main():
    import argparse
    import sys
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import run_corpus
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sphdeck", required=True)
    parser.add_argument("--decks", required=True, help="folder of decks (as the corpus check finds them)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    args = parser.parse_args()
    decks, _ = run_corpus.find_decks(args.decks)
    failures, summary = check_formatting(args.sphdeck, args.decks, decks, args.jobs)
    print(f"format check: {len(decks)} decks under {args.decks}")
    for line in summary + ["FAIL " + f for f in failures]:
        print(line)
    return 1 if failures else 0


if __name__ == "__main__":
    raise SystemExit(main())
