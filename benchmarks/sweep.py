"""Time a 200-point impact sweep of the paper's racket against a per-impact solve_ivp baseline.

    python benchmarks/sweep.py

The baseline is the straightforward implementation: for each impact point, integrate the
ball and every mode (rigid-body and bending) with scipy's solve_ivp (RK45, rtol 1e-8) in
two phases, loading until the compression peaks and unloading until the force vanishes.
Prints both times, their ratio and the largest difference in e; then the same sweep on the
hand-held racket (coupled modes), the unhappy ball's sweep (its Xo search included; target
< 1 s for 200 points) and the time to fit a racket to a spec sheet.
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np
from scipy.integrate import solve_ivp

from ball import Ball, SineLaw
from racket import CATALOG, impact, paper_racket, tennis_ball

POINTS = 200
SPEED = 10.0


def baseline_e(racket, ball, position, speed):
    """e at one impact point by solve_ivp on [u, u', q, q'] (the straightforward way)."""
    modes = racket.beam.modes
    phi = modes.shape(position)[:, 0]
    w, zeta = modes.omega, modes.damping
    k, e_ball, k_s = ball.law.k, ball.law.e, racket.strings.stiffness
    n = phi.size

    def force(z, f_max):
        f = z / (1 / k + 1 / k_s)
        if f >= f_max:
            return f
        return max((z - f_max * (1 - e_ball**2) / k) / (e_ball**2 / k + 1 / k_s), 0.0)

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


def _median_time(call, runs: int = 10) -> float:
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        call()
        times.append(time.perf_counter() - t0)
    return float(np.median(times))


def main() -> None:
    racket, ball = paper_racket(), tennis_ball()
    x = np.linspace(0.0, 0.32, POINTS)

    t0 = time.perf_counter()
    impact(racket, ball, x, SPEED)  # compiles (or loads the cached kernel)
    warmup = time.perf_counter() - t0
    fast = _median_time(lambda: impact(racket, ball, x, SPEED))
    result = impact(racket, ball, x, SPEED)

    t0 = time.perf_counter()
    e_base = np.array([baseline_e(racket, ball, xi, SPEED) for xi in x])
    slow = time.perf_counter() - t0

    print(
        f"racket-impact sweep, {POINTS} points: {fast * 1e3:.1f} ms (median of 10; "
        f"first call {warmup:.2f} s incl. compilation)"
    )
    print(f"solve_ivp baseline, {POINTS} points:  {slow * 1e3:.0f} ms")
    print(f"speed-up: {slow / fast:.0f}x")
    print(f"max |e - e_baseline|: {np.abs(result.e - e_base).max():.2e}")
    held = replace(racket, support="hand-held")
    print(
        f"hand-held racket, {POINTS} points: "
        f"{_median_time(lambda: impact(held, ball, x, SPEED)) * 1e3:.1f} ms (median of 10)"
    )
    for mass, k0 in ((0.0103, 2e4), (0.057, 4e4)):
        unhappy = Ball(mass, SineLaw(k0=k0))
        seconds = _median_time(lambda u=unhappy: impact(racket, u, x, SPEED), runs=3)
        print(
            f"unhappy ball ({1e3 * mass:g} g, k0 {k0:g} N/m), {POINTS} points: {seconds:.2f} s "
            f"(median of 3; target < 1 s, {seconds / fast:.0f}x the tennis ball's sweep)"
        )
    entry = CATALOG["pure-drive-2021"]
    print(
        f"fit to a spec sheet (from_specs, incl. the modes): "
        f"{_median_time(lambda: entry.racket().beam.modes) * 1e3:.0f} ms (median of 10)"
    )


if __name__ == "__main__":
    main()
