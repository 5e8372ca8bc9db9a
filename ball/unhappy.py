"""Collisions of the unhappy ball (sine law, Eq. 7) with a monotone partner (Eqs. 8-11).

The difficulty
--------------
The unhappy ball's force F = k0 Xo sin(pi X / Xo) rises and then falls while its
compression X only grows.  In series with a partner of compression Y = g(F), the total
compression is z = X + Y = H(theta), with the phase theta = pi X / Xo in [0, pi] and

    H(theta) = Xo theta / pi + g(k0 Xo sin theta).

Once the sine law's negative slope beats the partner's stiffness (pi k0 cos(theta) < -k2
for a linear partner), H turns over: it has a maximum, a *fold*, at theta*.  Past the fold
the split of a given z into X and Y has two solutions, and a root-finder that solves
X + Y = z at each time step for X jumps between them.  Integrating in time with X as a
state does not help: dX/dt = (dz/dt) / H'(theta) is 0/0 at the fold.

The method
----------
Use the phase theta, which never decreases, as the independent variable instead of time.
Along the collision z = H(theta), and the relative motion mu z'' = -F gives the energy
equation (Eqs. 8-11 combined, exactly)

    s(theta) = mu (dz/dt)**2 / 2 = mu v**2 / 2 - W(theta),   W(theta) = int_0^theta F H' dtheta,

and the time follows from dt/dtheta = |H'(theta)| / sqrt(2 s / mu).

*Self-consistent Xo.*  Xo is the compression at which the ball's force returns to zero, and
the collision must end there.  The approach (dz/dt > 0) can only turn into separation
where H stops rising, so the approach must end exactly at theta* = argmax H: s(theta*) = 0,
i.e. W(theta*; Xo) = mu v**2 / 2, which fixes Xo (solved by Brent's method; W grows with Xo).
A smaller Xo would leave the balls still approaching at the fold, with no continuous way
on (a snap-through); a larger one would stop the approach before it, and the ball would end
with X < Xo, contradicting the definition of Xo.

*Both regimes, exactly.*  With the fold inside (0, pi) (k2 < pi k0 for a linear partner),
s rises again past theta* as the partner gives back its energy, the contact opens at
theta = pi where F = 0, and the balls separate with mu V**2 / 2 = W(theta*) - W(pi): for a
linear partner this is Eq. 16 exactly (Eqs. 12-15 are the exact solution there, with
theta = omega t).  Without a fold (k2 >= pi k0, or the rigid wall) theta* = pi: the balls
approach their common speed exponentially as theta -> pi and the COR is zero, as in
Figs. 2 and 4.  The contact then never ends in finite time: the integration stops when the
force has fallen to ``force_tol`` times its peak, and the final state is the exact limit
theta -> pi (common speed, zero force, X = Xo).

*Numerics.*  s is integrated outward from theta* (cumulative Simpson rule on a grid
clustered at both ends of each interval), so it keeps full relative accuracy where it
vanishes, and dt/dtheta stays finite there (both |H'| and sqrt(s) vanish linearly).
"""

from __future__ import annotations

import functools
import itertools
from typing import NamedTuple

import numpy as np
from scipy.integrate import cumulative_simpson
from scipy.optimize import brentq

from ball.contact import RelativeContact
from ball.laws import MonotoneLaw, SineLaw

_NODES = 8001  # grid points per interval of theta
_BRACKET_STEPS = 60  # halvings or doublings of Xo when bracketing it


def _clustered(a: float, b: float, n: int = _NODES) -> np.ndarray:
    """Up to n points from a to b, clustered quadratically at both ends; points that
    coincide in floating point (a tiny interval) are dropped, so the grid strictly rises.
    """
    return np.unique(a + (b - a) * 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, n))))


class _Phases(NamedTuple):
    """A grid of phases theta [rad] with their sines and cosines [-], read-only: one that
    every Xo Brent's method tries is evaluated on, its trigonometry computed once.
    """

    theta: np.ndarray
    sin: np.ndarray
    cos: np.ndarray


def _phases(theta: np.ndarray) -> _Phases:
    """The :class:`_Phases` of the grid ``theta`` [rad]."""
    kept = _Phases(theta, np.sin(theta), np.cos(theta))
    for values in kept:
        values.flags.writeable = False
    return kept


@functools.cache
def _fold_phases() -> _Phases:
    """The grid :meth:`_Path.fold` looks for the fold on: pi/2 to pi, 4097 points."""
    return _phases(np.linspace(0.5 * np.pi, np.pi, 4097))


