"""No lost, torn or partial file, and a ``rerun`` that treats a sidecar as untrusted input
(issue 23, parts 2 and 3): a run's files appear together, complete, or not at all; Ctrl-C
ends with one line and status 130; ``rerun`` replays only table commands, from the sidecar
alone, into the table's own directory."""

import errno
import json
import os
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pandas as pd
import pytest

import studies.cli as cli
import studies.outputs as outputs
from studies.cli import main

BALL = ["ball", "--speeds", "10", "20"]
"""A cheap table command (no racket solver)."""


def _listing(folder: Path) -> dict:
    """Every file under ``folder`` (hidden ones included) and its bytes (None: a directory
    or a FIFO)."""
    found = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            path = Path(root) / name
            regular = path.is_file() and not path.is_symlink()
            found[str(path.relative_to(folder))] = path.read_bytes() if regular else None
    return found


def _one_line(capsys) -> str:
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    return lines[0]


def _within(seconds: float, argv) -> int:
    """main's status, failing the test if it has not returned within ``seconds``."""
    result = {}
    thread = threading.Thread(target=lambda: result.update(status=main(argv)), daemon=True)
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), f"{argv} blocked"
    return result["status"]


@pytest.fixture
def folder(tmp_path, monkeypatch):
    """A working directory holding an earlier run's table (which must survive a failed
    run) and nothing else."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "t.csv").write_text("old table\n")
    return tmp_path


# ----- all or nothing ---------------------------------------------------------------------
def test_a_run_replaces_its_files_whole_and_leaves_no_temporary_file(folder, capsys):
    umask = os.umask(0)
    os.umask(umask)
    assert main([*BALL, "--out", "t.csv", "--plot", "p.png"]) == 0
    capsys.readouterr()
    assert sorted(_listing(folder)) == ["p.png", "t.csv", "t.csv.meta.json"]
    assert len(pd.read_csv(folder / "t.csv")) == 2
    assert (folder / "p.png").read_bytes()[:4] == b"\x89PNG"
    for name in ("t.csv", "p.png"):  # readable as any new file (a temporary file is private)
        assert (folder / name).stat().st_mode & 0o777 == 0o666 & ~umask


def _no_status(*args, **kwargs):
    raise FileNotFoundError(errno.ENOENT, os.strerror(errno.ENOENT), "/proc/self/status")


@pytest.mark.parametrize("shown", [True, False], ids=["/proc", "elsewhere"])
def test_the_umask_is_read_not_set_where_the_system_shows_it(shown, tmp_path, monkeypatch):
    """Setting the umask to 0 and back races with other threads creating files."""
    if shown and not Path("/proc/self/status").exists():
        pytest.skip("the system does not show the umask")
    previous = os.umask(0o027)
    try:
        outputs._mode.cache_clear()
        if shown:
            monkeypatch.setattr(os, "umask", lambda mask: pytest.fail("the umask was set"))
        else:
            monkeypatch.setattr(outputs, "open", _no_status, raising=False)
        outputs.write(tmp_path / "x.txt", lambda temp: Path(temp).write_text("x"))
    finally:
        monkeypatch.undo()
        os.umask(previous)
        outputs._mode.cache_clear()
    assert (tmp_path / "x.txt").stat().st_mode & 0o777 == 0o640


CHILD = """
import os, sys, time
from pathlib import Path
from studies.cli import main

pause, wait, speeds = float(sys.argv[1]), sys.argv[2] == "wait", sys.argv[3:]
replace = os.replace

def slow(source, target):  # a pause after the table is in place, before its sidecar
    replace(source, target)
    if str(target).endswith("t.csv"):
        time.sleep(pause)

os.replace = slow
while not Path("go").exists():
    time.sleep(0.01)
while wait and not Path("t.csv").exists():  # the other run is between its two renames
    time.sleep(0.01)
