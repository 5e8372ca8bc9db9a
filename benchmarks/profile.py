"""Where a sweep's time goes (issue 47): the profile ``docs/developer.md`` quotes.

    python benchmarks/profile.py

Prints, for a 200-point sweep of the paper racket (the benchmark's, a linear ball) and of the
default racket (the Pure Drive with its real string bed and the ITF type 2 ball, stiffening):

* the step, the steps per contact and per impact, the blocks;
* the call split into the racket's set-up for the points (:class:`racket.solver.stepper.
  Stepper`), the kernel, and the rest of :func:`racket.impact` (the outcome's energies, the
  budget's check): medians of warm calls, in CPU time (the machine is shared);
* the kernel's cost per impact and step, and how it grows from the linear ball on a linear bed
  (the lockstep kernel's vectorised passes alone) to the stiffening ball (its force solved
  impact by impact) and to the real bed (a second law and the bed's mass): the same racket's
  200 points each time;
* the lockstep kernel's passes over a tile of 64 impacts, each timed alone (:func:`_passes`),
  as shares of one step of the tile.

All in one run: read the ratios, not the absolute times.
"""

from __future__ import annotations

import os
import time
from dataclasses import replace

import numpy as np
from numba import njit

from racket import CATALOG, default_ball, impact, paper_ball, paper_racket
from racket.solver import DEFAULT_STEPS_PER_CONTACT, lockstep
from racket.solver.layout import T_CONTACT, T_END
from racket.solver.stepper import Stepper

POINTS = 200
RUNS = 21


def _cpu(call, runs: int = RUNS) -> float:
    """Least CPU time [s] of ``call`` over ``runs`` calls (every thread of the process; the
    least, as other processes sharing the cores only add to it).
    """
    times = []
    for _ in range(runs):
        start = time.process_time()
        call()
        times.append(time.process_time() - start)
    return min(times)


def _stepper(racket, ball, x, speed):
    return Stepper(
        racket, ball, x, None, np.full(x.size, speed), 0.0, None, DEFAULT_STEPS_PER_CONTACT
    )


def split(name, racket, ball, x, speed) -> float:
    """Print the call's split and the steps; returns the kernel's CPU time per impact-step."""
    impact(racket, ball, x, speed)
    stepper = _stepper(racket, ball, x, speed)
    nan = np.full(x.size, np.nan)
    out = stepper.run(nan)
    contact = out.summary[:, T_CONTACT] / stepper.dt
    left = out.summary[:, T_END] / stepper.dt
    total = _cpu(lambda: impact(racket, ball, x, speed))
    kernel = _cpu(lambda: stepper.run(nan))
    setup = _cpu(lambda: _stepper(racket, ball, x, speed))
    per_step = kernel / left.sum()
    print(f"{name}: {x.size} points at {speed:g} m/s, {stepper.frame.trans.shape[0]} blocks")
    print(f"  step {1e6 * stepper.dt:.3g} us; steps in contact {contact.mean():.0f} per impact")
    print(f"  (the contact time's {DEFAULT_STEPS_PER_CONTACT} are for the stiffest spot's")
    print(f"  shortest contact); steps to the ball's last leaving {left.mean():.0f}")
    rest = total - kernel - setup
    print(f"  CPU per call {1e3 * total:.2f} ms: set-up {_share(setup, total)}, kernel ")
    print(f"  {_share(kernel, total)}, the rest (outcome, budget) {_share(rest, total)}")
    print(f"  kernel per impact and step {1e9 * per_step:.0f} ns")
    return per_step


def _share(part: float, whole: float) -> str:
    return f"{1e3 * part:.2f} ms ({100 * part / whole:.0f} %)"


def passes(racket, ball, x, speed) -> None:
    """Print each lockstep pass's share of one step of a full tile (the paper racket)."""
    from racket.solver import tile_layout as tl

    stepper = _stepper(racket, ball, x[: tl.TILE], speed)
    nb = stepper.frame.trans.shape[0]
    n = tl.TILE
    rng = np.random.default_rng(0)
    w = rng.normal(size=(tl.N_ROWS, nb, n)) * 1e-3
    v = np.abs(rng.normal(size=(tl.N_SCALARS, n)))
    f = stepper.frame
    # a free racket's blocks read the point's row alone (lockstep._modal)
    shapes = np.stack([f.g0[:, 0, 1], f.g0[:, 1, 1], f.g1[:, 0, 1], f.g1[:, 1, 1]], axis=1)
    reps = 20000
    kinds = {
        "ball's free step": 0,
        "blocks' free step (and the point)": 1,
        "linear ball's force": 2,
        "ball's response": 3,
        "blocks' response and damping power": 4,
        "bookkeeping": 5,
    }
    times = {}
    for name, kind in kinds.items():
        _one_pass(1, kind, f.trans, shapes, f.damp_blocks, f.damp_rows, w, v, n)
        start = time.process_time()
        _one_pass(reps, kind, f.trans, shapes, f.damp_blocks, f.damp_rows, w, v, n)
        times[name] = (time.process_time() - start) / reps
    step = sum(times.values())
    print(f"lockstep passes over a tile of {n} impacts, {nb} blocks: {1e9 * step / n:.1f} ns")
    print("  per impact and step, of which")
    for name, t in times.items():
        print(f"    {name:<36} {100 * t / step:5.1f} %")


