"""The ``racket-impact`` command line.

Subcommands: ``paper``, ``sweep``, ``serve``, ``stroke``, ``collide``, ``modes``, ``specs``,
``compare``, ``strings``, ``bat`` and more (``racket-impact --help``).
Rackets and balls are presets or TOML files (:mod:`studies.config`).  Tables go to CSV,
JSON or Parquet by the file's extension, plots to PNG, SVG or PDF.  Bad input prints one
line naming the problem and exits with status 2.

One module per command family (each adds its subcommands' parsers and holds their
handlers), :mod:`studies.cli.options` for the options they share, :mod:`studies.cli.files`
for the files they write, :mod:`studies.cli.runner` for running a parsed command; here the
parser, :func:`main` and ``rerun`` (which replays a command through the whole parser).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ball import DEFAULT_BALL
from common.version import __version__
from studies.cli import (
    app,
    balls,
    bat,
    compare,
    court,
    face,
    paper,
    rackets,
    serve,
    strings,
    stroke,
    sweep,
    validate,
)
from studies.cli.app import cmd_app
from studies.cli.balls import cmd_ball, cmd_collide, cmd_drop
from studies.cli.bat import cmd_bat
from studies.cli.compare import cmd_compare
from studies.cli.court import cmd_court
from studies.cli.face import cmd_map, cmd_sweetspots
from studies.cli.files import _RUN as _RUN  # the run being made (tests read it)
from studies.cli.files import check_outputs, save_plot, write_table
from studies.cli.options import _Parser, _Replay
from studies.cli.paper import cmd_paper, paper_figures
from studies.cli.rackets import cmd_feel, cmd_modes, cmd_specs
from studies.cli.runner import _reader_may_go, _start
from studies.cli.serve import cmd_serve
from studies.cli.strings import cmd_strings
from studies.cli.stroke import cmd_stroke
from studies.cli.sweep import cmd_sweep
from studies.cli.validate import cmd_validate
from studies.outputs import interrupted

__all__ = [
    "TABLE_COMMANDS",
    "build_parser",
    "check_outputs",
    "cmd_app",
    "cmd_ball",
    "cmd_bat",
    "cmd_collide",
    "cmd_compare",
    "cmd_court",
    "cmd_drop",
    "cmd_feel",
    "cmd_map",
    "cmd_modes",
    "cmd_paper",
    "cmd_rerun",
    "cmd_serve",
    "cmd_specs",
    "cmd_strings",
    "cmd_stroke",
    "cmd_sweep",
    "cmd_sweetspots",
    "cmd_validate",
    "main",
    "paper_figures",
    "save_plot",
    "write_table",
]

TABLE_COMMANDS = (
    "sweep", "map", "serve", "collide", "ball", "modes", "specs", "feel", "sweetspots", "compare",
    "validate", "drop", "strings", "stroke", "court", "bat",
)  # fmt: skip
"""The commands that write tables (with sidecars): the only ones ``rerun`` replays."""


def add_rerun(sub) -> None:
    """The ``rerun`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("rerun", help="make a table again from its sidecar (*.meta.json)")
    p.add_argument("sidecar", metavar="FILE", help="a table's sidecar, or the table itself")
    p.set_defaults(func=cmd_rerun)


def cmd_rerun(args) -> int:
    """``racket-impact rerun``: the command recorded in a table's sidecar (checked as
    untrusted input), made again from the sidecar alone (the recorded TOML texts), a
    table-making command only, every file it writes put in the table's own directory.
    """
    import shlex

    from studies.provenance import _restored, rerun_argv, temporary_directory

    folder, moved = Path(args.sidecar).parent, {}
    with temporary_directory() as workdir:
        argv, originals, written = rerun_argv(args.sidecar, workdir)
        if argv[0] not in TABLE_COMMANDS:
            raise ValueError(
                f"{args.sidecar!r}: command {argv[0]!r} makes no table; rerun replays only "
                f"{', '.join(TABLE_COMMANDS)}"
            )
        if "-h" in argv or "--help" in argv:
            raise ValueError(f"{args.sidecar!r}: command asks for help, not a table")
        argv = _serial(argv)
        replay = build_parser(_Replay).parse_args(argv)
        for dest in replay._writes:
            value = getattr(replay, dest)
            if value is None:
                continue
            if Path(value).name in ("", ".", ".."):
                raise ValueError(f"the sidecar's command: --{dest} {value!r} names no file")
            moved[value] = str(folder / Path(value).name)
            setattr(replay, dest, moved[value])
        replay.debug = args.debug
        shown = shlex.join(_restored(word, originals) for word in argv)
        into = "" if folder == Path(".") else f"  (files written into {folder}/)"
        print(f"racket-impact {shown}{into}")  # stdout: stderr is for one line of trouble
        # the new sidecars record where the files went, at the time of the run they reproduce
        return _start(replay, [_restored(word, moved) for word in argv], originals, written)


def _serial(argv: list[str]) -> list[str]:
    """``argv`` without ``--workers``/``--scheduler``: a replay runs in this process (the
    same bits as on any executor; a recorded scheduler may be gone).
    """
    out, skip = [], False
    for word in argv:
        if skip:
            skip = False
        elif word in ("--workers", "--scheduler"):
            skip = True
        elif not word.startswith(("--workers=", "--scheduler=")):
            out.append(word)
    return out


def build_parser(parser_class=_Parser) -> argparse.ArgumentParser:
    """The ``racket-impact`` argument parser, one subcommand per study (``parser_class``:
    :class:`_Replay` for a command recorded in a sidecar).
    """
    from racket import DEFAULT_RACKET
    from studies.sweeps import BALL_SPEED

    parser = parser_class(
        prog="racket-impact",
        description="Ball impacts on a flexible tennis racket. Unless told otherwise, every "
        f"command hits the racket {DEFAULT_RACKET} with the ball {DEFAULT_BALL} at "
        f"{BALL_SPEED:g} m/s (--racket paper --ball paper: the paper's); every position is in "
        "cm from the tip.",
    )
    parser.add_argument(
        "--debug", action="store_true", help="show the traceback of an error (for reports)"
    )
    parser.add_argument("--version", action="version", version=f"racket-impact {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=parser_class)
    for add in (
        paper.add_paper, sweep.add_sweep, face.add_map, serve.add_serve, balls.add_collide,
        balls.add_drop, balls.add_ball, rackets.add_modes, rackets.add_specs, app.add_app,
        add_rerun, rackets.add_feel, face.add_sweetspots, compare.add_compare,
        validate.add_validate, strings.add_strings, stroke.add_stroke, court.add_court,
        bat.add_bat,
    ):  # fmt: skip
        add(sub)
    return parser


def main(argv=None) -> int:
    """Run the CLI; returns the exit status: 0, 1 if ``paper`` finds a claim out of
    tolerance or on an internal error, 2 for bad input, 130 when interrupted (Ctrl-C), 143
    or 129 when stopped by SIGTERM or SIGHUP: one line on stderr each.  Every file a run
    writes is put in place only when it succeeds (:mod:`studies.outputs`).  A reader of the
    output that goes (``racket-impact modes | head -3``) stops nothing.
    """
    argv = sys.argv[1:] if argv is None else list(argv)
    words = [a for a in argv if a != "--debug"]
    with _reader_may_go():
        try:
            parser = build_parser()
            args, extra = parser.parse_known_args(words)
            if extra:  # named with the command (argparse names the program alone)
                parser.exit(
                    2,
                    f"racket-impact {args.command}: error: unrecognized arguments: "
                    f"{' '.join(extra)} (racket-impact {args.command} --help lists its options)\n",
                )
            args.debug = len(words) < len(argv)  # before or after the subcommand
            return _start(args, words)
        except KeyboardInterrupt as err:  # before the run (a run reports its own)
            if "--debug" in argv:
                raise
            return interrupted("racket-impact", err, written=False)
