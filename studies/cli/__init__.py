"""The ``racket-impact`` command line.

Subcommands: ``paper``, ``sweep``, ``serve``, ``stroke``, ``collide``, ``modes``, ``specs``,
``compare``, ``strings``, ``bat`` and more (``racket-impact --help``).
Rackets and balls are presets or TOML files (:mod:`studies.config`).  Tables go to CSV,
JSON or Parquet by the file's extension, plots to PNG, SVG or PDF.  Bad input prints one
line naming the problem and exits with status 2.

One module per command family (each adds its subcommands' parsers and holds their
handlers), :mod:`studies.cli.options` for the options they share, :mod:`studies.cli.files`
for the files they write, :mod:`studies.cli.runner` for running a parsed command; here the
parser, :func:`main` and ``rerun`` (which replays a command through the whole parser).  A
command line imports the module of its own command only (:data:`COMMANDS`): the handlers
named here load on first use (:mod:`common.lazy`).
"""

from __future__ import annotations

import argparse
import importlib
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from common.blas import located_by_python_m, one_blas_thread_unless_set

# python -m studies.cli: BLAS on one thread, as the console command has it (studies.entry),
# set here since this package loads numpy before its __main__ runs; the imports below come
# after it.  (runpy.run_module does not come here: studies.entry's setting is then too late.)
if located_by_python_m("studies.cli"):
    one_blas_thread_unless_set()

from ball import DEFAULT_BALL
from common.lazy import lazy_names
from common.version import __version__
from studies.cli.files import _RUN as _RUN  # the run being made (tests read it)
from studies.cli.files import check_outputs, save_plot, write_table
from studies.cli.options import _Parser, _Replay
from studies.cli.runner import _reader_may_go, _start
from studies.outputs import interrupted

if TYPE_CHECKING:  # the handlers, loaded on first use (common.lazy): by module below
    from studies.cli.app import cmd_app
    from studies.cli.balls import cmd_ball, cmd_collide, cmd_drop
    from studies.cli.bat import cmd_bat
    from studies.cli.compare import cmd_compare
    from studies.cli.court import cmd_court
    from studies.cli.face import cmd_map, cmd_sweetspots
    from studies.cli.paper import cmd_paper, paper_figures
    from studies.cli.rackets import cmd_feel, cmd_modes, cmd_specs
    from studies.cli.serve import cmd_serve
    from studies.cli.strings import cmd_strings
    from studies.cli.stroke import cmd_stroke
    from studies.cli.sweep import cmd_sweep
    from studies.cli.validate import cmd_validate

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

__getattr__, __dir__ = lazy_names(
    __name__,
    {
        "studies.cli.app": ("cmd_app",),
        "studies.cli.balls": ("cmd_ball", "cmd_collide", "cmd_drop"),
        "studies.cli.bat": ("cmd_bat",),
        "studies.cli.compare": ("cmd_compare",),
        "studies.cli.court": ("cmd_court",),
        "studies.cli.face": ("cmd_map", "cmd_sweetspots"),
        "studies.cli.paper": ("cmd_paper", "paper_figures"),
        "studies.cli.rackets": ("cmd_feel", "cmd_modes", "cmd_specs"),
        "studies.cli.serve": ("cmd_serve",),
        "studies.cli.strings": ("cmd_strings",),
        "studies.cli.stroke": ("cmd_stroke",),
        "studies.cli.sweep": ("cmd_sweep",),
        "studies.cli.validate": ("cmd_validate",),
    },
)

COMMANDS = {
    "paper": "paper", "sweep": "sweep", "map": "face", "serve": "serve", "collide": "balls",
    "drop": "balls", "ball": "balls", "modes": "rackets", "specs": "rackets", "app": "app",
    "rerun": None, "feel": "rackets", "sweetspots": "face", "compare": "compare",
    "validate": "validate", "strings": "strings", "stroke": "stroke", "court": "court",
    "bat": "bat",
}  # fmt: skip
"""Each subcommand, in the order ``racket-impact --help`` lists them -> the module of
:mod:`studies.cli` whose ``add_<subcommand>`` adds its parser (None: this one's)."""

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
        replay = build_parser(_Replay, _command(argv)).parse_args(argv)
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


def build_parser(parser_class=_Parser, command: str | None = None) -> argparse.ArgumentParser:
    """The ``racket-impact`` argument parser, one subcommand per study (``parser_class``:
    :class:`_Replay` for a command recorded in a sidecar).  With ``command``, the command
    line's own subcommand, only its parser is made in full (its module imported): the
    others are named, for argparse to know them, and nothing more.
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
    for name, module in COMMANDS.items():
        if command not in (None, name):
            sub.add_parser(name)  # named only: the command line runs another
            continue
        home = importlib.import_module(f"{__name__}.{module}") if module else sys.modules[__name__]
        getattr(home, f"add_{name}")(sub)
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
            parser = build_parser(command=_command(words))
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


def _command(words: list[str]) -> str | None:
    """The subcommand a command line ``words`` (``--debug`` left out) runs, when its first
    word names one; None otherwise (``--help``, ``--version``, a slip), for the whole parser
    to answer.
    """
    return words[0] if words and words[0] in COMMANDS else None
