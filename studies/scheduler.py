"""A Dask scheduler's address, checked, and its client: refused in one line, within a stated
time, unless a Dask scheduler answers there.

The check, all of it within ``timeout`` (:data:`SCHEDULER_TIMEOUT` by default) of wall-clock
time:

* the address's form, ``[tcp://]HOST:PORT`` (:func:`check_scheduler`), and its protocol
  (:func:`check_protocol`): ``tcp``, or ``tls`` where Dask's configuration has the
  certificates; any other (``inproc``, ``ucx``, ``ws``, ``wss``) is refused by name before
  any connection;
* a plain socket to it that reads the first message a Dask scheduler sends anyone who
  connects (its handshake, about 60 bytes): no more than :data:`HANDSHAKE_BYTES` are read,
  so that a listener that is not Dask (an HTTP server, say) is refused, not taken at its
  first 8 bytes for a message's length (the exabytes ``distributed`` would try to allocate);
* then ``distributed``'s own client (:func:`connected`), with the time left as its connect
  timeout.

A command checks the address (:func:`check_answers`) before any work, and connects when its
impacts are to run.
"""

from __future__ import annotations

import re
import socket
import struct
import threading
import time

SCHEDULER_TIMEOUT = 10.0
"""Longest the check of a scheduler's address takes, from the first look-up of its host to a
client connected [s]."""

HANDSHAKE_BYTES = 65536
"""Most bytes of the first message read from a scheduler: its handshake (the compression,
Python version and pickle protocol it uses) is about 60 bytes (``distributed`` 2026.8)."""

_SCHEDULER = re.compile(r"^(?:(tcp|tls|ucx|ws|wss|inproc)://)?([^\s/:]+|\[[0-9A-Fa-f:]+\]):(\d+)$")

_UNSUPPORTED = {
    "inproc": "a scheduler inside this process",
    "ucx": "needs ucx-py, and a cluster started on it",
    "ws": "a scheduler started on websockets",
    "wss": "a scheduler started on websockets",
}
"""The protocols of a Dask address this command does not connect on, each with what it is."""


def check_scheduler(address: str, flag: str = "scheduler") -> str:
    """``address``, a Dask scheduler's ``[PROTOCOL://]HOST:PORT`` (e.g.
    ``tcp://10.0.0.5:8786``); ValueError naming ``flag`` otherwise.

    Parameters
    ----------
    address : str
        The scheduler's address.
    flag : str
        The input's name as the user typed it (``--scheduler``).
    """
    match = _SCHEDULER.match(str(address).strip())
    if match is None or not 0 < int(match.group(3)) < 65536:
        raise ValueError(
            f"{flag} must be a Dask scheduler's address, [tcp://]HOST:PORT with a port in "
            f"[1, 65535] (e.g. tcp://10.0.0.5:8786), got {address!r}"
        )
    return str(address).strip()


def check_protocol(address: str, flag: str = "scheduler") -> str:
    """The protocol of ``address`` (one :func:`check_scheduler` accepts): ``tcp`` (also for
    a bare ``HOST:PORT``), or ``tls`` where Dask's configuration has the certificates
    (``distributed.comm.tls``); ValueError naming ``flag`` for any other, before any
    connection.

    Parameters
    ----------
    address, flag
        As in :func:`check_scheduler`.
    """
    protocol = _SCHEDULER.match(address).group(1) or "tcp"
    if protocol in _UNSUPPORTED:
        raise ValueError(
            f"{flag} {address}: {protocol}:// is not supported ({_UNSUPPORTED[protocol]}); "
            "give the scheduler's tcp://HOST:PORT"
        )
    if protocol == "tls" and _tls_context() is None:
        raise ValueError(
            f"{flag} {address}: tls:// needs TLS certificates in Dask's configuration "
            "(distributed.comm.tls: ca-file, client.cert, client.key); give tcp://HOST:PORT "
            "or configure them"
        )
    return protocol


def _distributed():
    """The ``distributed`` module; ValueError saying how to install it where it is missing."""
    try:
        import distributed
    except ImportError:
        raise ValueError(
            "a Dask scheduler needs dask.distributed: pip install 'racket-impact[scale]'"
        ) from None
    return distributed


def _tls_context():
    """The client's ssl.SSLContext of Dask's configuration, or None without certificates."""
    return _distributed().Security().get_connection_args("client")["ssl_context"]


