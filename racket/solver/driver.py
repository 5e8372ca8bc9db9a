"""Ball impacts on a flexible racket (paper Sec. VII).

:func:`impact` drives the racket's modes with the ball's force law in series with the
string bed, for one impact point or many at once, and splits the racket's motion at the
moment the ball finally leaves (after any re-contact) into its dc part (the rigid-body
modes) and its ac part (the bending modes):

* e_A = V1 / v1, the apparent COR, from the ball's speeds;
* e = (V1 + V2) / v1 with V2 = V_cm + b omega the dc speed of the impact point (Eq. 21),
  V_cm and omega the racket's momentum and angular momentum over its mass and moment of
  inertia (for a free racket, its rigid-body modes);
* e_van_zandt, the same with the whole impact-point speed at separation, vibration
  included (Van Zandt's error, Sec. VII);
* the energy budget: ball and racket kinetic energy, vibration energy per mode, the energy
  lost in the ball and to modal damping, and the residual that shows it closes.

Every outcome is the state at that moment.  The stepping goes on after it, to catch a
re-contact, until the gap exceeds the reach of the remaining vibration; for a hand-held
racket the hand keeps pushing meanwhile, so a later moment would give another momentum,
and another e.

The unhappy ball (sine law, Eq. 7) needs its Xo, the compression at which its force returns
to zero, which the collision itself decides: Xo is the smallest for which the contact never
pushes the ball past its fold (or a spent ball again), found per impact by a scan and a
refinement (:func:`_self_consistent_x_o`).  The impact is *self-consistent* when the ball
then leaves with its compression at Xo; on a vibrating frame near the tip the frame can
unload the ball before it reaches its fold, for every Xo that does not snap.  There is then
no self-consistent Xo; the smallest that does not snap is kept (it leaves the ball closest
to Xo: the compression at separation falls further below Xo as Xo grows), the impact is
flagged (``Impact.self_consistent``) and a warning says how many are.
"""

from __future__ import annotations

import contextlib
import math
import warnings
from typing import NoReturn

import numpy as np

from ball import Ball, SineLaw, warn_if_squashed
from common.checks import finite, finite_array, in_range, shown
from common.checks import speed as check_speed
from common.typechecks import flag, instance
from racket.implement import Implement
from racket.solver import closure, layout
from racket.solver.dispatch import IMPACTS_PER_THREAD, LOCKSTEP_MIN, one_blas_thread, pool_size
from racket.solver.dispatch import compile_notice as _compile_notice  # noqa: F401  (kept importable here)
from racket.solver.outcome import (  # noqa: F401  (as above)
    SELF_CONSISTENT_TOL,
    Impact,
    history_bound,
    outcome,
)
from racket.solver.stepper import Stepper as _Stepper
from racket.solver.stepper import contact_time_scale
from racket.solver.unhappy_search import SCAN_RATIO, unhappy_x_o  # noqa: F401  (as above)
from racket.swing import ARM_REACH

DEFAULT_STEPS_PER_CONTACT = 300
"""Time steps per estimated contact time for the monotone ball laws.  With the static
correction for the modes left out and the contact's opening placed within its step, e is
within 1.2e-5 of a 64-mode, 9600-step solution at every point of the paper racket (free and
hand-held; linear, elastic and power-law balls at 20 m/s), and the error falls as dt**2
(``benchmarks/accuracy.py`` measures the frontier of steps and modes)."""

SINE_STEPS_PER_CONTACT = 600
"""Time steps per estimated contact time for the unhappy ball (sine law), whose fold and
opening are not placed within their step: e within 1.6e-5 of a 2400-step solution on the
paper racket (10.3 g and 57 g balls at 10 m/s)."""

PIVOT_BEYOND_BUTT = ARM_REACH
"""Farthest swing pivot beyond the butt [m] (:data:`racket.swing.ARM_REACH`)."""

F1_MIN = 20.0
"""Lowest first bending frequency [Hz] of a frame that the impact solver accepts (at 10 Hz
the paper racket's contact no longer ends within its step budget)."""

CONTACT_TIME_MAX = 0.02
"""Longest contact [s] (ball and strings in series on an immovable frame) the solver
accepts; a tennis ball's lasts 4-5 ms (paper Sec. III).  Above about 40 ms (a ball softer
than about 300 N/m) the frame's vibration over such a long contact is no longer resolved
at the default step and an elastic ball can come out with e = 1.000004."""