@functools.lru_cache(maxsize=16)
def _work_phases(a: float, b: float) -> _Phases:
    """The grid :meth:`_Path.work` integrates on from ``a`` to ``b`` [rad]: :func:`_clustered`
    on each side of pi/2, where the partner turns from loading to unloading.

    Kept: every Xo that Brent's method tries integrates from 0 to the same fold (pi
    without one; a linear partner puts it at the same phase for any Xo), and each grid costs
    a sort and a sine and cosine of its points.  The key is two numbers, so nothing
    invalidates an entry; beyond 16 (0.4 MB each) the least recently used go.
    """
    cuts = [a, *([0.5 * np.pi] if a < 0.5 * np.pi < b else []), b]
    pieces = [_clustered(p, q) for p, q in itertools.pairwise(cuts)]
    return _phases(np.concatenate([pieces[0], *(piece[1:] for piece in pieces[1:])]))


class _Path:
    """Force, compressions and H'(theta) of the unhappy ball and its partner for one Xo."""

    def __init__(self, sine: SineLaw, partner: MonotoneLaw | None, x_o: float):
        self.sine, self.partner, self.x_o = sine, partner, x_o
        self.f_o = sine.k0 * x_o

    def state(self, theta):
        """Force [N], sine-ball compression [m], partner compression [m], dH/dtheta [m] at
        the phases ``theta`` [rad] (or a kept grid of them, :class:`_Phases`).
        """
        kept = theta if isinstance(theta, _Phases) else None
        theta = theta if kept is None else kept.theta
        force = self.f_o * (np.sin(theta) if kept is None else kept.sin)
        x = self.x_o * theta / np.pi
        h_prime = np.full(np.shape(theta), self.x_o / np.pi)
        if self.partner is None:
            return force, x, np.zeros_like(x), h_prime
        # The partner loads while the force rises (theta <= pi/2) and unloads from Fo after.
        f_max = np.where(theta <= 0.5 * np.pi, force, self.f_o)
        y = self.partner.compression(force, f_max)
        with np.errstate(invalid="ignore"):
            cos = np.cos(theta) if kept is None else kept.cos
            h_prime = h_prime + self.partner.compliance(force, f_max) * self.f_o * cos
        return force, x, y, h_prime

    def power(self, theta):
        """F dH/dtheta [J/rad], the integrand of W; zero where F = 0 even if H' is infinite
        there (F g'(F) -> 0 as F -> 0 for every monotone law).
        """
        force, _, _, h_prime = self.state(theta)
        with np.errstate(invalid="ignore"):
            return np.where(force > 0, force * h_prime, 0.0)

    def fold(self) -> float:
        """theta* = argmax H: the first zero of H' past pi/2, or pi if H rises throughout."""
        phases = _fold_phases()
        grid, h_prime = phases.theta, self.state(phases)[3]
        down = np.nonzero(~(h_prime > 0))[0]
        if down.size == 0:
            return np.pi
        i = down[0]
        if np.any(h_prime[i:] > 0):
            raise ValueError(
                f"partner {self.partner!r} softens as it unloads (compliance falling with "
                "force), so the unhappy ball would have to stop and restart compressing: "
                "use a partner whose unloading exponent is >= 1"
            )
        if i == 0:
            return 0.5 * np.pi
        return brentq(lambda th: float(self.state(th)[3]), grid[i - 1], grid[i], xtol=1e-15)

    def work(self, a: float, b: float) -> float:
        """int_a^b F H' dtheta [J]: work done on the contact as theta goes from a to b."""
        phases = _work_phases(a, b)
        return float(cumulative_simpson(self.power(phases), x=phases.theta)[-1])


def _solve_x_o(sine: SineLaw, partner: MonotoneLaw | None, energy: float) -> float:
    """The self-consistent Xo [m]: the approach ends at the fold, W(theta*; Xo) = energy."""

    def residual(x_o):
        path = _Path(sine, partner, x_o)
        return path.work(0.0, path.fold()) - energy

    # Start from the rigid-wall value (2 k0 Xo**2 / pi = energy) and bracket outwards.
    x_o = np.sqrt(np.pi * energy / (2.0 * sine.k0))
    lo, hi = x_o, x_o
    r_lo = r_hi = residual(x_o)
    for _ in range(_BRACKET_STEPS):
        if r_lo <= 0:
            break
        lo *= 0.5
        r_lo = residual(lo)
    for _ in range(_BRACKET_STEPS):
        if r_hi >= 0:
            break
        hi *= 2.0
        r_hi = residual(hi)
    if r_lo > 0 or r_hi < 0:
        raise RuntimeError(
            f"no Xo within 2**{_BRACKET_STEPS} of the rigid wall's {x_o:.3g} m balances the "
            "collision's energy"
        )
    if lo == hi:
        return lo
    return brentq(residual, lo, hi, xtol=1e-16 * hi, rtol=4 * np.finfo(float).eps)


