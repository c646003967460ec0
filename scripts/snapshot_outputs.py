#!/usr/bin/env python3
"""Record what sphdeck prints on every deck of decks/ and the corpus, to prove a refactor changes no output.

    python3 scripts/snapshot_outputs.py --sphdeck build/sphdeck --out /tmp/before
    ... change the code, rebuild ...
    python3 scripts/snapshot_outputs.py --sphdeck build/sphdeck --out /tmp/after --compare /tmp/before

For each deck it records `check --format json` and `format --diff --includes` (standard output, standard error
and exit status) in one file named after the deck's path; --compare lists the decks whose record differs and
exits 1 when any does.
"""
import argparse
import hashlib
import os
import pathlib
import re
import subprocess
import sys

DECK_SUFFIXES = (".k", ".key", ".dyn")
RADIOSS_SUFFIX = "_0000.rad"


def decks_under(folder: pathlib.Path):
    for path in sorted(folder.rglob("*")):
        if path.is_file() and (path.suffix in DECK_SUFFIXES or path.name.endswith(RADIOSS_SUFFIX)):
            yield path


def record(sphdeck: str, deck: pathlib.Path) -> str:
    parts = []
    for args in (["check", "--format", "json"], ["format", "--diff", "--includes"]):
        run = subprocess.run([sphdeck, *args, str(deck)], capture_output=True, text=True, timeout=300,
                             errors="replace")
        # How long the check took is the one figure that differs between two runs (JSON and summary line).
        stdout = re.sub(r'"seconds": [-+0-9.eE]+', '"seconds": N', run.stdout)
        stderr = re.sub(r" in [0-9.]+ s$", " in N s", run.stderr, flags=re.M)
        parts.append(f"$ {' '.join(args)}\nexit {run.returncode}\n--- stdout\n{stdout}\n--- stderr\n{stderr}\n")
    return "".join(parts)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sphdeck", required=True)
    parser.add_argument("--out", required=True, type=pathlib.Path)
    parser.add_argument("--compare", type=pathlib.Path, help="a folder written before by this script")
    parser.add_argument("--corpus", type=pathlib.Path,
                        default=pathlib.Path(os.environ.get("SPHDECK_CORPUS", "../shared/corpus")))
    options = parser.parse_args()
    sphdeck = str(pathlib.Path(options.sphdeck).resolve())
    folders = [pathlib.Path("decks")] + ([options.corpus] if options.corpus.is_dir() else [])
    options.out.mkdir(parents=True, exist_ok=True)
    names = []
    for folder in folders:
        for deck in decks_under(folder):
            name = hashlib.sha1(str(deck).encode()).hexdigest()[:16] + "_" + deck.name + ".txt"
            (options.out / name).write_text(f"deck {deck}\n" + record(sphdeck, deck))
            names.append(name)
    print(f"recorded {len(names)} decks in {options.out}")
    if options.compare is None:
        return 0
    differing = [n for n in names
                 if not (options.compare / n).is_file()
                 or (options.compare / n).read_text() != (options.out / n).read_text()]
    for name in differing:
        print(f"differs: {name} (diff {options.compare / name} {options.out / name})")
    print(f"{len(differing)} of {len(names)} decks print differently")
    return 1 if differing else 0


if __name__ == "__main__":
    sys.exit(main())
