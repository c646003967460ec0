"""The module's calls on decks given as paths and as text, against what the command line does with them."""
import json
import pathlib
import re

import pytest

import sphdeck
from conftest import run_cli


def fixed_columns(*values) -> str:
    """One card line as pydyna writes it: each value right-aligned in a 10-character field."""
    return "".join(f"{v:>10}" for v in values)


def pydyna_like_deck(iavis: int) -> str:
    """A small 2D deck written the way ansys-dyna-core's Deck.write() lays keywords out ($# headers)."""
    lines = ["*KEYWORD",
             "*CONTROL_TERMINATION", "$#  endtim    endcyc     dtmin    endeng    endmas",
             fixed_columns(0.5, 0, 0.0, 0.0, 0.0),
             "*CONTROL_SPH", "$#    ncbs     boxid        dt      idim    memory      form     start      maxv",
             fixed_columns(1, 0, "1.0E+20", 2, 150, 0, 0.0, "1.0E+15"),
             "$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp",
             fixed_columns(0, 0, 0, 0, 0, 0, iavis, 100),
             "*SECTION_SPH", "$#   secid      cslh      hmin      hmax    sphini     death     start",
             fixed_columns(1, 1.2, 0.2, 2.0, 0.0, "1.0E+20", 0.0),
             "*PART", "$#                                                                         title", "water",
             "$#     pid     secid       mid     eosid", fixed_columns(1, 1, 1, 1),
             "*MAT_NULL", "$#     mid        ro", fixed_columns(1, 1000.0),
             "*EOS_MURNAGHAN", "$#   eosid     gamma        k0", fixed_columns(1, 7.0, 340000.0),
             "*NODE"]
    nodes = [(1 + i + 5 * j, 0.01 + 0.02 * i, 0.01 + 0.02 * j) for j in range(5) for i in range(5)]
    lines += [f"{n:>8}{x:>16.3f}{y:>16.3f}{0.0:>16.1f}" for n, x, y in nodes]
    lines += ["*ELEMENT_SPH"] + [f"{n:>8}{1:>8}{8.0e-4:>16.4e}" for n, _, _ in nodes]
    return "\n".join(lines + ["*END"]) + "\n"


def cli_json(*args, input_text=None) -> list:
    done = run_cli("check", "--format", "json", *args, input_text=input_text)
    assert done.returncode in (0, 1), done.stderr
    return json.loads(done.stdout)["diagnostics"]


def test_a_pydyna_like_text_deck_is_checked_with_line_and_column():
    text = pydyna_like_deck(iavis=1)
    findings = sphdeck.check(text)
    by_code = {f.code: f for f in findings}
    assert "SPH030" in by_code, [str(f) for f in findings]
    iavis = by_code["SPH030"]
    card_line = text.splitlines().index(fixed_columns(0, 0, 0, 0, 0, 0, 1, 100)) + 1
    assert (iavis.file, iavis.line, iavis.column, iavis.severity) == ("deck.k", card_line, 70, "error")
    assert str(iavis).startswith(f"deck.k:{card_line}:70: error: IAVIS 1")
    # The same findings as the command line reading the text on standard input.
    assert [f.to_dict() for f in findings] == cli_json("-", "--stdin-filename", "deck.k", input_text=text)
    assert "SPH030" not in {f.code for f in sphdeck.check(pydyna_like_deck(iavis=0))}


def test_text_is_named_and_selected_as_told():
    text = pydyna_like_deck(iavis=1)
    assert {f.file for f in sphdeck.check(text, name="tank.k")} == {"tank.k"}
    assert [f.code for f in sphdeck.check(text, select="SPH030")] == ["SPH030"]
    assert [f.code for f in sphdeck.check(text, select=["SPH030", "DK001"])] == ["SPH030"]
    assert "SPH030" not in {f.code for f in sphdeck.check(text, ignore=["SPH030"])}
    assert sphdeck.check(text, format="lsdyna") == sphdeck.check(text)


def test_a_deck_with_includes_reports_the_included_files_line():
    deck = "decks/tests/dk/DK017_fires.k"
    findings = sphdeck.check(deck)
    assert [f.to_dict() for f in findings] == cli_json(deck)
    included = [f for f in findings if f.file == "decks/tests/dk/include/dk017_f_nodes.inc"]
    assert included and included[0].code == "DK017"
    assert included[0].include_chain == [{"file": deck, "line": 4}]


def test_a_text_deck_finds_its_includes_from_its_name(tmp_path: pathlib.Path):
    text = pydyna_like_deck(iavis=1)
    head, nodes = text.split("*NODE\n")
    (tmp_path / "particles.k").write_text("*KEYWORD\n*NODE\n" + nodes)
    main = head + "*INCLUDE\nparticles.k\n*END\n"
    findings = sphdeck.check(main, name=str(tmp_path / "main.k"))
    assert "SPH030" in {f.code for f in findings}
    assert not any(f.code.startswith("REF") for f in findings), [str(f) for f in findings]
    # Without the include file, the particles' part has none: the missing include is reported.
    missing = sphdeck.check(main, name=str(tmp_path / "elsewhere" / "main.k"))
    assert any("particles.k" in f.message for f in missing), [str(f) for f in missing]


def test_an_include_file_is_checked_as_part_of_the_decks_that_include_it():
    include = "decks/tests/dk/include/dk017_f_nodes.inc"
    findings = sphdeck.check(pathlib.Path(include))
    assert [f.to_dict() for f in findings] == cli_json(include)
    assert findings and all(f.file == include and f.include_chain for f in findings)


