"""Speed of the impact solver, each figure printed beside its target (issues 10 and 27).

    python benchmarks/sweep.py

Every figure is measured in this one run (the machine is shared and noisy; read the ratios
to the targets, not the absolute times; the load average is printed before and after):

* the lockstep kernel against the scalar kernel on the same inputs, batch by batch size
  (interleaved runs, medians): where the lockstep kernel starts to pay is
  :data:`racket.solver.dispatch.LOCKSTEP_MIN`;

* a 200-point sweep of the paper racket (the median of 200 calls in a row, after 30 warm
  ones); the scalar and the lockstep kernel alternated call by call on it, 30 calls each
  (the scalar kernel's figure, and the lockstep kernel's speed-up); and the straightforward
  implementation side by side: for each impact point, integrate the ball and every mode
  (rigid-body and bending, the strings in series with the residual flexibility of the
  modes left out, as the model has it) with scipy's solve_ivp (RK45, rtol 1e-8) in two
  phases, loading until the compression peaks and unloading until the force vanishes;
  and a real string bed (stiffening and lossy) against the same bed linear (issue 47's
  1.2 at most, issue 35's 1.3 before); and the same sweep of oblique impacts of a spinning
  ball against head-on (issue 36's 1.5 at most);
* one position (a new one each call; the median of 1000 calls after 300 warm ones: the first
  300 after the solve_ivp baseline measured 0.31 ms, the next 0.20); 1e5 positions in one
  call and 1e6 impacts through ``studies.sweeps.sweep`` (untraced, then the peak of traced
  memory in a second run); the unhappy ball's 200-point sweep (its Xo search included); the
  default accuracy against 16 times the steps, on the paper racket and on the default racket
  and ball (the stiffening ITF ball on the real bed); the default racket's 200-point sweep
  (no target: what a user's sweep costs); the hand-held sweep and the fit to a spec sheet; a
  15 x 9 face map (issue 13);
* whole processes: ``python -c "import racket"``, a cached ``racket-impact sweep`` and
  ``racket-impact paper`` (warm: the compiled kernel on disk).

Beside each figure is its ratio to the baseline, the same figure of the previous release
measured on this machine, and "SLOWER" where a figure has moved the wrong way by more than
:data:`SLOWER` (10 %).  The script records that baseline itself::

    python benchmarks/sweep.py --record-baseline REV

checks out the release ``REV`` (a tag or commit) in a temporary git worktree, runs this
script against it, and writes its figures, the machine and the load to
``benchmarks/baseline.json``; a machine other than the recorded one gets no ratios.

The accuracy of the defaults is measured by ``benchmarks/accuracy.py``.
"""

from __future__ import annotations

import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time
import tracemalloc
import warnings
from dataclasses import replace

import numpy as np
from scipy.integrate import solve_ivp

from ball import Ball, SineLaw
from racket import CATALOG, default_ball, default_racket, impact, paper_ball, paper_racket
from racket.solver import DEFAULT_STEPS_PER_CONTACT, dispatch
from racket.solver.stepper import Stepper
from studies.face.maps import face_map
from studies.sweeps import sweep

POINTS = 200
SPEED = 10.0
BASELINE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "baseline.json")
"""The previous release's figures on this machine (``--record-baseline``)."""
SLOWER = 1.10
"""A figure this much worse than its baseline is flagged."""
FIGURES = {}
"""This run's figures, by name (value, the direction that is better)."""


def baseline_e(racket, ball, position, speed):
    """E at one impact point by solve_ivp on [u, u', q, q'] (the straightforward way)."""
    modes = racket.beam.modes
    phi = modes.shape(position)[:, 0]
    w, zeta = modes.omega, modes.damping
    k, e_ball = ball.law.k, ball.law.e
    series = 1 / racket.strings.stiffness + racket.beam.residual_flexibility([position])[0]
    n = phi.size

    def force(z, f_max):
        f = z / (1 / k + series)
        if f >= f_max:
            return f
        return max((z - f_max * (1 - e_ball**2) / k) / (e_ball**2 / k + series), 0.0)

    def rhs(_t, s, f_max):
        u, ud, q, qd = s[0], s[1], s[2 : 2 + n], s[2 + n :]
        f = force(u - phi @ q, f_max)
        return np.concatenate([[ud, -f / ball.mass], qd, phi * f - 2 * zeta * w * qd - w**2 * q])

    def peak(_t, s, f_max):
        return s[1] - phi @ s[2 + n :]

    def opened(_t, s, f_max):
        return force(s[0] - phi @ s[2 : 2 + n], f_max) - 1e-9

    peak.terminal = opened.terminal = True
    peak.direction = opened.direction = -1
    s0 = np.zeros(2 + 2 * n)
    s0[1] = speed
    one = solve_ivp(rhs, (0, 0.05), s0, args=(0.0,), events=peak, rtol=1e-8, atol=1e-12)
    s1 = one.y[:, -1]
    f_max = force(s1[0] - phi @ s1[2 : 2 + n], 0.0)
    two = solve_ivp(rhs, (one.t[-1], 0.05), s1, args=(f_max,), events=opened, rtol=1e-8, atol=1e-12)
    s2 = two.y[:, -1]
    qd = s2[2 + n :]
    return (phi[:2] @ qd[:2] - s2[1]) / speed