def unhappy_contact(
    sine: SineLaw,
    partner: MonotoneLaw | None,
    mu: float,
    closing_speed: float,
    samples: int = 400,
    force_tol: float = 1e-6,
) -> RelativeContact:
    """Integrate an unhappy-ball contact in its phase theta (see the module docstring).

    Parameters
    ----------
    sine : SineLaw
        The unhappy ball's law.
    partner : MonotoneLaw or None
        The other body's law; None for the rigid wall.
    mu : float
        Reduced mass [kg].
    closing_speed : float
        Approach speed at first touch [m/s], > 0.
    samples : int
        History points returned.
    force_tol : float
        Without a fold the force decays to zero only as t -> infinity; stop when it has
        fallen to this fraction [-] of its peak.

    Returns
    -------
    RelativeContact
        ``compression_a`` is the unhappy ball's, ``compression_b`` the partner's.
    """
    energy = 0.5 * mu * closing_speed**2
    x_o = _solve_x_o(sine, partner, energy)
    path = _Path(sine, partner, x_o)
    theta_star = path.fold()
    theta_end = np.pi if theta_star < np.pi else np.pi - np.arcsin(force_tol)

    # Approach: 0 -> pi/2 -> theta*; separation: theta* -> theta_end.
    approach = np.concatenate(
        [_clustered(0.0, min(0.5 * np.pi, theta_star)), _clustered(0.5 * np.pi, theta_star)[1:]]
    )
    if theta_star >= theta_end:
        approach = np.append(approach[approach < theta_end], theta_end)
    force, x, y, h_prime = path.state(approach)
    # s from theta* backwards: s(theta) = int_theta^theta* F H' dtheta.
    tail = cumulative_simpson(path.power(approach)[::-1], x=-approach[::-1], initial=0.0)[::-1]
    s_approach = np.maximum(tail, 0.0)
    if theta_star >= theta_end:  # no fold: the approach ends at theta_end, not at rest
        s_approach = s_approach + path.work(theta_end, np.pi)
    parts = [(approach, force, x, y, h_prime, s_approach, 1.0)]
    sep = _clustered(theta_star, theta_end)
    if sep.size > 2:
        f_s, x_s, y_s, hp_s = path.state(sep)
        s_sep = np.maximum(-cumulative_simpson(path.power(sep), x=sep, initial=0.0), 0.0)
        parts.append((sep[1:], f_s[1:], x_s[1:], y_s[1:], hp_s[1:], s_sep[1:], -1.0))

    theta = np.concatenate([p[0] for p in parts])
    force = np.concatenate([p[1] for p in parts])
    x = np.concatenate([p[2] for p in parts])
    y = np.concatenate([p[3] for p in parts])
    h_prime = np.concatenate([p[4] for p in parts])
    s = np.concatenate([p[5] for p in parts])
    sign = np.concatenate([np.full(p[0].size, p[6]) for p in parts])
    speed = sign * np.sqrt(2.0 * s / mu)
    if theta_star >= theta_end:
        # No fold: the last point is the exact limit theta -> pi (common speed, F = 0,
        # X = Xo), reached at the time the force fell to force_tol of its peak.
        force[-1], x[-1], speed[-1] = 0.0, x_o, 0.0
        y[-1] = 0.0 if partner is None else partner.compression(0.0, path.f_o)

    with np.errstate(divide="ignore", invalid="ignore"):
        rate = np.abs(h_prime) / np.abs(speed)  # dt/dtheta
    bad = ~np.isfinite(rate)  # 0/0 at the fold, or an infinitely soft partner at theta = 0
    good = np.nonzero(~bad)[0]
    rate[bad] = rate[good[np.clip(np.searchsorted(good, np.nonzero(bad)[0]), 0, good.size - 1)]]
    t = np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(theta))])

    keep = np.unique(
        np.concatenate(
            [
                np.linspace(0, theta.size - 1, samples).round().astype(int),
                [int(np.argmin(np.abs(theta - 0.5 * np.pi)))],  # the force peak
            ]
        )
    )
    return RelativeContact(
        t=t[keep],
        force=force[keep],
        compression_a=x[keep],
        compression_b=y[keep],
        closing_speed=speed[keep],
        dissipated_a=float(sine.dissipated(x_o, x[-1])),
        dissipated_b=0.0 if partner is None else float(partner.dissipated(path.f_o)),
        x_o=x_o,
    )