def check_answers(address: str, flag: str = "scheduler", timeout: float = SCHEDULER_TIMEOUT):
    """Whether a Dask scheduler answers at ``address`` (checked by :func:`check_scheduler`):
    its protocol (:func:`check_protocol`), then its greeting read on a plain socket (see the
    module docstring); ValueError in one line, naming ``flag``, unless it greets within
    ``timeout``.  Nothing is started: for a command to refuse the address before any work.

    Parameters
    ----------
    address, flag
        As in :func:`check_scheduler`.
    timeout : float
        The longest the check takes [s].
    """
    _distributed()  # imported before the clock starts (about 1 s)
    deadline = time.monotonic() + timeout
    protocol = check_protocol(address, flag)
    host, port = _SCHEDULER.match(address).group(2, 3)
    refused = f"{flag}: no Dask scheduler answers at {address}"
    try:
        _in_time(deadline, _handshake, host.strip("[]"), int(port), protocol, deadline)
    except TimeoutError:
        raise ValueError(f"{refused} within {timeout:g} s") from None
    except OSError as err:
        raise ValueError(f"{refused} ({err.strerror or err})") from None
    except _NotDask as err:
        raise ValueError(
            f"{flag}: {address} answers, but not as a Dask scheduler ({err})"
        ) from None


def connected(address: str, flag: str = "scheduler", timeout: float = SCHEDULER_TIMEOUT):
    """A ``distributed.Client`` of the scheduler at ``address`` (checked by
    :func:`check_scheduler`); ValueError in one line, naming ``flag``, unless a Dask
    scheduler answers there (:func:`check_answers`) and its client connects, all within
    ``timeout``.

    Parameters
    ----------
    address, flag
        As in :func:`check_scheduler`.
    timeout : float
        The longest the whole check takes [s].
    """
    client = _distributed().Client
    import dask  # (installed with distributed)

    deadline = time.monotonic() + timeout
    check_answers(address, flag, timeout)
    left = max(deadline - time.monotonic(), 0.1)
    try:
        with dask.config.set({"distributed.comm.timeouts.connect": f"{left}s"}):
            return client(address, timeout=left, set_as_default=False)
    except Exception as err:  # whatever stops distributed's client: not a scheduler at hand
        raise ValueError(
            f"{flag}: no Dask scheduler answers at {address} within {timeout:g} s "
            f"({type(err).__name__}: {err})"
        ) from None


class _NotDask(Exception):
    """What answered is not a Dask scheduler."""


def _in_time(deadline: float, work, *args) -> None:
    """``work(*args)`` on a thread, its exception raised here; TimeoutError if it has not
    ended by ``deadline`` (of ``time.monotonic``): a host's look-up has no timeout of its own.
    """
    failed = []

    def run():
        try:
            work(*args)
        except BaseException as err:  # raised again in the caller's thread
            failed.append(err)

    thread = threading.Thread(target=run, daemon=True, name="racket-impact scheduler check")
    thread.start()
    thread.join(max(deadline - time.monotonic(), 0.0))
    if thread.is_alive():
        raise TimeoutError
    if failed:
        raise failed[0]


def _handshake(host: str, port: int, protocol: str, deadline: float) -> None:
    """Connect to ``host:port`` and read the handshake a Dask scheduler sends first: an
    8-byte length, then that many bytes, frames of which the first is a msgpack map with
    the sender's ``python``; _NotDask otherwise, OSError or TimeoutError by ``deadline``.
    """
    import msgpack
    from distributed.protocol.utils import unpack_frames

    with _opened(host, port, protocol, deadline) as sock:
        (size,) = struct.unpack("<Q", _read(sock, 8, deadline))
        if not 0 < size <= HANDSHAKE_BYTES:
            raise _NotDask(f"its first message would be {size} bytes")
        body = _read(sock, size, deadline)
        try:
            first = msgpack.unpackb(unpack_frames(body)[0])
        except Exception:  # any garbage: msgpack's and struct's errors have no common base
            first = None
        if not isinstance(first, dict) or "python" not in first:
            raise _NotDask("it does not greet as Dask does")


def _opened(host: str, port: int, protocol: str, deadline: float) -> socket.socket:
    """A socket connected to ``host:port`` by ``deadline``, TLS-wrapped for ``tls``."""
    sock = socket.create_connection((host, port), timeout=_left(deadline))
    if protocol != "tls":
        return sock
    try:
        return _tls_context().wrap_socket(sock, server_hostname=host)  # (it takes the socket)
    except BaseException:
        sock.close()
        raise


def _read(sock, count: int, deadline: float) -> bytes:
    """``count`` bytes from ``sock`` by ``deadline``; _NotDask if it closes before."""
    data = b""
    while len(data) < count:
        sock.settimeout(_left(deadline))
        chunk = sock.recv(count - len(data))
        if not chunk:
            raise _NotDask(f"it closed the connection after {len(data)} bytes")
        data += chunk
    return data


def _left(deadline: float) -> float:
    """Seconds until ``deadline``; TimeoutError when it has passed."""
    left = deadline - time.monotonic()
    if left <= 0:
        raise TimeoutError
    return left