CHUNK_POINTS = 4096
"""Impacts run together at most (without histories): bounds the memory of a call to about
10 MB however many positions it is given."""


def impact(
    racket: Implement,
    ball: Ball,
    position,
    speed: float,
    *,
    offset=None,
    swing_speed=0.0,
    pivot: float | None = None,
    steps_per_contact: int | None = None,
    watch_after: float = 0.0,
    histories: bool | str = False,
) -> Impact:
    """A ball hits the racket head-on at ``position``, normal to the string plane.

    Parameters
    ----------
    racket : Implement
        The racket (:class:`racket.Racket`) or bat (:class:`bat.Bat`, struck on its own
        surface), initially still
        unless ``swing_speed`` > 0.
    ball : Ball
        The ball (any law of :mod:`ball`, the unhappy SineLaw included).
    position : float or array_like
        Impact point(s) [m from the tip], on the strings; an array runs all impacts together.
    speed : float
        Ball speed towards the strings [m/s], 0 or in [0.001, 300] (> 0 unless the racket
        is swung).
    offset : float or array_like, optional
        Distance of the impact point(s) from the racket's long axis [m, + towards 3
        o'clock], broadcast with ``position`` (to at most one dimension); the point must
        lie on the elliptical string bed.  Given (even 0), the racket's roll and torsion
        modes join the bending ones (the beam's roll inertia must be modelled, as on a
        spec-sheet racket); None (default): impacts on the long axis, bending only.
    swing_speed : float or array_like
        Speed [m/s] of the impact point towards the ball from the racket's rigid-body
        motion (a swing), 0 or in [0.001, 300]; 0 for a racket at rest.  An array gives each
        impact point its own (broadcast with the points), e.g. from one swing about a pivot
        (:meth:`racket.Swing.point_speeds`).
    pivot : float, optional
        The swing's instantaneous centre of rotation [m from the tip], beyond every impact
        point and at most 1 m beyond the butt (e.g. the wrist, 5 cm beyond it); None for
        pure translation.
    steps_per_contact : int, optional
        Time steps per estimated contact time, in [50, 100000]; default
        ``DEFAULT_STEPS_PER_CONTACT`` (300), ``SINE_STEPS_PER_CONTACT`` (600) for the
        unhappy ball.
    watch_after : float
        Extra time [s], in [0, 1], to keep stepping after the solver has decided that the
        ball has left for good, watching for another contact; the outcome does not depend
        on it unless that decision was wrong.
    histories : bool or str
        ``"force"``: also return the force's history alone (recorded in the run itself:
        what :func:`racket.oblique_impact` needs, at a small cost).  True: also return the
        histories (force, compressions, velocities against time; recorded in the run
        itself when they fit in :data:`racket.solver.outcome.HISTORY_MEMORY`, else the
        impacts run twice, the second time recording); None otherwise.

    Returns
    -------
    Impact

    Raises
    ------
    ValueError
        For an input out of its range, a frame whose first bending (or, off the axis,
        torsion) mode is below ``F1_MIN`` (20 Hz), or a ball and strings so soft that the
        contact would last more than ``CONTACT_TIME_MAX`` (20 ms).

    References
    ----------
    .. [1] R. Cross, Am. J. Phys. 68, 1025-1031 (2000), doi:10.1119/1.1285945.

    Examples
    --------
    >>> from racket import paper_racket, paper_ball
    >>> r = impact(paper_racket(), paper_ball(), 0.16, 10.0)  # the string centre
    >>> round(r.e, 3), round(r.e_A, 3)
    (0.887, 0.442)
    """
    instance("racket", racket, Implement, "a racket.Racket or bat.Bat")
    instance("ball", ball, Ball, "a ball.Ball")
    if histories is not False and histories != "force":
        histories = flag("histories", histories)
    scalar = _one_value(position) and (offset is None or _one_value(offset))
    x, y = racket.check_points(position, offset)
    speed = check_speed("speed", speed, allow_zero=True)
    scalar = scalar and _one_value(swing_speed)
    swing = _swing_speeds(swing_speed, x.size)
    swung = np.count_nonzero(swing) > 0  # (ndarray.any's reduction costs 5x more on a few)
    if speed == 0.0 and not swing.all():  # (both are 0 or at least 1 mm/s)
        raise ValueError("speed must be > 0 m/s (or the racket swung, swing_speed > 0), got 0")
    closing = speed + swing
    if pivot is not None:
        pivot = finite("pivot", pivot, "m from the tip")
        reach = racket.beam.length + PIVOT_BEYOND_BUTT
        if not x.max() < pivot <= reach:
            raise ValueError(
                f"pivot must lie beyond the impact points and at most {PIVOT_BEYOND_BUTT:g} m "
                f"beyond the butt, in ({x.max():g}, {reach:g}] m from the tip, got {shown(pivot)}"
            )
    if math.isinf(racket.contact.stiffness) and isinstance(ball.law, SineLaw):  # a bare surface
        raise ValueError(
            "the unhappy (sine-law) ball is for rackets: its Xo search takes a string bed in "
            "series; strike a bat with a monotone ball (e.g. ball.baseball)"
        )
    if steps_per_contact is None:
        sine = isinstance(ball.law, SineLaw)
        steps_per_contact = SINE_STEPS_PER_CONTACT if sine else DEFAULT_STEPS_PER_CONTACT
    else:
        steps_per_contact = int(in_range("steps_per_contact", steps_per_contact, 50, 100_000))
    watch_after = in_range("watch_after", watch_after, 0.0, 1.0, "s")
    if swung:
        racket.check_swing(pivot)
    modes = racket.beam.modes  # (the first frequency alone, not all of them)
    f1 = modes.omega[2] / (2.0 * np.pi) if modes.count > 2 else np.inf
    if f1 < F1_MIN:
        raise ValueError(
            f"the frame's first bending frequency must be >= {F1_MIN:g} Hz for an impact, "
            f"got {f1:.4g} Hz"
        )
    roll = racket.beam.roll_modes if y is not None else None
    if roll is not None and roll.count > 1 and roll.frequencies[0] < F1_MIN:
        raise ValueError(
            f"the frame's first torsion frequency must be >= {F1_MIN:g} Hz for an impact off "
            f"the axis, got {roll.frequencies[0]:.4g} Hz"
        )
    batches = _time_step_batches(racket, ball, closing)
    if histories and len(batches) > 1:
        raise ValueError(
            "histories need one time step for all impacts: give them one closing speed "
            "(ball speed + swing speed), or a ball whose contact time does not depend on it"
        )
    run = (racket, ball, speed, pivot, steps_per_contact, watch_after, histories)
    if scalar:  # one impact: one batch, one chunk (x copied: the user's 0-d array may be it)
        parts = [_solve(x.copy(), y, swing, *run)]
    else:
        if not histories:  # in chunks: the kernel's inputs take about 1.6 kB per impact
            batches = [b[i : i + CHUNK_POINTS] for b in batches
                       for i in range(0, b.size, CHUNK_POINTS)]  # fmt: skip
        with one_blas_thread() if x.size > IMPACTS_PER_THREAD else contextlib.nullcontext():
            parts = [_solve(x[b], None if y is None else y[b], swing[b], *run) for b in batches]
    fields = parts[0][0]
    if len(parts) > 1:
        back = np.argsort(np.concatenate(batches))
        fields = {
            k: None if v is None else np.concatenate([p[0][k] for p in parts])[back]
            for k, v in fields.items()
        }
    squashed = fields.pop("compression")
    self_consistent = fields["self_consistent"]
    if np.count_nonzero(self_consistent) < x.size:
        warnings.warn(
            f"{np.count_nonzero(~self_consistent)} of {x.size} unhappy-ball impacts "
            f"(first at {x[~self_consistent][0]:g} m from the tip) have no self-consistent "
            "Xo: the ball leaves before its compression reaches Xo (see Impact."
            "self_consistent)",
            stacklevel=2,
        )
    warn_if_squashed(ball, squashed)
    if isinstance(ball.law, SineLaw) and not racket.contact.plain:
        warnings.warn(
            "the unhappy (sine-law) ball takes the string bed as a linear, lossless, massless "
            "spring: the bed's stiffening, loss and mass are left out",
            stacklevel=2,
        )
    if scalar:
        fields = {
            k: (v if v is None else v[0] if v.ndim > 1 else v.item()) for k, v in fields.items()
        }
    fields["speed"], fields["t"] = speed, parts[0][1]
    return Impact.of(fields)