sys.exit(main(["ball", "--speeds", *speeds, "--out", "t.csv"]))
"""


def test_two_concurrent_runs_leave_one_runs_table_and_its_own_sidecar(tmp_path):
    """The first run pauses 2 s between putting its table and its sidecar in place; the
    second starts once the first's table is there.  Unlocked, the second's table would end
    beside the first's sidecar; locked, the second waits and its own pair wins."""
    runs = [
        subprocess.Popen(
            [sys.executable, "-c", CHILD, pause, wait, *speeds],
            cwd=tmp_path,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            text=True,
        )
        for pause, wait, speeds in (("2", "go", ["10", "20"]), ("0", "wait", ["10", "20", "30"]))
    ]
    (tmp_path / "go").touch()
    for run in runs:
        assert run.wait(timeout=120) == 0, run.stderr.read()
        run.stderr.close()
    record = json.loads((tmp_path / "t.csv.meta.json").read_text())
    table = pd.read_csv(tmp_path / "t.csv")
    assert record["options"]["speeds"] == table["speed_m_s"].tolist() == [10, 20, 30]
    assert sorted(_listing(tmp_path)) == ["go", "t.csv", "t.csv.meta.json"]


def _interrupt(*args, **kwargs):
    raise KeyboardInterrupt


def _torn_csv(self, path, **kwargs):  # half a table written, then Ctrl-C
    Path(path).write_text("speed_m_s,e\n10,0.7")
    raise KeyboardInterrupt


@pytest.mark.parametrize(
    "where, target, patched",
    [
        ("computing", "studies.bounce.rigid_bounce_table", _interrupt),
        ("writing the table", "pandas.DataFrame.to_csv", _torn_csv),
        ("writing the sidecar", "studies.provenance.describe", _interrupt),
        ("between the table and the plot", "studies.plots.plot_rigid_bounce", _interrupt),
    ],
)
def test_ctrl_c_leaves_nothing_new_one_line_status_130(
    where, target, patched, folder, capsys, monkeypatch
):
    before = _listing(folder)
    monkeypatch.setattr(target, patched)
    assert main([*BALL, "--out", "t.csv", "--plot", "p.png"]) == 130, where
    assert _one_line(capsys) == "racket-impact ball: interrupted; no file written"
    assert _listing(folder) == before


def test_ctrl_c_during_the_renames_waits_for_a_complete_set(folder, capsys, monkeypatch):
    """SIGINT between two renames is held back until every file is in place."""
    replace, calls = os.replace, []

    def interrupted(source, target):
        replace(source, target)
        calls.append(target)
        if len(calls) == 1:
            os.kill(os.getpid(), signal.SIGINT)

    monkeypatch.setattr(os, "replace", interrupted)
    assert main([*BALL, "--out", "t.csv", "--plot", "p.png"]) == 130
    assert _one_line(capsys) == "racket-impact ball: interrupted; its files were all written"
    assert len(calls) == 3
    assert sorted(_listing(folder)) == ["p.png", "t.csv", "t.csv.meta.json"]
    assert len(pd.read_csv(folder / "t.csv")) == 2


def test_ctrl_c_before_the_run_is_one_line_too(capsys, monkeypatch):
    monkeypatch.setattr(cli, "build_parser", _interrupt)
    assert main(BALL) == 130
    assert _one_line(capsys) == "racket-impact: interrupted; no file written"