def test_exit_2_conditions_raise_sphdeck_error_with_the_command_lines_message(tmp_path: pathlib.Path):
    with pytest.raises(sphdeck.Error) as missing:
        sphdeck.check("no_such_deck.k")
    cli = run_cli("check", "no_such_deck.k")
    assert cli.returncode == 2
    assert f"sphdeck: error: {missing.value}" in cli.stderr
    assert str(missing.value) == "cannot open 'no_such_deck.k': No such file or directory"

    bad = tmp_path / "sphdeck.toml"
    bad.write_text("select = [\n")
    deck = tmp_path / "deck.k"
    deck.write_text(pydyna_like_deck(iavis=0))
    with pytest.raises(sphdeck.Error) as config:
        sphdeck.check(deck)
    cli = run_cli("check", str(deck))
    assert cli.returncode == 2 and cli.stderr.strip() == str(config.value)
    with pytest.raises(sphdeck.Error, match=str(bad)):
        sphdeck.check(pydyna_like_deck(iavis=0), config=bad)
    without = sphdeck.check(deck, config=False)
    assert [(f.code, f.line) for f in without] == [(f.code, f.line)
                                                 for f in sphdeck.check(pydyna_like_deck(iavis=0), config=False)]

    with pytest.raises(sphdeck.Error, match="unknown rule 'XX999'"):
        sphdeck.check(deck, select="XX999")
    with pytest.raises(sphdeck.Error, match="unknown keyword"):
        sphdeck.keyword("*CONTROL_SPHH")
    with pytest.raises(sphdeck.Error, match="format"):
        sphdeck.check(pydyna_like_deck(iavis=0), format="nastran")
    with pytest.raises(TypeError):
        sphdeck.check(42)
    assert issubclass(sphdeck.Error, Exception)


FIXABLE = ("*KEYWORD\n*CONTROL_TERMINATION\n         1.0         0\n"  # shifted 2 columns: a safe fix
           "*DATABASE_GLSTATT\n       0.1\n*END\n")  # a typo: *DATABASE_GLSTAT is a judgement, an unsafe fix


def test_fix_mends_text_as_check_fix_mends_the_file(tmp_path: pathlib.Path):
    for unsafe, flags in ((False, ["--fix"]), (True, ["--fix", "--unsafe-fixes"])):
        copy = tmp_path / f"deck_{unsafe}.k"
        copy.write_text(FIXABLE)
        run_cli("check", *flags, str(copy))
        fixed = sphdeck.fix(FIXABLE, unsafe=unsafe)
        assert fixed == copy.read_text()
        assert fixed != FIXABLE and sphdeck.fix(fixed, unsafe=unsafe) == fixed
    assert "*DATABASE_GLSTATT" in sphdeck.fix(FIXABLE)
    assert [f.code for f in sphdeck.check(FIXABLE)] == ["DK029", "DK001"]
    assert not {"DK029", "DK001"} & {f.code for f in sphdeck.check(sphdeck.fix(FIXABLE, unsafe=True))}


def test_format_gives_what_sphdeck_format_writes():
    text = "*keyword\n*control_termination\n1.0       0\n*END\n"
    formatted = sphdeck.format(text)
    cli = run_cli("format", "-", "--stdin-filename", "deck.k", input_text=text)
    assert formatted == cli.stdout
    assert formatted != text and sphdeck.format(formatted) == formatted


def test_keyword_gives_the_cards_and_columns():
    layout = sphdeck.keyword("*CONTROL_SPH")
    first = layout["cards"][0]["fields"][0]
    assert layout["keyword"] == "*CONTROL_SPH"
    assert (first["name"], first["columns"]) == ("NCBS", [1, 10])
    long_layout = sphdeck.keyword("CONTROL_SPH", card_format="long")
    assert long_layout["cards"][0]["fields"][0]["columns"] == [1, 20]


def test_smooth_gives_the_parts_of_smooth_format_json(tmp_path: pathlib.Path):
    deck = "decks/demo/dam_break_2d.k"
    parts = sphdeck.smooth(deck)
    cli = run_cli("smooth", "--format", "json", deck)
    assert cli.returncode == 0, cli.stderr
    assert parts == json.loads(cli.stdout)["parts"]
    assert parts and all(isinstance(p, dict) for p in parts)
    # A path outside the working directory: the module is not confined as the MCP server is.
    elsewhere = tmp_path / "copy.k"
    elsewhere.write_text(pathlib.Path(deck).read_text())
    assert sphdeck.smooth(elsewhere) == parts
    with pytest.raises(sphdeck.Error, match="no SPH particles"):
        sphdeck.smooth("*KEYWORD\n*CONTROL_TERMINATION\n0.5\n*END\n")


def test_rules_is_the_catalogue():
    rules = sphdeck.rules()
    listing = run_cli("rules").stdout
    assert {r["code"] for r in rules} == set(re.findall(r"^([A-Z]{2,3}\d{3})\b", listing, flags=re.M))
    sph030 = next(r for r in rules if r["code"] == "SPH030")
    assert (sph030["name"], sph030["severity"]) == ("iavis-solid-in-2d", "error")


def test_findings_are_values():
    text = pydyna_like_deck(iavis=1)
    first, again = sphdeck.check(text), sphdeck.check(text)
    assert first == again and first[0] is not again[0]
    assert repr(first[0]).startswith("<Finding deck.k:")
    assert sphdeck.__version__ == run_cli("--version").stdout.split()[-1]