SCALAR, LOCKSTEP = 10**12, 0


def _kernels_side_by_side(call, runs: int) -> tuple[float, float]:
    """Median times [s] of ``call()`` with the scalar and with the lockstep kernel, their
    runs interleaved (so that the machine's load falls on both alike).
    """
    times = {SCALAR: [], LOCKSTEP: []}
    for _ in range(runs):
        for which in times:
            with dispatch.lockstep_from(which):
                t0 = time.perf_counter()
                call()
                times[which].append(time.perf_counter() - t0)
    return float(np.median(times[SCALAR])), float(np.median(times[LOCKSTEP]))


def _load() -> str:
    """The load averages over 1, 5 and 15 minutes (`uptime`)."""
    return "load average " + ", ".join(f"{v:.2f}" for v in os.getloadavg())


def _median_time(call, runs: int = 10) -> float:
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        call()
        times.append(time.perf_counter() - t0)
    return float(np.median(times))


def _machine() -> str:
    """The machine, as the baseline records it: processor, cores and Python."""
    cpu = platform.processor() or platform.machine()
    with open("/proc/cpuinfo") as info:  # Linux: the model name, where processor() is bare
        names = [line.split(":", 1)[1].strip() for line in info if line.startswith("model name")]
    return (
        f"{names[0] if names else cpu}, {os.cpu_count()} cores, Python {platform.python_version()}"
    )


def _baseline() -> dict:
    """The recorded baseline's figures, or {} where none was recorded on this machine."""
    if not os.path.exists(BASELINE):
        return {}
    with open(BASELINE) as file:
        recorded = json.load(file)
    return recorded["figures"] if recorded["machine"] == _machine() else {}


def _row(name: str, value: float, unit: str, target: float | None, better: str = "lower") -> None:
    """One figure beside its target (None: it has none), and their ratio (< 1 meets a
    'lower' target), and its ratio to the baseline's.
    """
    FIGURES[name] = value
    against = ""
    past = _BASE.get(name)
    if past:
        change = value / past if better == "lower" else past / value
        against = f"  baseline {change:5.2f}{'  SLOWER' if change > SLOWER else ''}"
    if target is None:
        print(f"{name:<48} {value:>10.3g} {unit:<5} {'(no target)':<35}{against}")
        return
    ratio = value / target
    met = ratio <= 1.0 if better == "lower" else ratio >= 1.0
    print(
        f"{name:<48} {value:>10.3g} {unit:<5} target {'<=' if better == 'lower' else '>='} "
        f"{target:<7g} ratio {ratio:6.2f}  {'met' if met else 'NOT MET'}{against}"
    )


def record_baseline(rev: str) -> None:
    """Run this script against the release ``rev`` checked out in a temporary worktree and
    write its figures to :data:`BASELINE`.
    """
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    commit = subprocess.run(["git", "-C", root, "rev-parse", rev], check=True,
                            capture_output=True, text=True).stdout.strip()  # fmt: skip
    tree = tempfile.mkdtemp(prefix="racket-impact-baseline-")
    subprocess.run(["git", "-C", root, "worktree", "add", "--detach", tree, commit], check=True,
                   capture_output=True)  # fmt: skip
    try:
        env = dict(os.environ, PYTHONPATH=tree)
        with tempfile.NamedTemporaryFile(suffix=".json") as out:
            subprocess.run([sys.executable, os.path.abspath(__file__), "--json", out.name],
                           check=True, cwd=tree, env=env)  # fmt: skip
            figures = json.load(open(out.name))
    finally:
        subprocess.run(["git", "-C", root, "worktree", "remove", "--force", tree], check=True)
        shutil.rmtree(tree, ignore_errors=True)
    recorded = {"release": rev, "commit": commit, "machine": _machine(), "load": _load(),
                "figures": figures}  # fmt: skip
    partial = f"{BASELINE}.partial"
    with open(partial, "w") as file:
        json.dump(recorded, file, indent=1)
    os.replace(partial, BASELINE)
    print(f"baseline of {rev} ({commit[:10]}) written to {BASELINE}")