def _one_value(value) -> bool:
    """Whether ``value`` is one value (0-d); a float is told without asking numpy."""
    return isinstance(value, float) or np.ndim(value) == 0


def _swing_speeds(swing_speed, count: int) -> np.ndarray:
    """``swing_speed`` as one value per impact point (P,), each 0 or a speed in range."""
    if _one_value(swing_speed):  # one for all (checked once)
        return np.full(count, check_speed("swing_speed", swing_speed, allow_zero=True))
    values = finite_array("swing_speed", swing_speed, "m/s")
    if values.ndim > 1:
        raise ValueError(
            f"swing_speed must be a number or one per impact point [m/s], got an array of "
            f"shape {values.shape}"
        )
    for v in np.unique(values):
        check_speed("swing_speed", v, allow_zero=True)
    try:
        return np.broadcast_to(values, (count,)).astype(float)
    except ValueError:
        raise ValueError(
            f"swing_speed must be one value or one per impact point ({count}), got {values.size}"
        ) from None


def _time_step_batches(racket: Implement, ball: Ball, closing: np.ndarray) -> list:
    """The impacts (indices into ``closing``, the closing speeds [m/s]) that share a time
    step: one per closing speed (it sets the contact time of a non-linear ball), so that
    each impact's result depends on its own inputs only; a linear ball has one.  ValueError
    if the contact would last longer than ``CONTACT_TIME_MAX``.
    """
    # (one speed, a sweep's usual case, and a single impact's: without np.unique's sort)
    if closing.size == 1 or closing[0] == closing.min() == closing.max():
        scale = contact_time_scale(ball, racket.contact.stiffness, closing[0])
        if scale > CONTACT_TIME_MAX:
            _refuse_too_soft(racket, ball, closing[0], scale)
        return [np.arange(closing.size)]
    speeds, group = np.unique(closing, return_inverse=True)
    scales = [contact_time_scale(ball, racket.contact.stiffness, c) for c in speeds]
    longest = max(scales)
    if longest > CONTACT_TIME_MAX:
        _refuse_too_soft(racket, ball, speeds[scales.index(longest)], longest)
    _, step_group = np.unique(np.array(scales)[group], return_inverse=True)
    return [np.flatnonzero(step_group == g) for g in range(step_group.max() + 1)]