def test_ctrl_c_while_the_command_starts_is_one_line_too(capsys, monkeypatch):
    """The console command catches Ctrl-C while studies.cli imports numpy, pandas and
    matplotlib (about half a second), and starts without them."""
    import builtins
    from importlib.metadata import entry_points

    from studies import entry

    (script,) = entry_points(group="console_scripts", name="racket-impact")
    assert script.value == "studies.entry:main"
    code = "import sys, studies.entry; print({'numpy', 'pandas', 'matplotlib'} & set(sys.modules))"
    light = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert light.stdout.strip() == "set()", light.stderr
    load = builtins.__import__

    def starting(name, *args, **kwargs):
        if name == "studies.cli":
            raise KeyboardInterrupt
        return load(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", starting)
    monkeypatch.setattr(sys, "argv", ["racket-impact", *BALL])
    assert entry.main() == 130
    assert _one_line(capsys) == "racket-impact: interrupted; no file written"


STOP = """
import os, signal, sys, time
from pathlib import Path
import pandas as pd
from studies.cli import main

signum, where = getattr(signal, sys.argv[1]), sys.argv[2]
if where == "ignored":  # as under nohup
    signal.signal(signum, signal.SIG_IGN)
to_csv, replace = pd.DataFrame.to_csv, os.replace

def torn(self, path, **kwargs):  # half a table written, then the signal
    Path(path).write_text("speed_m_s,e\\n10,0.7")
    os.kill(os.getpid(), signum)
    time.sleep(0.5)
    to_csv(self, path, **kwargs)

def between(source, target):  # the signal between two renames
    replace(source, target)
    if str(target).endswith("t.csv"):
        os.kill(os.getpid(), signum)

if where == "renames":
    os.replace = between
else:
    pd.DataFrame.to_csv = torn
sys.exit(main(["ball", "--speeds", "10", "20", "--out", "t.csv", "--plot", "p.png"]))
"""


@pytest.mark.parametrize("name", ["SIGTERM", "SIGHUP"])
@pytest.mark.parametrize("where", ["writing", "renames", "ignored"])
def test_sigterm_and_sighup_end_a_run_as_ctrl_c_does(name, where, folder):
    """While a table is written: nothing new (no hidden temporary file), one line, status
    128 + the signal's number; between the renames: held back until every file is in place;
    ignored (nohup): ignored."""
    signum = getattr(signal, name)
    before = _listing(folder)
    run = subprocess.run(
        [sys.executable, "-c", STOP, name, where],
        cwd=folder,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
        timeout=120,
    )
    if where == "writing":
        assert (run.returncode, run.stderr) == (
            128 + signum,
            f"racket-impact ball: stopped by {name}; no file written\n",
        )
        assert _listing(folder) == before
        return
    if where == "renames":
        assert (run.returncode, run.stderr) == (
            128 + signum,
            f"racket-impact ball: stopped by {name}; its files were all written\n",
        )
    else:
        assert (run.returncode, run.stderr) == (0, "")
    assert sorted(_listing(folder)) == ["p.png", "t.csv", "t.csv.meta.json"]
    assert len(pd.read_csv(folder / "t.csv")) == 2


def test_a_full_disk_at_the_second_output_leaves_nothing_new(folder, capsys, monkeypatch):
    from matplotlib.figure import Figure

    def full(self, path, **kwargs):
        Path(path).write_bytes(b"\x89PNG partial")
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), path)

    before = _listing(folder)
    monkeypatch.setattr(Figure, "savefig", full)
    assert main([*BALL, "--out", "t.csv", "--plot", "p.png"]) == 2
    line = _one_line(capsys)
    assert line == f"racket-impact ball: error: {os.strerror(errno.ENOSPC)} (p.png)"
    assert _listing(folder) == before


def test_an_unwritable_second_directory_at_write_time_leaves_nothing_new(
    folder, capsys, monkeypatch
):
    """The directory turns read-only after the checks (simulated: root may write anyway)."""
    import tempfile

    (folder / "ro").mkdir()
    mkstemp = tempfile.mkstemp

    def refused(*args, dir=None, **kwargs):
        if Path(dir).name == "ro":
            raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), str(dir) + "/.x")
        return mkstemp(*args, dir=dir, **kwargs)

    before = _listing(folder)
    monkeypatch.setattr(tempfile, "mkstemp", refused)
    assert main([*BALL, "--out", "t.csv", "--plot", "ro/p.png"]) == 2
    assert _one_line(capsys) == f"racket-impact ball: error: {os.strerror(errno.EACCES)} (ro/p.png)"
    assert _listing(folder) == before


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into read-only directories")
def test_a_read_only_directory_is_refused_before_the_run(folder, capsys):
    (folder / "ro").mkdir(mode=0o500)
    before = _listing(folder)
    assert main([*BALL, "--out", "t.csv", "--plot", "ro/p.png"]) == 2
    assert "--plot: directory 'ro' of 'ro/p.png' is not writable" in _one_line(capsys)
    assert _listing(folder) == before