_BASE = {}  # the baseline's figures, read when main starts


def _traced(call):
    """(seconds, peak traced memory [GiB]) of ``call()``."""
    tracemalloc.start()
    t0 = time.perf_counter()
    call()
    seconds = time.perf_counter() - t0
    peak = tracemalloc.get_traced_memory()[1] / 2**30
    tracemalloc.stop()
    return seconds, peak


def _process(args, runs: int = 3, cwd=None) -> float:
    """Median wall time [s] of a whole process, warm: after one run not timed, with Python's
    bytecode cache allowed as on a user's machine (an environment setting
    ``PYTHONDONTWRITEBYTECODE``, as this project's build machine does, would have each run
    compile the project's modules again: about 0.2 s more on a 2-core machine).
    """
    env = {name: value for name, value in os.environ.items() if name != "PYTHONDONTWRITEBYTECODE"}
    times = []
    for run in range(runs + 1):
        t0 = time.perf_counter()
        subprocess.run(args, check=True, capture_output=True, cwd=cwd, env=env)
        if run:
            times.append(time.perf_counter() - t0)
    return float(np.median(times))


def _real_bed_ratio(runs: int = 15) -> float:
    """A 200-point sweep of the Pure Drive (2021) and the default ball with its real string
    bed (stiffening, lossy and with a moving mass: fresh polyester 16L 16x19 at 55 lb), over
    the same sweep with the bed linear, lossless and massless: medians of interleaved warm
    calls.
    """
    from racket import default_ball

    real = CATALOG["pure-drive-2021"].racket()
    plain = replace(real, strings=replace(real.strings, stretch=0.0, loss=0.0, moving_mass=0.0))
    ball, (start, end) = default_ball(), real.strings.extent
    x = np.linspace(start, end, POINTS + 2)[1:-1]
    times = {"real": [], "plain": []}
    for racket in (real, plain):
        impact(racket, ball, x, 16.5)
    for _ in range(runs):
        for name, racket in (("real", real), ("plain", plain)):
            t0 = time.perf_counter()
            impact(racket, ball, x, 16.5)
            times[name].append(time.perf_counter() - t0)
    return float(np.median(times["real"]) / np.median(times["plain"]))


def _oblique_ratio(runs: int = 15) -> float:
    """A 200-point sweep of oblique impacts (issue 36: 8 m/s along the face, 3 m/s across,
    300 rad/s of backspin, on the Pure Drive's sliding mains) over the same sweep head-on:
    medians of interleaved warm calls.
    """
    from racket import default_ball, oblique_impact

    racket, ball = CATALOG["pure-drive-2021"].racket(), default_ball()
    start, end = racket.strings.extent
    x = np.linspace(start, end, POINTS + 2)[1:-1]
    calls = {
        "oblique": lambda: oblique_impact(
            racket, ball, x, 16.5, slip_velocity=(8.0, 3.0), spin=(0.0, -300.0, 0.0)
        ),
        "head-on": lambda: impact(racket, ball, x, 16.5),
    }
    return _interleaved_ratio(calls, runs)


def _bat_ratio(runs: int = 15) -> float:
    """A 200-point sweep along Nathan's R161 bat (issue 37: free, 18 Timoshenko modes, his
    baseball at 40 m/s onto the bat at rest, from the barrel's end to 40 cm from the knob)
    over the Pure Drive's 200-point sweep with the default ball at 16.5 m/s: medians of
    interleaved warm calls.  The target, 3, is the issue's "same time class": the bat keeps
    18 modes (the racket 12) and its ball leaves in about 1 ms.
    """
    from ball import baseball
    from bat import BATS
    from racket import default_ball

    bat, racket = BATS["r161"](), CATALOG["pure-drive-2021"].racket()
    x_bat = np.linspace(0.0, bat.beam.length - 0.40, POINTS)
    x_racket = np.linspace(*racket.strings.extent, POINTS + 2)[1:-1]
    calls = {
        "bat": lambda: impact(bat, baseball(), x_bat, 40.0),
        "racket": lambda: impact(racket, default_ball(), x_racket, 16.5),
    }
    return _interleaved_ratio(calls, runs)