def _refuse_too_soft(racket: Implement, ball: Ball, slow, longest: float) -> NoReturn:
    """ValueError: at the closing speed ``slow`` [m/s] the contact would last ``longest``
    [s], more than ``CONTACT_TIME_MAX``.
    """
    strings = np.isfinite(racket.contact.stiffness)  # (a bat's ball meets the wood)
    raise ValueError(
        f"the ball{' and strings are' if strings else ' is'} too soft at this speed "
        f"({slow:.3g} m/s): the contact would last about {1e3 * longest:.3g} ms, "
        f"and racket-impact resolves contacts up to {1e3 * CONTACT_TIME_MAX:g} ms (ball "
        f"stiffness {ball.law.secant_stiffness(ball.mass, slow):.3g} N/m"
        + (f", strings {racket.contact.stiffness:.3g} N/m)" if strings else ")")
    )


def _solve(
    x, y, swing_speed, racket, ball, speed, pivot, steps_per_contact, watch_after, histories
):
    """:func:`impact` at the points ``x`` (offsets ``y`` or None) once its inputs are
    checked: the Impact's fields (and the ball's largest compression, ``compression``) and
    the histories' times.  Impacts whose answer a passive impact does not allow are stepped
    again, finer (:func:`racket.solver.closure.refined`); ValueError where that does not
    settle them either.
    """
    run = (racket, ball, speed, pivot, watch_after, histories)
    fields, t = _unless_broken(_solve_at, x, y, swing_speed, steps_per_contact, *run)
    bad = np.ones(x.size, dtype=bool) if fields is None else closure.unclosed(fields, ball)
    if not np.count_nonzero(bad):
        return fields, t
    if histories or fields is None:  # one time axis for all, or none: every impact again
        bad[:] = True

    def solve(steps):
        return _solve_at(x[bad], None if y is None else y[bad], swing_speed[bad], steps, *run)

    again, t_again, settled = closure.refined(solve, steps_per_contact)
    if histories or fields is None:  # every impact again, on the finer time axis
        fields, t = again, t_again
    else:
        for k, v in fields.items():
            if v is not None:
                v[bad] = again[k]
    if not settled.all():
        _refuse_unclosed(fields, np.flatnonzero(bad)[~settled][0], x, y, swing_speed,
                         steps_per_contact, *run)  # fmt: skip
    return fields, t