def test_a_failed_rename_puts_back_the_files_already_replaced(folder, capsys, monkeypatch):
    (folder / "t.csv.meta.json").write_text("old sidecar\n")
    replace, calls = os.replace, []

    def second_fails(source, target):
        calls.append(target)
        if len(calls) == 2:
            raise OSError(errno.EIO, os.strerror(errno.EIO), source, None, target)
        replace(source, target)

    before = _listing(folder)
    monkeypatch.setattr(os, "replace", second_fails)
    assert main([*BALL, "--out", "t.csv"]) == 2
    assert "(t.csv.meta.json)" in _one_line(capsys)
    assert len(calls) == 3  # the table put in place, the sidecar failed, the table put back
    assert _listing(folder) == before


def test_a_previous_file_that_cannot_be_put_back_is_kept_and_named(folder, capsys, monkeypatch):
    (folder / "t.csv.meta.json").write_text("old sidecar\n")
    replace, calls = os.replace, []

    def failing(source, target):  # the sidecar's rename fails, then putting the table back
        calls.append(target)
        if len(calls) > 1:
            raise OSError(errno.EIO, os.strerror(errno.EIO), source, None, target)
        replace(source, target)

    monkeypatch.setattr(os, "replace", failing)
    assert main([*BALL, "--out", "t.csv"]) == 2
    line = _one_line(capsys)
    after = _listing(folder)
    kept = [name for name, data in after.items() if data == b"old table\n"]
    assert len(kept) == 1 and kept[0].startswith(outputs.PREFIX), after
    assert f"could not be put back and are kept: t.csv as {kept[0]} (t.csv.meta.json)" in line
    assert after["t.csv.meta.json"] == b"old sidecar\n" and len(after) == 3


def test_a_backup_copy_that_fails_is_removed(folder, capsys, monkeypatch):
    """Where hard links are not supported the previous file is copied; a copy cut short
    (a full disk) leaves nothing."""

    def no_links(source, target, **kwargs):
        raise OSError(errno.EPERM, os.strerror(errno.EPERM), source, None, target)

    def full(source, target, **kwargs):
        Path(target).write_text("old")
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(target))

    monkeypatch.setattr(os, "link", no_links)
    monkeypatch.setattr(shutil, "copy2", full)
    before = _listing(folder)
    assert main([*BALL, "--out", "t.csv"]) == 2
    assert _one_line(capsys) == f"racket-impact ball: error: {os.strerror(errno.ENOSPC)} (t.csv)"
    assert _listing(folder) == before


@pytest.mark.parametrize(
    "argv, made, message",
    [
        (
            ["--out", "t.csv"],
            "t.csv.meta.json/",
            "--out's sidecar: 't.csv.meta.json' exists and is not a regular file",
        ),
        (["--plot", "p.png"], "p.png/", "--plot: 'p.png' exists and is not a regular file"),
        (["--out", "f.csv"], "f.csv|", "--out: 'f.csv' exists and is not a regular file"),
        (["--out", "f.csv"], "f.csv.meta.json|", "--out's sidecar: 'f.csv.meta.json' exists"),
        (["--out", "LONGEST.csv"], "", "--out's sidecar: the name of 'xxx"),
        (["--out", "LONGEST+.csv"], "", "--out: the name of 'xxx"),
        (["--out", "l.csv"], "l.csv@", "--out: 'l.csv' is a symbolic link; name the file"),
        (["--out", "l.csv"], "l.csv.meta.json@", "--out's sidecar: 'l.csv.meta.json' is a symb"),
        (["--plot", "p.png"], "p.png@", "--plot: 'p.png' is a symbolic link"),
    ],
)
def test_outputs_that_cannot_be_replaced_are_refused_up_front(argv, made, message, folder, capsys):
    """A directory, a FIFO (never opened: no reader would block the run forever), a name
    longer than the directory allows (LONGEST: a table's name just short enough, but not
    its sidecar's), a symbolic link (the rename would replace the link, not the file it
    names, which would stay as it was; the last one names no file yet)."""
    longest = "x" * (os.pathconf(folder, "PC_NAME_MAX") - len(".csv"))
    argv = [word.replace("LONGEST+", longest + "x").replace("LONGEST", longest) for word in argv]
    if made.endswith("/"):
        (folder / made[:-1]).mkdir()
    elif made.endswith("|"):
        os.mkfifo(folder / made[:-1])
    elif made.endswith("@"):
        os.symlink("t.csv" if made.endswith(".csv@") else "nowhere.png", folder / made[:-1])
    before = _listing(folder)
    assert _within(30, [*BALL, *argv]) == 2
    assert message in _one_line(capsys)
    assert _listing(folder) == before


