"""Nothing ignored in silence (issue 34): an option given twice is refused, not the last one
kept; an option that does not apply where it was given is refused in one line; a table is
never written over a sidecar."""

import argparse
import json

import pytest

from studies.cli import build_parser, main

REPEATABLE = (argparse._StoreTrueAction, argparse._AppendAction, argparse._VersionAction,
              argparse._HelpAction)  # fmt: skip
"""Flags whose repeating means nothing more (store_true) or is their documented meaning
(``compare --racket A --racket B``)."""


def run(capsys, *args):
    status = main(list(args))
    out, err = capsys.readouterr()
    return status, out, err


def _value(action) -> list[str]:
    """Words a parser accepts for ``action`` once."""
    if action.choices:
        word = str(next(iter(action.choices)))
    elif hasattr(action.type, "names"):  # a preset's name (or a TOML file)
        word = action.type.names[0]
    elif action.type in (int, float):
        word = "1"
    else:
        word = "x.csv" if action.metavar == "FILE" else "x"
    count = action.nargs if isinstance(action.nargs, int) else 1
    return [word] * count


def _options():
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    for command, p in sub.choices.items():
        for action in p._actions:
            if action.option_strings and not isinstance(action, REPEATABLE):
                yield command, action.option_strings[0], _value(action)


OPTIONS = list(_options())


def test_the_walk_finds_the_options_of_every_kind():
    flags = {(command, flag) for command, flag, _ in OPTIONS}
    for seen in [("sweep", "--f1"), ("sweep", "--ra"), ("sweep", "--speed-mph"),
                 ("map", "--grid"), ("serve", "--position"), ("map", "--workers"),
                 ("drop", "--lead"), ("compare", "--support")]:  # fmt: skip
        assert seen in flags
    assert len(OPTIONS) > 100


@pytest.mark.parametrize(("command", "flag", "value"), OPTIONS,
                         ids=[f"{c} {f}" for c, f, _ in OPTIONS])  # fmt: skip
def test_every_option_given_twice_is_refused_in_one_line(command, flag, value, capsys):
    with pytest.raises(SystemExit) as stop:
        main([command, flag, *value, flag, *value])
    err = capsys.readouterr().err
    assert stop.value.code == 2
    assert f"{flag} given twice" in err and len(err.strip().splitlines()) == 1


def test_a_many_valued_option_twice_says_to_give_its_values_once(capsys):
    with pytest.raises(SystemExit):
        main(["sweep", "--f1", "100", "--f1", "120"])
    assert "give all its values after one --f1" in capsys.readouterr().err


def test_a_racket_given_twice_to_compare_is_its_documented_meaning():
    args = build_parser().parse_args(
        ["compare", "--racket", "paper", "--racket", "pure-drive-2021"]
    )
    assert args.racket == ["paper", "pure-drive-2021"]


@pytest.mark.parametrize(
    ("words", "flag"),
    [
        (["ball", "--list", "--plot", "p.png"], "--plot"),
        (["ball", "--list", "--speeds", "10", "20"], "--speeds"),
        (["ball", "--list", "--speeds-mph", "30"], "--speeds-mph"),
        (["ball", "--list", "itf-type-1"], "the ball 'itf-type-1'"),
        (["drop", "--racket", "paper"], "--racket"),
        (["drop", "--onto", "floor", "--tension-lb", "55"], "--tension-lb"),
        (["drop", "--string-stiffness", "30000"], "--string-stiffness"),
        (["drop", "--lead", "5@12"], "--lead"),
        (["drop", "--onto", "strings", "--lead", "5@12"], "--lead"),
        (["modes", "--tension-lb", "55"], "--tension-lb"),
        (["modes", "--string-stiffness", "30000"], "--string-stiffness"),
        (["modes", "--support", "hand-held"], "--support"),
        (["modes", "--support", "hand-held", "--grip", "tight"], "--support"),
        (["map", "--field", "e"], "--field"),
        (
            ["sweetspots", "--support", "clamped-head", "--hand-cm-from-tip", "60"],
            "--hand-cm-from-tip",
        ),
        (["feel", "--racket", "paper", "--offset", "2"], "--offset"),
        (["sweep", "--racket", "paper", "--offset", "0", "--points", "3"], "--offset"),
        (["collide", "--b", "wall", "--vb", "0"], "--vb"),
        (["collide", "--b", "wall", "--vb-kmh", "3"], "--vb-kmh"),
    ],
)
def test_an_option_that_does_not_apply_is_refused_in_one_line(words, flag, tmp_path,
                                                                monkeypatch, capsys):  # fmt: skip
    monkeypatch.chdir(tmp_path)
    status, out, err = run(capsys, *words)
    assert status == 2 and out == ""
    assert err.strip().splitlines() == [err.strip()]
    assert f"error: {flag} does not apply" in err
    assert list(tmp_path.iterdir()) == []  # nothing written


def test_the_same_options_where_they_apply_run(tmp_path, capsys):
    plot = tmp_path / "b.png"
    assert run(capsys, "ball", "itf-type-1", "--speeds", "10", "20", "--plot", str(plot))[0] == 0
    assert plot.exists()
    presets = tmp_path / "presets.csv"
    assert run(capsys, "ball", "--list", "--out", str(presets))[0] == 0 and presets.exists()
    status, out, _ = run(capsys, "drop", "--onto", "racket", "--lead", "5@12")
    assert status == 0 and "lying free" in out
    assert run(capsys, "drop", "--onto", "strings", "--tension-lb", "50")[0] == 0
    assert run(capsys, "map", "--grid", "4", "4", "--field", "e",
               "--plot", str(tmp_path / "m.png"))[0] == 0  # fmt: skip


@pytest.mark.parametrize("name", ["t.csv.meta.json", "t.META.JSON"])
def test_a_table_is_never_written_over_a_sidecar(name, tmp_path, capsys):
    table = tmp_path / "t.csv"
    assert run(capsys, "modes", "--count", "2", "--out", str(table))[0] == 0
    sidecar = tmp_path / "t.csv.meta.json"
    before = sidecar.read_text()
    status, out, err = run(capsys, "modes", "--count", "2", "--out", str(tmp_path / name))
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert "--out" in err and "sidecar" in err
    assert sidecar.read_text() == before
    assert json.loads(before)["command"][0] == "modes"


def test_a_sidecar_never_overwrites_another_output_of_the_same_run(tmp_path, capsys):
    summary, history = tmp_path / "c.json", tmp_path / "c.json.meta.json"
    status, _, err = run(capsys, "collide", "--out", str(summary), "--history", str(history))
    assert status == 2 and "sidecar" in err and len(err.strip().splitlines()) == 1
    assert list(tmp_path.iterdir()) == []