def _interleaved_ratio(calls: dict, runs: int) -> float:
    """The median time of the first of two ``calls`` (name: function) over the second's:
    each called once first (warm), then ``runs`` times in turn.
    """
    times = {name: [] for name in calls}
    for call in calls.values():
        call()
    for _ in range(runs):
        for name, call in calls.items():
            t0 = time.perf_counter()
            call()
            times[name].append(time.perf_counter() - t0)
    first, second = (np.median(times[name]) for name in calls)
    return float(first / second)


def kernel_table(racket, ball) -> None:
    """The lockstep kernel against the scalar one by batch size (the kernel alone, on the
    threads the batch is worth).
    """
    print(f"{'impacts':>8} {'scalar ms':>10} {'lockstep ms':>12} {'speed-up':>9}")
    for count in (8, 16, 24, 32, 48, 64, 200, 10_000):
        x = np.linspace(0.0, 0.32, count)
        stepper = Stepper(racket, ball, x, None, SPEED, 0.0, None, DEFAULT_STEPS_PER_CONTACT)
        x_o = np.full(count, np.nan)
        runs = 5 if count > 1000 else 40
        scalar, lockstep = _kernels_side_by_side(lambda s=stepper, x_o=x_o: s.run(x_o), runs)
        print(
            f"{count:>8} {1e3 * scalar:>10.3f} {1e3 * lockstep:>12.3f} {scalar / lockstep:>8.2f}x"
        )
    print(
        f"(lockstep from {dispatch.LOCKSTEP_MIN} impacts per thread: "
        "racket.solver.dispatch.LOCKSTEP_MIN)"
    )


