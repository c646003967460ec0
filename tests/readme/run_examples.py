#!/usr/bin/env python3
"""Runs the console examples of README.md and docs/*.md and compares what they print with the text shown.

Every ```console block is run, one `$ command` after another, in a scratch folder holding a copy of the
repository's decks/ (so an example that writes files leaves nothing in the repository), with `sphdeck` on
PATH being the binary under test. The lines after a command, up to the next `$` line, are what it must
print (stdout and stderr together, as a terminal shows them):
  - a line `...` stands for any number of lines (also none);
  - a line ending in `...` matches any line that starts with the text before the `...`;
  - times (`in 0.01 s`, `0.3 s`), the version and the scratch folder are normalised;
  - a command followed directly by another `$` line, or by the block's end, must print nothing.
A block right after the line `<!-- example: not run -->` is not run (say why next to the marker).
The examples that `import sphdeck` (the Python module, README "From Python") run with `python3` being
--python and the module found in --pythonpath; without --pythonpath they are skipped, and said so.
Exit 0 when every example prints what it shows; 1 with a diff of each one that drifted.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

NOT_RUN_MARKER = "<!-- example: not run -->"
ELLIPSIS = "..."
COMMAND_TIMEOUT_S = 120


@dataclass
class Command:
    text: str
    expected: list = field(default_factory=list)


@dataclass
class Example:
    source: Path
    line: int  # line of the ```console fence, 1-based
    commands: list


def parse_examples(path: Path):
    """The console blocks of one Markdown file, each as its commands and their shown output."""
    lines = path.read_text(encoding="utf-8").splitlines()
    examples = []
    i = 0
    while i < len(lines):
        if lines[i].strip() != "```console":
            i += 1
            continue
        fence = i
        previous = next((lines[k].strip() for k in range(fence - 1, -1, -1) if lines[k].strip()), "")
        body = []
        i += 1
        while i < len(lines) and lines[i].strip() != "```":
            body.append(lines[i])
            i += 1
        i += 1
        if previous == NOT_RUN_MARKER:
            continue
        commands = []
        for text in body:
            if text.startswith("$ "):
                commands.append(Command(text[2:]))
            elif commands:
                commands[-1].expected.append(text)
        if commands:
            examples.append(Example(path, fence + 1, commands))
    return examples


def normalise(text: str, scratch: str = "") -> str:
    if scratch:
        text = text.replace(scratch + "/tmp/", "/tmp/").replace(scratch + "/", "").replace(scratch, ".")
    text = re.sub(r"\bin \d+(\.\d+)? s\b", "in <time> s", text)
    text = re.sub(r"\bsphdeck \d+\.\d+\.\d+\b", "sphdeck <version>", text)
    return "\n".join(line.rstrip() for line in text.splitlines())


def line_matches(pattern: str, actual: str) -> bool:
    if pattern.endswith(ELLIPSIS) and pattern != ELLIPSIS:
        return actual.startswith(pattern[: -len(ELLIPSIS)])
    return pattern == actual


def output_matches(expected: list, actual: list) -> bool:
    """Glob-like matching with `...` lines standing for any run of lines (memoised, so linear-ish)."""
    memo = {}

    def match(e: int, a: int) -> bool:
        key = (e, a)
        if key in memo:
            return memo[key]
        if e == len(expected):
            result = a == len(actual)
        elif expected[e] == ELLIPSIS:
            result = any(match(e + 1, k) for k in range(a, len(actual) + 1))
        else:
            result = a < len(actual) and line_matches(expected[e], actual[a]) and match(e + 1, a + 1)
        memo[key] = result
        return result

    return match(0, 0)


def uses_python_module(example: Example) -> bool:
    return any("import sphdeck" in command.text for command in example.commands)


def make_scratch(repo: Path, sphdeck: Path, python: Path = None) -> tuple:
    scratch = tempfile.mkdtemp(prefix="sphdeck-readme-")
    shutil.copytree(repo / "decks", Path(scratch) / "decks", symlinks=True)
    (Path(scratch) / "docs").mkdir()
    (Path(scratch) / "tmp").mkdir()
    bin_dir = Path(scratch) / ".bin"
    bin_dir.mkdir()
    (bin_dir / "sphdeck").symlink_to(sphdeck.resolve())
    if python:
        (bin_dir / "python3").symlink_to(python)
    return scratch, bin_dir


def run_example(example: Example, repo: Path, sphdeck: Path, verbose: bool = False, python: Path = None,
                pythonpath: Path = None) -> list:
    """The drifted commands of one example as (command, expected, actual) triples."""
    scratch, bin_dir = make_scratch(repo, sphdeck, python)
    env = dict(os.environ, PATH=f"{bin_dir}:{os.environ.get('PATH', '')}", NO_COLOR="1", COLUMNS="120")
    if pythonpath:
        env["PYTHONPATH"] = str(pythonpath.resolve())
        env["PYTHONDONTWRITEBYTECODE"] = "1"
    env.pop("CI", None)  # progress lines follow the terminal rules, not CI's
    cwd = scratch
    drifted = []
    try:
        for command in example.commands:
            text = command.text.replace("/tmp/", scratch + "/tmp/")
            cd = re.fullmatch(r"cd\s+(\S+)", text.strip())
            if cd:
                cwd = os.path.normpath(os.path.join(cwd, cd.group(1)))
                actual = ""
            else:
                started = time.monotonic()
                try:
                    done = subprocess.run(["bash", "-c", text], cwd=cwd, env=env, stdin=subprocess.DEVNULL,
                                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                          timeout=COMMAND_TIMEOUT_S)
                    actual = done.stdout.decode("utf-8", "replace")
                except subprocess.TimeoutExpired:
                    actual = f"(timed out after {COMMAND_TIMEOUT_S} s)"
                if verbose:
                    print(f"  {time.monotonic() - started:6.2f} s  $ {command.text}", file=sys.stderr)
            actual_lines = normalise(actual, scratch).splitlines() if actual.strip() else []
            expected_lines = normalise("\n".join(command.expected)).splitlines() if command.expected else []
            if not output_matches(expected_lines, actual_lines):
                drifted.append((command.text, expected_lines, actual_lines))
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    return drifted


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sphdeck", required=True, type=Path, help="the binary under test")
    parser.add_argument("--repo", type=Path, default=Path(__file__).resolve().parents[2])
    parser.add_argument("--verbose", action="store_true", help="print each command's time on stderr")
    parser.add_argument("--python", type=Path, help="the python3 the Python module's examples run with")
    parser.add_argument("--pythonpath", type=Path, help="the folder holding the built Python module sphdeck")
    parser.add_argument("files", nargs="*", type=Path, help="Markdown files (default: README.md, docs/*.md)")
    args = parser.parse_args()
    files = args.files or [args.repo / "README.md", *sorted((args.repo / "docs").glob("*.md"))]
    examples = [example for path in files for example in parse_examples(path)]
    skipped = 0
    if not args.pythonpath:
        skipped = sum(1 for example in examples if uses_python_module(example))
        examples = [example for example in examples if not uses_python_module(example)]
    failures = 0
    commands = 0
    for example in examples:
        commands += len(example.commands)
        for text, expected, actual in run_example(example, args.repo, args.sphdeck, args.verbose, args.python,
                                                  args.pythonpath):
            failures += 1
            where = os.path.relpath(example.source, args.repo)
            print(f"{where}:{example.line}: `$ {text}` prints other than the example shows")
            print("  shown:")
            print("\n".join("    " + line for line in expected) or "    (nothing)")
            print("  printed:")
            print("\n".join("    " + line for line in actual) or "    (nothing)")
    print(f"{commands - failures} passed, {failures} failed "
          f"({len(examples)} console examples, {commands} commands)")
    if skipped:
        print(f"{skipped} examples of the Python module skipped: no --pythonpath (the module is not built)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