def test_a_plot_named_as_long_as_the_directory_allows_is_written(folder, capsys):
    name = "x" * (os.pathconf(folder, "PC_NAME_MAX") - 4) + ".png"
    assert main([*BALL, "--plot", name]) == 0
    capsys.readouterr()
    assert (folder / name).read_bytes()[:4] == b"\x89PNG"


def test_a_second_output_naming_the_first_ones_sidecar_is_refused(folder, capsys):
    argv = ["sweep", "--points", "2", "--csv", "s.csv", "--json", "s.csv.meta.json"]
    assert main(argv) == 2
    assert "--json and --csv's sidecar name the same file 's.csv.meta.json'" in _one_line(capsys)


def test_the_paper_commands_outputs_are_checked_before_its_work(folder, capsys, monkeypatch):
    import studies.paper

    monkeypatch.setattr(studies.paper, "paper_table", lambda: pytest.fail("ran the paper"))
    (folder / "figs" / "modes.png").mkdir(parents=True)
    os.mkfifo(folder / "rows.json")
    before = _listing(folder)
    assert _within(30, ["paper", "--out", "figs"]) == 2
    assert "--out: 'figs/modes.png' exists and is not a regular file" in _one_line(capsys)
    assert _within(30, ["paper", "--out", "new", "--json", "rows.json"]) == 2
    assert "--json: 'rows.json' exists and is not a regular file" in _one_line(capsys)
    assert _listing(folder) == before


def test_a_failed_paper_run_removes_the_figures_directory_it_made(folder, capsys, monkeypatch):
    import studies.plots

    monkeypatch.setattr(studies.plots, "plot_collision", _interrupt)  # the first figure
    monkeypatch.setattr(
        "studies.paper.paper_table",
        lambda: pd.DataFrame(
            {"claim": ["c"], "paper": [1.0], "simulated": [1.0], "tolerance": [0.1], "ok": [True]}
        ),
    )
    before = _listing(folder)
    assert main(["paper", "--out", "a/b/figs", "--json", "rows.json"]) == 130
    assert _listing(folder) == before


def test_a_reader_that_goes_stops_nothing(tmp_path):
    """``racket-impact modes --out m.csv | head -3``: the rest of the output is dropped, the
    run's files are written, status 0, nothing on stderr (unbuffered: every print meets the
    closed pipe)."""
    read, write = os.pipe()
    os.close(read)  # the reader has gone
    try:
        run = subprocess.run(
            [sys.executable, "-u", "-c", "import studies.entry as e, sys; sys.exit(e.main())",
             "modes", "--out", "m.csv"],
            cwd=tmp_path, stdout=write, stderr=subprocess.PIPE, text=True, timeout=120,
        )  # fmt: skip
    finally:
        os.close(write)
    assert (run.returncode, run.stderr) == (0, "")
    assert sorted(_listing(tmp_path)) == ["m.csv", "m.csv.meta.json"]


def test_writing_outside_a_run_is_whole_too(tmp_path):
    outputs.write(tmp_path / "x.txt", lambda temp: Path(temp).write_text("whole"))
    with pytest.raises(ZeroDivisionError):
        outputs.write(tmp_path / "y.txt", lambda temp: (Path(temp).write_text("ha"), 1 / 0))
    assert _listing(tmp_path) == {"x.txt": b"whole"}