def main() -> None:
    """Print every figure beside its target and its baseline's."""
    warnings.simplefilter("ignore")
    _BASE.update(_baseline())
    print("baseline:", "recorded on this machine" if _BASE else "none for this machine")
    print(_load(), "(at the start)")
    racket, ball = paper_racket(), paper_ball()
    x = np.linspace(0.0, 0.32, POINTS)

    t0 = time.perf_counter()
    impact(racket, ball, x, SPEED)  # compiles (or loads the cached kernels)
    impact(racket, ball, 0.1, SPEED)
    warmup = time.perf_counter() - t0
    print(f"first calls {warmup:.2f} s (loading or compiling the kernels)\n")
    kernel_table(racket, ball)
    print()

    def points():
        return impact(racket, ball, x, SPEED)

    scalar, alternated = _kernels_side_by_side(points, runs=30)
    _median_time(points, runs=30)  # warm again after the scalar kernel's last call
    fast = _median_time(points, runs=200)
    _row(f"{POINTS}-point sweep, median warm", 1e3 * fast, "ms", 2.0)
    _row("  the same, moonshot", 1e3 * fast, "ms", 1.0)
    _row("  the same with the scalar kernel (no target)", 1e3 * scalar, "ms", None)
    _row("  the same, each call after a scalar one", 1e3 * alternated, "ms", None)
    print(f"{'  lockstep speed-up of the whole call':<48} {scalar / alternated:>10.3g} x")
    result = impact(racket, ball, x, SPEED)
    t0 = time.perf_counter()
    e_base = np.array([baseline_e(racket, ball, xi, SPEED) for xi in x])
    slow = time.perf_counter() - t0
    print(
        f"solve_ivp baseline, {POINTS} points: {slow:.1f} s; max |e - e_baseline| "
        f"{np.abs(result.e - e_base).max():.1e}"
    )
    _row("  speed-up over the solve_ivp baseline", slow / fast, "x", 5000, better="higher")
    print(f"{'  a real string bed (issue 35):':<48}")
    _row("  real bed (stiffening, lossy, massed) / linear", _real_bed_ratio(), "", 1.2)
    _row("  oblique, spinning / head-on (issue 36)", _oblique_ratio(), "", 1.5)
    _row("  a bat (R161) / a racket, 200 points (issue 37)", _bat_ratio(), "", 3.0)
    positions = iter(np.linspace(0.0, 0.32, 100_003)[1:])  # a new position each call
    _median_time(lambda: impact(racket, ball, next(positions), SPEED), runs=300)  # warm
    one = _median_time(lambda: impact(racket, ball, next(positions), SPEED), runs=1000)
    _row("single position (a new one each call), median", 1e3 * one, "ms", 0.2)
    many = np.linspace(0, 0.32, 100_000)
    _row("1e5 positions in one impact() call", _median_time(
        lambda: impact(racket, ball, many, SPEED), runs=3), "s", 1.0)  # fmt: skip
    grid = dict(
        speed=list(np.linspace(5.0, 40.0, 10)),
        string_stiffness=list(np.linspace(2e4, 6e4, 10)),
        f1=list(np.linspace(100.0, 190.0, 10)),
        progress=False,
    )
    along = np.linspace(0, 0.32, 1000)
    t0 = time.perf_counter()
    sweep(racket, ball, along, **grid)
    _row("1e6 impacts through studies.sweeps.sweep, untraced", time.perf_counter() - t0, "s", 12.0)
    seconds, peak = _traced(lambda: sweep(racket, ball, along, **grid))
    _row("  the same traced (tracemalloc)", seconds, "s", 30.0)
    _row("  peak traced memory", peak, "GiB", 0.5)
    for mass, k0 in ((0.0103, 2e4), (0.057, 4e4)):
        unhappy = Ball(mass, SineLaw(k0=k0))
        seconds = _median_time(lambda u=unhappy: impact(racket, u, x, SPEED), runs=3)
        _row(f"unhappy ball {1e3 * mass:g} g, {POINTS} points", seconds, "s", 0.5)
    coarse = np.linspace(0.0, 0.32, 20)
    converged = impact(
        racket, ball, coarse, SPEED, steps_per_contact=16 * DEFAULT_STEPS_PER_CONTACT
    )
    error = np.abs(impact(racket, ball, coarse, SPEED).e - converged.e).max()
    _row("default accuracy: max |e - e(16x steps)|", error, "", 2e-5)
    default, itf = default_racket(), default_ball()
    start, end = default.strings.extent
    along = np.linspace(start, end, 22)[1:-1]
    converged = impact(default, itf, along, 16.5, steps_per_contact=16 * DEFAULT_STEPS_PER_CONTACT)
    error = np.abs(impact(default, itf, along, 16.5).e - converged.e).max()
    _row("  the same, default racket and ball, 16.5 m/s", error, "", 2e-5)
    along = np.linspace(start, end, POINTS + 2)[1:-1]
    _row("default racket and ball, 200 points, median warm", 1e3 * _median_time(
        lambda: impact(default, itf, along, 16.5), runs=30), "ms", None)  # fmt: skip
    held = replace(racket, support="hand-held")
    held_ms = 1e3 * _median_time(lambda: impact(held, ball, x, SPEED), runs=30)
    print(f"{'hand-held racket, 200 points (no target)':<48} {held_ms:>10.3g} ms")
    entry = CATALOG["pure-drive-2021"]
    fit_ms = 1e3 * _median_time(lambda: entry.racket().beam.modes)
    print(f"{'fit to a spec sheet incl. modes (no target)':<48} {fit_ms:>10.3g} ms")
    face = entry.racket()
    face_map(face, ball, 16.5)  # its systems built once, as for any map after the first
    _row("face map 15 x 9, spec-sheet racket (warm)", _median_time(
        lambda: face_map(face, ball, 16.5)), "s", 1.0)  # fmt: skip
    held_face = replace(face, support="hand-held")
    face_map(held_face, ball, 16.5)
    _row("  the same, hand-held (warm)", _median_time(
        lambda: face_map(held_face, ball, 16.5)), "s", 1.0)  # fmt: skip
    print()
    _row("python -c 'import racket'", _process([sys.executable, "-c", "import racket"]), "s", 0.3)
    cli = [sys.executable, "-m", "studies.cli"]
    with tempfile.TemporaryDirectory() as tmp:
        _row(
            "racket-impact sweep (cached kernel)",
            _process([*cli, "sweep", "--out", "s.csv"], cwd=tmp),
            "s",
            1.0,
        )
        _row("racket-impact paper (warm)", _process([*cli, "paper"], runs=1, cwd=tmp), "s", 4.0)
    print(_load(), "(at the end)")


if __name__ == "__main__":
    if sys.argv[1:2] == ["--record-baseline"]:
        record_baseline(sys.argv[2])
    else:
        main()
        if sys.argv[1:2] == ["--json"]:  # (what --record-baseline reads)
            with open(sys.argv[2], "w") as out:
                json.dump(FIGURES, out)
