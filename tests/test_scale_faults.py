"""Scale-out that fails cleanly and cleans up (issue 34): a scheduler's address refused in one
line, within a stated time, unless a Dask scheduler answers there; --workers cut to the
cores; a pool's workers ending with the command, however it ends; Ctrl-C and SIGTERM on a
--workers run ending it at once, with one line, and nothing written.  Only 127.0.0.1."""

import os
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from studies import scale
from studies.scale import check_workers, cores, executor_for
from studies.scheduler import check_answers, check_protocol, check_scheduler

COMMAND = [sys.executable, "-c", "import sys; from studies.entry import main; sys.exit(main())"]
"""``racket-impact`` as installed (its Ctrl-C before the command has started answered too)."""

LONG_RUN = ["sweep", "--points", "100000", "--speed", "10", "20", "30", "40", "--workers", "2"]
"""A --workers run of 4e5 impacts: several seconds on two workers."""


class Listener:
    """A plain TCP server on 127.0.0.1, not Dask: to each connection it sends ``greeting``
    (an HTTP server's answer, say), or nothing, and holds it open until closed."""

    def __init__(self, greeting: bytes = b""):
        self.sock = socket.create_server(("127.0.0.1", 0))
        self.address = f"127.0.0.1:{self.sock.getsockname()[1]}"
        self.greeting, self.held = greeting, []
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self):
        while True:
            try:
                conn, _ = self.sock.accept()
            except OSError:  # closed
                return
            self.held.append(conn)
            conn.sendall(self.greeting)

    def close(self):
        self.sock.close()
        for conn in self.held:
            conn.close()


@pytest.fixture
def listener(request):
    server = Listener(request.param)
    yield server
    server.close()


def _cli(*words, **kwargs):
    return subprocess.run([*COMMAND, *words], capture_output=True, text=True, **kwargs)


@pytest.mark.parametrize("protocol", ["inproc", "ucx", "ws", "wss"])
def test_other_protocols_are_refused_by_name_before_any_connection(protocol):
    address = f"{protocol}://127.0.0.1:8786"
    with pytest.raises(ValueError, match=f"--scheduler {address}: {protocol}:// is not supp"):
        check_protocol(check_scheduler(address), "--scheduler")


def test_tls_without_certificates_is_refused_by_name():
    pytest.importorskip("distributed")
    with pytest.raises(ValueError, match="tls:// needs TLS certificates in Dask's config"):
        check_protocol("tls://127.0.0.1:8786", "--scheduler")
    assert check_protocol("127.0.0.1:8786") == check_protocol("tcp://h:1") == "tcp"


