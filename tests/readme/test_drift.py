#!/usr/bin/env python3
"""The README example test must fail when an example drifts: run_examples.py on a copy of one README
example passes, and on the same example with one printed line edited, one line added or the exit code's
line dropped, fails. Also the matcher's `...` rules on their own."""
import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from run_examples import output_matches, parse_examples  # noqa: E402


def run_on(markdown: str, sphdeck: Path, repo: Path) -> int:
    with tempfile.TemporaryDirectory() as folder:
        page = Path(folder) / "page.md"
        page.write_text(markdown, encoding="utf-8")
        return subprocess.run([sys.executable, str(HERE / "run_examples.py"), "--sphdeck", str(sphdeck),
                               "--repo", str(repo), str(page)], stdout=subprocess.DEVNULL).returncode


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--sphdeck", required=True, type=Path)
    parser.add_argument("--repo", type=Path, default=HERE.parents[1])
    args = parser.parse_args()
    failures = []

    def expect(condition: bool, what: str):
        if not condition:
            failures.append(what)

    expect(output_matches(["a", "...", "d"], ["a", "b", "c", "d"]), "'...' stands for lines")
    expect(output_matches(["a", "...", "b"], ["a", "b"]), "'...' stands for no line too")
    expect(not output_matches(["a", "d"], ["a", "b", "d"]), "a line the example leaves out is drift")
    expect(output_matches(["steps: 12 ..."], ["steps: 12 wall 0.3 s"]), "a line ending in ... is a prefix")
    expect(not output_matches([], ["x"]), "no line shown means nothing printed")

    # The format example of the README (its first command writes the deck, the next ones read it).
    readme = (args.repo / "README.md").read_text(encoding="utf-8")
    examples = [e for e in parse_examples(args.repo / "README.md")
                if any("sphdeck format --check t.k" in c.text for c in e.commands)]
    expect(len(examples) == 1, "the README's format example is there")
    if examples:
        lines = readme.splitlines()
        start = examples[0].line - 1
        end = next(k for k in range(start + 1, len(lines)) if lines[k].strip() == "```")
        block = lines[start:end + 1]
        expect(run_on("\n".join(block) + "\n", args.sphdeck, args.repo) == 0, "the example as written passes")
        at = next(k for k, line in enumerate(block) if line == "exit 1")
        edited = block[:at] + ["exit 0"] + block[at + 1:]
        expect(run_on("\n".join(edited) + "\n", args.sphdeck, args.repo) == 1, "an edited line fails")
        added = block[:at] + ["one line more"] + block[at:]
        expect(run_on("\n".join(added) + "\n", args.sphdeck, args.repo) == 1, "an added line fails")
        dropped = block[:at] + block[at + 1:]
        expect(run_on("\n".join(dropped) + "\n", args.sphdeck, args.repo) == 1, "a dropped line fails")
        marked = ["<!-- example: not run -->"] + edited
        expect(run_on("\n".join(marked) + "\n", args.sphdeck, args.repo) == 0, "a marked example is not run")

    for what in failures:
        print(f"FAILED: {what}")
    checks = 10
    print(f"{checks - len(failures)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
