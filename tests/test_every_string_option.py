"""Every string option does what it says in every command that takes it, or is refused
(issue 45): each option, given alone, changes the command's table (``--out``), and an option a
command cannot honour exits 2 with one line naming it.  One parametrised test over the
commands and the options, so that a new command or option is checked as it lands.
"""

import pandas as pd
import pytest

from studies.cli import main

COMMANDS = {
    "sweep": ["sweep", "--points", "3"],
    "map": ["map", "--grid", "4", "4"],
    "sweetspots": ["sweetspots"],
    "specs": ["specs", "--count", "2"],
    "feel": ["feel", "--duration-ms", "10"],
    "compare": ["compare", "--points", "3"],
    "serve": ["serve"],
    "drop": ["drop", "--onto", "racket"],
    "strings": ["strings", "--strings", "polyester", "natural-gut"],
    "stroke": ["stroke", "topspin-forehand"],
}
"""Each command that takes the string options, small."""

OPTIONS = {
    "string": ["--string", "natural-gut"],
    "gauge": ["--gauge", "1.40"],
    "pattern": ["--pattern", "18x20"],
    "played": ["--played"],
    "tension": ["--tension-lb", "45"],
    "tension-kg": ["--tension-kg", "20"],
    "stiffness": ["--string-stiffness", "3.6e4"],
    "dt": ["--string-bed-dt", "36"],
}
"""Each string option, at a value away from the default racket's."""

PRINTED = {"specs": "string bed:"}
"""The commands whose strings are in what they print, not in their table, and where that
starts (``specs``: its table is the effective mass along the strings, Eq. 20, which no
string changes; it prints the bed)."""

REFUSED = {("strings", "string"): "--strings"}
"""The options a command refuses, and a word its one line says: ``strings`` strings each
of ``--strings`` in turn, so ``--string`` would be dropped."""

_BASE = {}


def _table(command, extra, tmp_path, capsys):
    """The command's table (``--out``), or what it prints for :data:`PRINTED`."""
    out = tmp_path / f"{command}{len(list(tmp_path.iterdir()))}.json"
    assert main([*COMMANDS[command], *extra, "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    return printed[printed.index(PRINTED[command]) :] if command in PRINTED else pd.read_json(out)


@pytest.mark.parametrize("option", OPTIONS)
@pytest.mark.parametrize("command", COMMANDS)
def test_each_string_option_changes_each_command_s_rows(command, option, tmp_path, capsys):
    if (command, option) in REFUSED:
        assert main([*COMMANDS[command], *OPTIONS[option]]) == 2
        said = capsys.readouterr().err.strip()
        assert OPTIONS[option][0] in said and REFUSED[command, option] in said
        assert "\n" not in said
        return
    if command not in _BASE:
        _BASE[command] = _table(command, [], tmp_path, capsys)
    base, changed = _BASE[command], _table(command, OPTIONS[option], tmp_path, capsys)
    if command in PRINTED:
        assert changed != base, f"{OPTIONS[option]} changed nothing"
        return
    numbers = base.select_dtypes("number").columns
    assert list(changed.columns) == list(base.columns)
    assert not changed[numbers].equals(base[numbers]), f"{OPTIONS[option]} changed nothing"