def _solve_at(
    x, y, swing_speed, steps_per_contact, racket, ball, speed, pivot, watch_after, histories
):
    """:func:`_solve` at one number of steps per contact, unchecked."""
    stepper = _Stepper(racket, ball, x, y, speed, swing_speed, pivot, steps_per_contact)
    x_o = stepper.points.x_o  # (NaN: none but the unhappy ball's)
    if stepper.code == layout.SINE:
        x_o = unhappy_x_o(racket, ball, x, y, speed, swing_speed, pivot, stepper)
    extra_steps = round(watch_after / stepper.dt)
    force_only = histories == "force"
    rows = 1 if force_only else layout.N_HISTORY
    record = history_bound(stepper, x.size, extra_steps, rows) if histories else 0
    outputs = stepper.run(x_o, extra_steps=extra_steps, history_steps=record,
                          force_only=force_only)  # fmt: skip
    ended = outputs.summary[:, layout.ENDED]
    if np.count_nonzero(ended) < x.size:
        raise NotEnded(
            f"the impact at {x[ended == 0][0]:g} m from the tip had not ended after "
            f"{stepper.max_steps * stepper.dt:.3g} s"
        )
    return outcome(stepper, racket, ball, x, y, speed, x_o, outputs, histories, extra_steps)


class NotEnded(RuntimeError):
    """An impact still in contact when the kernel's last step was taken."""


def _unless_broken(solve_at, *args):
    """``solve_at(*args)``, or (None, None) where the step broke down: a bed mass stepped
    beyond its stability (omega dt > 6**0.5, :data:`racket.solver.bed_mass_kernel.
    BED_MASS_BETA`: a light bed mass, few steps per contact and a stiffening ball near its
    limit) divides by zero in the kernel or never ends the contact.  The caller then steps
    every impact again, finer, as one whose budget does not close.
    """
    try:
        return solve_at(*args)
    except (ZeroDivisionError, NotEnded):
        return None, None


def _refuse_unclosed(fields, i, x, y, swing_speed, steps, racket, ball, speed, pivot, *_):
    """:class:`~racket.solver.closure.Unanswered` (a ValueError) for the impact ``i`` that
    refinement did not settle, naming up to what closing speed this racket and ball are
    answered there.
    """
    point = x[i : i + 1], None if y is None else y[i : i + 1], np.zeros(1)
    closing = speed + swing_speed[i]

    def answers(v):
        run = (racket, ball, v, pivot, 0.0, False)
        fields, _ = _unless_broken(_solve_at, *point, steps, *run)
        if fields is not None and not closure.unclosed(fields, ball)[0]:
            return True
        return bool(closure.refined(lambda n: _solve_at(*point, n, *run), steps)[2][0])

    limit = closure.answered_up_to(answers, closing)
    squash = ""
    if ball.radius is not None:
        squash = (
            f"; the ball is squashed to {fields['compression'][i] / ball.radius:.1%} of its "
            "radius, beyond what its force law describes"
        )
    raise closure.Unanswered(
        closing,
        limit,
        f"the impact at {x[i]:g} m from the tip gives e = {fields['e'][i]:.3g} and does not "
        f"settle even with {closure.REFINE**closure.REFINEMENTS} times the steps{squash}",
    )


def load_kernel() -> None:
    """Load the compiled kernels now (numba compiles them on a machine's first run, about a
    minute, and caches them on disk), by running impacts one at a time and in lockstep of the
    paper's racket and ball and of the default ones (a bed with a mass, a stiffening ball:
    functions of their own); a program that shows progress (the interactive page, the test
    suite) calls it before its first impact.
    """
    from racket.presets import default_ball, default_racket, paper_ball, paper_racket

    many = LOCKSTEP_MIN * pool_size()  # enough for the lockstep kernel on every thread
    for racket, ball in ((paper_racket(), paper_ball()), (default_racket(), default_ball())):
        start, end = racket.strings.extent
        impact(racket, ball, 0.5 * (start + end), 10.0)
        impact(racket, ball, np.linspace(start, end, many), 10.0)