@pytest.mark.parametrize(
    "listener",
    [b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n", b"\xff" * 64],
    indirect=True,
)
def test_a_listener_that_is_not_dask_is_refused_not_read_for_exabytes(listener):
    pytest.importorskip("distributed")
    start = time.monotonic()
    with pytest.raises(ValueError, match="answers, but not as a Dask scheduler") as err:
        with executor_for(scheduler=listener.address, timeout=5.0):
            pass
    assert time.monotonic() - start < 2.0
    assert str(err.value).startswith(f"scheduler: {listener.address} answers")
    assert "\n" not in str(err.value)


@pytest.mark.parametrize("listener", [b""], indirect=True)
def test_a_listener_that_says_nothing_is_refused_within_the_time(listener):
    pytest.importorskip("distributed")
    start = time.monotonic()
    with pytest.raises(ValueError, match=f"no Dask scheduler answers at {listener.address} "):
        check_answers(listener.address, "--scheduler", timeout=1.0)
    assert 1.0 <= time.monotonic() - start < 1.5


def test_a_dask_scheduler_greets_as_the_check_expects():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(
        host="127.0.0.1", n_workers=0, processes=False, protocol="tcp", dashboard_address=None
    ) as cluster:  # fmt: skip
        check_answers(cluster.scheduler_address, timeout=5.0)


@pytest.mark.parametrize("listener", [b"HTTP/1.1 200 OK\r\n\r\n"], indirect=True)
def test_the_command_line_refuses_a_bad_scheduler_in_one_line_before_any_work(listener):
    pytest.importorskip("distributed")
    start = time.monotonic()
    done = _cli("compare", "--scheduler", listener.address, "--points", "20", timeout=60)
    assert done.returncode == 2, done.stderr
    assert done.stdout == ""  # refused before the rackets are built and said
    assert done.stderr == (
        f"racket-impact compare: error: --scheduler: {listener.address} answers, but not as a "
        "Dask scheduler (its first message would be 3543824036068086856 bytes)\n"
    )
    assert time.monotonic() - start < 30  # (the interpreter's start included)


def test_workers_beyond_the_cores_are_cut_to_them_with_a_warning(monkeypatch):
    monkeypatch.setattr(scale, "cores", lambda: 2)
    with pytest.warns(UserWarning, match=r"--workers 1000: this process may use 2 cores"):
        assert check_workers(1000, "--workers") == 2
    assert check_workers(2) == 2
    assert 1 <= cores() <= (os.cpu_count() or 1)


def test_an_interrupted_pool_kills_its_running_tasks_at_once():
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        with executor_for(workers=1) as pool:
            running = pool.submit(time.sleep, 60)
            while not running.running():
                time.sleep(0.05)
            workers = list(pool._processes.values())
            started = time.monotonic()
            raise KeyboardInterrupt
    assert time.monotonic() - started < 5.0, "waited for the running task"
    assert not any(worker.is_alive() for worker in workers)
    assert time.monotonic() - start < 30


def _in_session(sid: int) -> list[int]:
    """The live processes of session ``sid`` (zombies not counted), from /proc."""
    found = []
    for entry in Path("/proc").iterdir():
        try:
            stat = (entry / "stat").read_text()
        except (OSError, ValueError):
            continue
        fields = stat[stat.rindex(")") + 2 :].split()
        if fields[0] not in "ZX" and int(fields[3]) == sid:
            found.append(int(entry.name))
    return found


@pytest.fixture
def launch(tmp_path):
    """Start ``racket-impact`` on :data:`LONG_RUN` in a session of its own (as a terminal
    runs it) and return it, with its table's path, once its pool runs (a worker of its
    forkserver, a grandchild, is up); whatever of the session is left is killed after the
    test."""
    sessions = []

    def started():
        out = tmp_path / "table.csv"
        command = subprocess.Popen(
            [*COMMAND, *LONG_RUN, "--out", str(out)],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            text=True,
            start_new_session=True,
        )
        sessions.append(command.pid)
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and command.poll() is None:
            parents = {pid: _parent(pid) for pid in _in_session(command.pid)}
            if any(parents.get(parent) == command.pid for parent in parents.values()):
                time.sleep(0.5)  # (its tasks running)
                return command, out
            time.sleep(0.1)
        pytest.fail(f"no worker started: {command.communicate()[1]}")

    yield started
    for sid in sessions:
        for pid in _in_session(sid):
            os.kill(pid, signal.SIGKILL)


def _parent(pid: int) -> int | None:
    """The parent of the process ``pid`` (None if it has ended)."""
    try:
        return int(Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[1])
    except (OSError, ValueError, IndexError):
        return None


def _gone(sid: int, seconds: float = 5.0) -> list[int]:
    """The processes of session ``sid`` still alive after waiting up to ``seconds``."""
    deadline = time.monotonic() + seconds
    while _in_session(sid) and time.monotonic() < deadline:
        time.sleep(0.1)
    return _in_session(sid)


linux_only = pytest.mark.skipif(
    not sys.platform.startswith("linux"),
    reason="reads /proc; workers die with the command on Linux",
)


@linux_only
def test_killing_the_command_leaves_no_process_behind(launch):
    command, out = launch()
    assert len(_in_session(command.pid)) >= 3  # the command, its forkserver, a worker
    os.kill(command.pid, signal.SIGKILL)
    command.wait(timeout=10)
    command.stderr.close()
    assert _gone(command.pid) == [], "processes of the killed command left alive"
    assert not out.exists()


@linux_only
@pytest.mark.parametrize(
    ("signum", "group", "status", "said"),
    [
        (signal.SIGINT, True, 130, "interrupted; no file written"),  # Ctrl-C at a terminal
        (signal.SIGTERM, False, 143, "stopped by SIGTERM; no file written"),
    ],
)
def test_a_signal_ends_a_workers_run_at_once_in_one_line(
    launch, tmp_path, signum, group, status, said
):
    command, _ = launch()
    sent = time.monotonic()
    (os.killpg if group else os.kill)(command.pid, signum)
    _, stderr = command.communicate(timeout=30)
    assert time.monotonic() - sent < 10
    assert command.returncode == status, stderr
    lines = [line for line in stderr.splitlines() if "compiling the solver" not in line]
    assert lines == [f"racket-impact sweep: {said}"]
    assert _gone(command.pid) == []
    assert list(tmp_path.iterdir()) == []  # no table, no sidecar, no temporary file