# ----- rerun ------------------------------------------------------------------------------
def test_rerun_writes_only_into_the_tables_directory(tmp_path, capsys, monkeypatch):
    """The issue's data loss: ``rerun sub/t.csv`` from the parent overwrote ./t.csv.  And
    the recorded TOML text is used, not the file now at the recorded (relative) path."""
    (tmp_path / "sub").mkdir()
    monkeypatch.chdir(tmp_path / "sub")
    examples = Path(__file__).parent.parent / "examples"
    ball = (examples / "hertz_ball.toml").read_text()
    Path("b.toml").write_text(ball)
    argv = ["ball", "b.toml", "--speeds", "10", "20", "--out", "t.csv", "--plot", "p.png"]
    assert main(argv) == 0
    first = Path("t.csv").read_text()
    Path("b.toml").write_text("[ball]\nmass = 0.1\n")  # both copies changed since
    monkeypatch.chdir(tmp_path)
    Path("b.toml").write_text("[ball]\nmass = 0.2\n")
    Path("t.csv").write_text("unrelated\n")
    before = {path: path.stat().st_ino for path in tmp_path.rglob("*")}
    assert main(["rerun", "sub/t.csv"]) == 0
    assert "files written into sub/" in capsys.readouterr().out
    after = {path: path.stat().st_ino for path in tmp_path.rglob("*")}
    written = {str(p.relative_to(tmp_path)) for p in after if after[p] != before.get(p)}
    assert written == {"sub/t.csv", "sub/t.csv.meta.json", "sub/p.png"}
    assert Path("t.csv").read_text() == "unrelated\n"
    after = _listing(tmp_path)
    assert after["sub/t.csv"].decode() == first
    record = json.loads(after["sub/t.csv.meta.json"])
    # the TOML input as first given, the outputs where they went
    assert record["command"] == [*argv[:-4], "--out", "sub/t.csv", "--plot", "sub/p.png"]
    assert (record["options"]["out"], record["options"]["plot"]) == ("sub/t.csv", "sub/p.png")
    assert record["inputs"]["ball"][0]["toml_file"] == "b.toml"
    assert record["inputs"]["ball"][0]["toml"] == ball


def test_every_output_of_a_recorded_command_lands_in_the_tables_directory(
    tmp_path, capsys, monkeypatch
):
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (tmp_path / "sub").mkdir()
    monkeypatch.chdir(tmp_path)
    assert main(["collide", "--out", "sub/c.csv"]) == 0
    record = json.loads(Path("sub/c.csv.meta.json").read_text())
    record["command"] = [
        "collide", "--out", str(elsewhere / "c.csv"), f"--history={elsewhere}/../h.csv",
        "--plot", "../../p.png",
    ]  # fmt: skip
    Path("sub/c.csv.meta.json").write_text(json.dumps(record))
    assert main(["rerun", "sub/c.csv"]) == 0
    capsys.readouterr()
    assert sorted(_listing(tmp_path)) == [
        "elsewhere", "sub", "sub/c.csv", "sub/c.csv.meta.json", "sub/h.csv",
        "sub/h.csv.meta.json", "sub/p.png",
    ]  # fmt: skip
    for table in ("c.csv", "h.csv"):  # the new sidecars say where the files went
        record = json.loads((tmp_path / "sub" / f"{table}.meta.json").read_text())
        assert record["command"] == [
            "collide", "--out", "sub/c.csv", "--history=sub/h.csv", "--plot", "sub/p.png"
        ]  # fmt: skip
        written = {k: record["options"][k] for k in ("out", "history", "plot")}
        assert written == {"out": "sub/c.csv", "history": "sub/h.csv", "plot": "sub/p.png"}