@njit(cache=False)
def _one_pass(reps, kind, trans, shapes, damp_blocks, damp_rows, w, v, n):
    """Pass ``kind`` of the lockstep kernel's step (:mod:`racket.solver.lockstep`), ``reps``
    times over the tile's ``n`` impacts (states ``w``, scalars ``v``; their values are
    immaterial to the time).
    """
    s0, s1 = w[0], w[1]
    gin0_0, gin0_1, gin1_0, gin1_1, out_d0, out_d1 = w[2], w[3], w[4], w[5], w[6], w[7]
    u, ud, u_p, ud_p, z, tau = v[0], v[1], v[17], v[18], v[19], v[16]
    force, f_new, f_before, f_peak = v[2], v[20], v[3], v[4]
    c0, c1, c2 = v[6], v[7], v[8]
    power, power_prev, damping, need = v[21], v[14], v[12], v[23]
    stop_at = np.zeros(n, dtype=np.int64)
    recontacts = np.zeros(n, dtype=np.int64)
    for _ in range(reps):
        if kind == 0:
            lockstep._ball_free(1.0, 1e-5, 0.0, 1.0, 1e-9, 1e-5, u, ud, force, u_p, ud_p, z, n)
        elif kind == 1:
            lockstep._free_blocks(trans, shapes, True, s0, s1, gin0_0, gin0_1, out_d0, out_d1,
                                  force, z, n)  # fmt: skip
        elif kind == 2:
            lockstep._linear_force(u_p, z, c0, c1, c2, f_peak, f_new, n)
        elif kind == 3:
            lockstep._ball_force(1e-9, 1e-5, u_p, ud_p, f_new, u, ud, tau, n)
        elif kind == 4:  # (a free racket's modal damping: one block a row)
            lockstep._force_blocks(shapes, True, s0, s1, gin1_0, gin1_1, out_d0, f_new,
                                          damp_blocks, damp_rows, power, n)  # fmt: skip
        else:
            lockstep._bookkeep(power, power_prev, damping, force, f_new, f_before, f_peak, need,
                               stop_at, recontacts, 1e-5, 0.0, n)  # fmt: skip


def main() -> None:
    """Print the profile."""
    print(f"load average {os.getloadavg()[0]:.2f} (at the start)")
    paper, ball = paper_racket(), paper_ball()
    split("paper racket, linear ball", paper, ball, np.linspace(0.0, 0.32, POINTS), 10.0)
    print()
    one = np.array([0.16])
    total = _cpu(lambda: impact(paper, ball, one, 10.0), 101)
    stepper = _stepper(paper, ball, one, 10.0)
    kernel = _cpu(lambda: stepper.run(np.full(1, np.nan)), 101)
    setup = _cpu(lambda: _stepper(paper, ball, one, 10.0), 101)
    print(f"one position (paper racket): CPU per call {1e3 * total:.3f} ms: set-up")
    print(f"  {_share(setup, total)}, kernel {_share(kernel, total)}, the rest")
    print(f"  {_share(total - kernel - setup, total)}")
    print()
    real = CATALOG["pure-drive-2021"].racket()
    start, end = real.strings.extent
    x = np.linspace(start, end, POINTS + 2)[1:-1]
    linear_bed = replace(real.strings, stretch=0.0, loss=0.0, moving_mass=0.0)
    stiff = default_ball()
    linear_ball = replace(stiff, law=paper_ball().law)
    costs = {}
    for name, racket, b in (
        ("Pure Drive, linear ball, linear bed", replace(real, strings=linear_bed), linear_ball),
        ("Pure Drive, ITF ball, linear bed", replace(real, strings=linear_bed), stiff),
        ("Pure Drive, ITF ball, its real bed (the default)", real, stiff),
    ):
        costs[name] = split(name, racket, b, x, 16.5)
        print()
    base = next(iter(costs.values()))
    print("kernel per impact and step, over the linear ball on the linear bed:")
    for name, cost in costs.items():
        print(f"  {name:<50} {cost / base:5.2f}")
    print()
    passes(paper, ball, np.linspace(0.0, 0.32, POINTS), 10.0)
    print(f"load average {os.getloadavg()[0]:.2f} (at the end)")


if __name__ == "__main__":
    main()
