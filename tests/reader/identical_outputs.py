#!/usr/bin/env python3
"""Whole-output check of the chunked line reader (issue 40, grammar/line_chunks.hpp).

    python3 tests/reader/identical_outputs.py --sphdeck build/sphdeck DECK_OR_FOLDER...
    python3 tests/reader/identical_outputs.py --sphdeck build/sphdeck --reference OLD/sphdeck bench/out/big.k

For each deck, `check --format json` and `format --diff --includes` (standard output, standard error, exit
status) must print the same with every file read in chunks of --chunk-bytes (SPHDECK_READER_CHUNK_BYTES)
on each of --threads (OMP_NUM_THREADS) as the reference prints: by default the same binary reading small
files line by line (a deck of 4 MiB or more is read in chunks anyway: give --reference, a build from before
the chunked reader). Exit 1 when a deck prints differently, 2 on a usage error.
"""
import argparse
import os
import pathlib
import re
import subprocess
import sys

DECK_SUFFIXES = (".k", ".key", ".dyn")
RADIOSS_SUFFIX = "_0000.rad"
COMMANDS = (["check", "--format", "json"], ["format", "--diff", "--includes"])


def decks_of(paths):
    for path in paths:
        if path.is_dir():
            yield from (p for p in sorted(path.rglob("*"))
                        if p.is_file() and (p.suffix in DECK_SUFFIXES or p.name.endswith(RADIOSS_SUFFIX)))
        else:
            yield path


def output(sphdeck, deck, environment):
    parts = []
    for args in COMMANDS:
        run = subprocess.run([sphdeck, *args, str(deck)], capture_output=True, text=True, errors="replace",
                             timeout=600, env=environment)
        stdout = re.sub(r'"seconds": [-+0-9.eE]+', '"seconds": N', run.stdout)  # the one figure that moves
        stderr = re.sub(r" in [0-9.]+ s$", " in N s", run.stderr, flags=re.M)
        parts.append(f"$ {' '.join(args)}\nexit {run.returncode}\n{stdout}\n--- stderr\n{stderr}\n")
    return "".join(parts)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sphdeck", required=True)
    parser.add_argument("--reference", help="the sphdeck to compare with (default: --sphdeck, line by line)")
    parser.add_argument("--chunk-bytes", type=int, default=13)
    parser.add_argument("--threads", default="1,2,16")
    parser.add_argument("decks", nargs="+", type=pathlib.Path)
    options = parser.parse_args()
    if options.chunk_bytes < 1:
        parser.error("--chunk-bytes must be at least 1")
    sphdeck = str(pathlib.Path(options.sphdeck).resolve())
    reference = str(pathlib.Path(options.reference or options.sphdeck).resolve())
    plain = {k: v for k, v in os.environ.items() if k not in ("SPHDECK_READER_CHUNK_BYTES", "OMP_NUM_THREADS")}
    decks = list(decks_of(options.decks))
    differing = 0
    for deck in decks:
        expected = output(reference, deck, plain)
        for threads in options.threads.split(","):
            environment = dict(plain, SPHDECK_READER_CHUNK_BYTES=str(options.chunk_bytes), OMP_NUM_THREADS=threads)
            if output(sphdeck, deck, environment) != expected:
                differing += 1
                print(f"differs: {deck} (chunks of {options.chunk_bytes} bytes, {threads} threads)")
    print(f"{len(decks)} decks, {differing} differing outputs (threads {options.threads}, "
          f"chunks of {options.chunk_bytes} bytes)")
    return 1 if differing or not decks else 0


if __name__ == "__main__":
    sys.exit(main())
