"""The issue's done-when test: for every deck of decks/, sphdeck.check(path) gives the findings of
`sphdeck check --format json path`, field by field, and the same errors where the command exits 2.

The command line checks all decks in one run (each named deck is checked as when named alone, in the
order named), while the module checks them on a pool of threads (check() releases the GIL)."""
import concurrent.futures
import json
import os
import re
import subprocess

import sphdeck
from conftest import ROOT, sphdeck_binary

DECK_SUFFIXES = {".k", ".key", ".dyn", ".inc", ".rad"}


def shipped_decks() -> list:
    return sorted(str(p.relative_to(ROOT)) for p in (ROOT / "decks").rglob("*")
                  if p.suffix in DECK_SUFFIXES and p.is_file())


def module_outcome(path: str):
    """The module's findings for one deck, or the sphdeck.Error it raised."""
    try:
        return sphdeck.check(path)
    except sphdeck.Error as error:
        return error


def differences(decks: list, outcomes: list, cli_findings: list, cli_errors: list) -> list:
    """Where the module's findings (per deck, in deck order) and errors differ from the command line's."""
    problems = []
    errors = [str(o) for o in outcomes if isinstance(o, sphdeck.Error)]
    if errors != cli_errors:
        problems.append(f"errors differ: command line {cli_errors}, module {errors}")
    at = 0
    for deck, outcome in zip(decks, outcomes):
        if isinstance(outcome, sphdeck.Error):
            continue
        for k, finding in enumerate(outcome):
            if at >= len(cli_findings):
                problems.append(f"{deck}: finding {k} ({finding}) is not in the command line's report")
                return problems
            expected = cli_findings[at]
            at += 1
            for field, value in expected.items():
                got = getattr(finding, field, "(no such attribute)")
                if got != value:
                    problems.append(f"{deck}: finding {k} ({expected['code']}), {field}: command line {value!r}, "
                                    f"module {got!r}")
            if set(finding.to_dict()) != set(expected):
                problems.append(f"{deck}: finding {k}: fields {sorted(finding.to_dict())}, command line "
                                f"{sorted(expected)}")
            if problems:
                return problems  # the first difference; the ones after it follow from it
    if at != len(cli_findings):
        problems.append(f"the command line reports {len(cli_findings) - at} finding(s) more, from "
                        f"{cli_findings[at]['file']}:{cli_findings[at]['line']} ({cli_findings[at]['code']}) on")
    return problems


def cli_report(decks: list) -> tuple:
    """The command line's findings for the decks, in deck order, and its error messages."""
    done = subprocess.run([sphdeck_binary(), "check", "--format", "json", "--exit-zero", *decks],
                          capture_output=True, text=True, cwd=ROOT)
    assert done.returncode in (0, 2), done.stderr
    errors = re.findall(r"^sphdeck: error: (.*)$", done.stderr, flags=re.M)
    return json.loads(done.stdout)["diagnostics"], errors


def test_every_shipped_deck_gives_the_command_lines_findings():
    decks = shipped_decks()
    assert len(decks) > 300, "the decks of decks/ are found"
    with concurrent.futures.ThreadPoolExecutor(max_workers=min(8, os.cpu_count() or 1)) as pool:
        module_run = pool.map(module_outcome, decks)
        cli_findings, cli_errors = cli_report(decks)  # meanwhile
        outcomes = list(module_run)
    assert sum(len(o) for o in outcomes if isinstance(o, list)) > 300, "the decks have findings to compare"
    assert differences(decks, outcomes, cli_findings, cli_errors) == []


def test_the_comparison_fails_when_the_module_drops_or_changes_a_finding():
    decks = ["decks/demo/sph_mistakes_2d.k", "decks/demo/dam_break_2d.k"]
    cli_findings, cli_errors = cli_report(decks)
    outcomes = [module_outcome(d) for d in decks]
    assert len(outcomes[0]) >= 3
    assert differences(decks, outcomes, cli_findings, cli_errors) == []
    for dropped in (0, len(outcomes[0]) - 1):
        fewer = [outcomes[0][:dropped] + outcomes[0][dropped + 1:], outcomes[1]]
        assert differences(decks, fewer, cli_findings, cli_errors) != [], f"finding {dropped} dropped"
    changed = outcomes[0][0].to_dict()
    changed["column"] += 1
    cli_changed = [changed] + cli_findings[1:]
    assert differences(decks, outcomes, cli_changed, cli_errors) != [], "a column changed"
    assert differences(decks, outcomes, cli_findings, cli_errors + ["cannot open 'x.k'"]) != [], "an error more"