def test_every_command_is_replayable_or_refused_and_its_outputs_known():
    parser = cli.build_parser()
    commands = {
        name
        for action in parser._actions
        if isinstance(action, cli.argparse._SubParsersAction)
        for name in action.choices
    }
    assert commands == {*cli.TABLE_COMMANDS, "paper", "app", "rerun"}
    for command in cli.TABLE_COMMANDS:
        args = parser.parse_args([command])  # every racket an option with a default
        dests = {k for k in vars(args) if k in ("out", "csv", "json", "plot", "history")}
        assert "out" in args._writes and set(args._writes) == dests, command


@pytest.fixture(scope="module")
def ball_run(tmp_path_factory):
    """``BALL --out FOLDER/t.csv`` run once for the module (its ball's bounces take a second
    or two): the folder it ran in, its table's bytes and its sidecar's text."""
    folder = tmp_path_factory.mktemp("ball-run")
    assert main([*BALL, "--out", str(folder / "t.csv")]) == 0
    return folder, (folder / "t.csv").read_bytes(), (folder / "t.csv.meta.json").read_text()


def _edited(folder: Path, edit, ball_run) -> Path:
    """A table and its sidecar in ``folder``, as ``BALL --out folder/t.csv`` writes them
    (``ball_run``'s, the folder it names made ``folder``), the sidecar then edited by ``edit``
    (given the record; returns the new record, or bytes for the file)."""
    made, table, sidecar = ball_run
    (folder / "t.csv").write_bytes(table)
    path = folder / "t.csv.meta.json"
    where = [json.dumps(str(f / "t.csv"))[1:-1] for f in (made, folder)]  # as the JSON has it
    assert sidecar.count(where[0]) == 2  # the command's --out and the options' out
    record = edit(json.loads(sidecar.replace(*where)))
    path.write_bytes(record if isinstance(record, bytes) else json.dumps(record).encode())
    return path


def _without(key):
    return lambda r: {k: v for k, v in r.items() if k != key}


def _with(key, value):
    return lambda r: {**r, key: value}


def _with_ball(entry):
    return lambda r: {**r, "inputs": {"ball": [entry]}}


EDITS = {
    "no made_by": (_without("made_by"), "not a racket-impact sidecar"),
    "no command": (_without("command"), "command must be a non-empty list of strings"),
    "no inputs": (_without("inputs"), "inputs must be a JSON object"),
    "command a string": (_with("command", "ball --out t.csv"), "command must be"),
    "command of numbers": (_with("command", ["ball", 10]), "command must be a list of strings"),
    "empty command": (_with("command", []), "command must be a non-empty list"),
    "inputs a list": (_with("inputs", []), "inputs must be a JSON object"),
    # (an input no command names; "bat" was the example until the bat command, issue 37)
    "unknown input": (_with("inputs", {"club": []}), "inputs.club must be one of"),
    "entries not a list": (_with("inputs", {"ball": "tennis"}), "inputs.ball must be a list"),
    "entry not an object": (_with_ball(3), "inputs.ball[0] must be a JSON object"),
    "toml not text": (
        _with_ball({"given": "b.toml", "toml_file": "b.toml", "toml": 5}),
        "inputs.ball[0].toml must be a string",
    ),
    "toml_file without text": (
        _with_ball({"given": "b.toml", "toml_file": "b.toml"}),
        "inputs.ball[0].toml must be the text of its toml_file",
    ),
    "toml_file a directory": (
        _with_ball({"toml_file": "..", "toml": ""}),
        "inputs.ball[0].toml_file must be a file name",
    ),
    "toml_file too long": (
        _with_ball({"toml_file": "x" * 300 + ".toml", "toml": ""}),
        "inputs.ball[0].toml_file must be a file name of at most 255 bytes",
    ),
    "toml_file with a NUL": (
        _with_ball({"toml_file": "b\0.toml", "toml": ""}),
        "inputs.ball[0].toml_file must be text (no NUL, no lone surrogate)",
    ),
    "toml_file with a lone surrogate": (
        _with_ball({"toml_file": "b\ud800.toml", "toml": ""}),
        "inputs.ball[0].toml_file must be text",
    ),
    "toml with a lone surrogate": (
        _with_ball({"toml_file": "b.toml", "toml": "# \ud800"}),
        "inputs.ball[0].toml must be text",
    ),
    "a NUL in the command": (
        _with("command", ["ball", "--out", "t\0.csv"]),
        "command must be a list of text (no NUL",
    ),
    "options a list": (_with("options", []), "options must be a JSON object"),
    "a TOML file without its text": (
        lambda r: {**r, "command": ["ball", "mine.toml", "--out", "t.csv"]},
        "inputs holds no text for 'mine.toml'",
    ),
    "a recursive rerun": (_with("command", ["rerun", "t.csv"]), "command 'rerun' makes no table"),
    "a server": (
        _with("command", ["app", "--host", "0.0.0.0", "--port", "8080"]),
        "command 'app' makes no table",
    ),
    "the paper": (_with("command", ["paper", "--out", "/tmp/x"]), "command 'paper' makes no"),
    "help": (_with("command", ["ball", "--help"]), "command asks for help"),
    "a bad option": (_with("command", ["ball", "--bogus"]), "unrecognized arguments: --bogus"),
    "an abbreviation": (_with("command", ["ball", "--spe", "10"]), "unrecognized arguments"),
    "an output naming no file": (_with("command", ["ball", "--out", ".."]), "names no file"),
    "binary content": (lambda r: b"\x89PNG\r\n\x1a\n\x00\xff\xfe", "not UTF-8 text"),
    "not JSON": (lambda r: b"{'made_by': 1}", "not JSON"),
    "nested too deeply": (lambda r: b"[" * 100_000 + b"]" * 100_000, "not JSON"),
    "a huge file": (
        lambda r: {**r, "padding": "x" * 1_000_001},
        "larger than a sidecar may be (1000000 bytes)",
    ),
}


