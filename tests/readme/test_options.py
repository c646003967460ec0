#!/usr/bin/env python3
"""Every option of every subcommand's --help is in README.md's section of that subcommand, and every option
a section's option table names is one the subcommand has: the manual and the binary cannot disagree.

A section is the text from `### \\`sphdeck CMD ...\\`` to the next `###`/`##` heading (`rule` and `rules`
share one). An option counts as documented when the section names it in backticks (`--name`, `--name X`,
`-I, --include-path`). Also checks the counts the README quotes against the binary (keyword layouts)."""
import argparse
import re
import subprocess
import sys
from pathlib import Path

COMMANDS = ["check", "rule", "rules", "keyword", "format", "dump", "diff", "smooth", "sol2sph", "run", "verify",
            "lsp", "mcp"]
NOT_DOCUMENTED = {"--help"}  # every command has it; the README says so once


def help_options(sphdeck: Path, command: str) -> set:
    text = subprocess.run([str(sphdeck), command, "--help"], capture_output=True, text=True).stdout
    options = set()
    in_options = False
    for line in text.splitlines():
        if line.startswith("Options:"):
            in_options = True
            continue
        if in_options and re.match(r"^\S", line):
            in_options = False
        match = re.match(r"^  (-[\w-]+(?:,\s*-[\w-]+)*)", line) if in_options else None
        if match:
            names = [n.strip() for n in match.group(1).split(",")]
            longest = max(names, key=len)
            if longest not in NOT_DOCUMENTED:
                options.add(longest)
    return options


def sections(readme: str) -> dict:
    """Command -> the README text of its section."""
    out = {}
    current = None
    for line in readme.splitlines():
        heading = re.match(r"^###\s+`sphdeck (\w+)", line)
        if heading:
            current = heading.group(1)
            out[current] = ""
            continue
        if re.match(r"^##", line):
            current = None
        if current:
            out[current] += line + "\n"
    if "rule" in out:
        out["rules"] = out["rule"]
    return out


def table_options(section: str) -> set:
    found = set()
    for line in section.splitlines():
        if line.startswith("| `-"):
            first_cell = line.split("|")[1]
            found.update(re.findall(r"`(--?[\w-]+)", first_cell))
    return found


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--sphdeck", required=True, type=Path)
    parser.add_argument("--readme", type=Path, default=Path(__file__).resolve().parents[2] / "README.md")
    args = parser.parse_args()
    readme = args.readme.read_text(encoding="utf-8")
    by_command = sections(readme)
    problems = []
    checks = 0
    for command in COMMANDS:
        section = by_command.get(command)
        if section is None:
            problems.append(f"README has no section `sphdeck {command}`")
            continue
        options = help_options(args.sphdeck, command)
        checks += 1
        if not options and command not in ("rule", "rules", "lsp", "mcp"):
            problems.append(f"`sphdeck {command} --help` lists no options (could not be read)")
        prose = re.sub(r"```.*?```", "", section, flags=re.S)
        quoted_spans = re.findall(r"`([^`]+)`", prose)
        quoted_spans += re.findall(r"^\$ (.*)$", section, flags=re.M)  # the examples' command lines
        for option in sorted(options):
            checks += 1
            token = re.compile(r"(?<![\w-])" + re.escape(option) + r"(?![\w-])")
            if not any(token.search(span) for span in quoted_spans):
                problems.append(f"`sphdeck {command} {option}` is not in README's section of {command}")
        all_spellings = set(options)
        for line in subprocess.run([str(args.sphdeck), command, "--help"], capture_output=True,
                                   text=True).stdout.splitlines():
            all_spellings.update(re.findall(r"(?<![\w-])(--?[A-Za-z][\w-]*)", line.split("  ")[1] if line.startswith("  -") and len(line.split("  ")) > 1 else ""))
        for option in sorted(table_options(section)):
            checks += 1
            if option not in all_spellings and option != "--help":
                problems.append(f"README's table of {command} names {option}, which `sphdeck {command}` does not have")
    # The counts the README quotes, from the binary.
    listing = subprocess.run([str(args.sphdeck), "keyword", "--list"], capture_output=True, text=True).stdout
    dyna = sum(1 for line in listing.splitlines() if line.startswith("*"))
    checks += 1
    quoted = re.findall(r"\(([\d,]+) in all, `sphdeck keyword --list`\)", readme)
    if not quoted:
        problems.append("README no longer quotes the count of `sphdeck keyword --list` (this test reads it)")
    for number in quoted:
        if int(number.replace(",", "")) != dyna:
            problems.append(f"README quotes layouts of {number} LS-DYNA keywords; `keyword --list` has {dyna}")
    # One project URL: the rule pages the binary links (`sphdeck rule`, SARIF, the editor) and the README's.
    page = subprocess.run([str(args.sphdeck), "rule", "SPH030"], capture_output=True, text=True).stdout
    linked = re.findall(r"(https://github\.com/[\w.-]+/[\w.-]+)/blob/", page)
    checks += 1
    if not linked:
        problems.append("`sphdeck rule SPH030` prints no rule-page link")
    else:
        for url in sorted(set(re.findall(r"https://github\.com/[\w<>.-]+/sphdeck\b", readme))):
            if url != linked[0]:
                problems.append(f"README names {url}; the binary links rule pages under {linked[0]}")
    for problem in problems:
        print(problem)
    print(f"{checks - len(problems)} passed, {len(problems)} failed")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