@pytest.mark.parametrize("name", EDITS)
def test_an_edited_sidecar_gets_one_line_and_status_2(
    name, ball_run, tmp_path, capsys, monkeypatch
):
    edit, message = EDITS[name]
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(cli, "cmd_app", lambda args: pytest.fail("a server was started"))
    _edited(tmp_path, edit, ball_run)
    capsys.readouterr()
    before = _listing(tmp_path)
    start = time.monotonic()
    assert _within(30, ["rerun", "t.csv"]) == 2
    assert time.monotonic() - start < 10
    line = _one_line(capsys)
    assert line.startswith("racket-impact rerun: error: ") and message in line, line
    assert "racket-impact-rerun-" not in line
    assert _listing(tmp_path) == before


@pytest.mark.parametrize("kind", ["FIFO", "directory"])
def test_a_sidecar_that_is_not_a_file_is_refused_naming_it(kind, tmp_path, capsys, monkeypatch):
    """A FIFO without blocking; a directory named as given, not by its handle's number."""
    monkeypatch.chdir(tmp_path)
    (os.mkfifo if kind == "FIFO" else os.mkdir)("t.csv.meta.json")
    assert _within(30, ["rerun", "t.csv"]) == 2
    assert _one_line(capsys) == (
        "racket-impact rerun: error: rerun needs a racket-impact sidecar file: "
        "'t.csv.meta.json' is not a file"
    )


def test_errors_of_a_replayed_run_name_the_recorded_file_not_its_copy(
    tmp_path, capsys, monkeypatch
):
    monkeypatch.chdir(tmp_path)
    examples = Path(__file__).parent.parent / "examples"
    Path("b.toml").write_text((examples / "hertz_ball.toml").read_text())
    assert main(["ball", "b.toml", "--speeds", "10", "--out", "t.csv"]) == 0
    record = json.loads(Path("t.csv.meta.json").read_text())
    record["inputs"]["ball"][0]["toml"] = "[ball\nmass = -1\n"  # not TOML
    Path("t.csv.meta.json").write_text(json.dumps(record))
    capsys.readouterr()
    assert main(["rerun", "t.csv"]) == 2
    line = _one_line(capsys)
    assert "b.toml" in line and "racket-impact-rerun-" not in line and "/0/" not in line
