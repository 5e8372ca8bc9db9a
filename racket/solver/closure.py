"""What a passive impact allows, checked after every impact: e <= 1 and an energy budget that
closes (:func:`unclosed`), the refinement of the time step where it does not
(:func:`refined`), and the closing speed up to which a racket and ball are answered
(:func:`answered_up_to`).

A passive impact cannot give back more energy than it receives.  Where the stepped solution
says otherwise the time step is too coarse for the contact (a stiffening ball near its
limit compression is hundreds of times stiffer at its peak than at rest, and the step is
set from its secant stiffness): :func:`racket.solver.driver.impact` steps those impacts
again with :data:`REFINE` and :data:`REFINE` squared times the steps, and keeps the finer
answer where it closes its budget and agrees with the coarser one to :data:`SETTLED_E`.
Where it does not, the impact is refused, saying up to what speed it can be answered.
"""

from __future__ import annotations

from decimal import ROUND_FLOOR

import numpy as np

from common.checks import rounded
from common.units import SPEED_UNITS

BUDGET_TOL = 1e-4
"""Largest energy-budget residual [fraction of the energy the impact starts with] of an
answer.  The default step leaves at most 4e-5 at closing speeds up to 80 m/s (every ball
preset on the default and the paper rackets, ``tests/test_budget_closes.py``); at 100 m/s
and above a stiffening ball's residual grows past it and the step is refined."""

REFINE = 4
"""Factor by which the steps per contact grow at each refinement."""

REFINEMENTS = 2
"""Refinements tried (16 times the steps: the accuracy reference)."""

SETTLED_E = 3e-3
"""Largest change of e [-] between the last two refinements of an answer that is kept.  A
budget that closes does not prove the peak resolved: at 200 m/s on the default racket a
point 4 cm beyond the string centre closes its budget at 4 times the steps with e 0.013
above its limit; at 16 times the steps e is within 2e-3 of 64 times' (the change between
them, 1.8e-3, within this bound)."""

LIMIT_BISECTIONS = 7
"""Bisections of the closing speed up to which an impact is answered, on a log scale from
1 m/s: to (closing speed)**(1/128), about 4 % at 100 m/s."""


STIFF_FRACTION = 0.88
"""Compression [fraction of the limit a stiffening ball approaches] beyond which an answer
is refined whatever its budget says.  The ball is then more than 8 times stiffer at its peak
than at rest and the default step, set from its secant stiffness, misses its peak: on the
default racket e moves by 2e-3 at 100 m/s (compression 0.91 of the limit) and 1e-2 at
150 m/s against 16 times the steps, with budgets that close to 6e-5; at 80 m/s (0.85) it
moves by 6e-4, and no stroke closes faster (the serve record, 73 m/s)."""


class Unanswered(ValueError):
    """An impact the model cannot answer (:func:`refined` did not settle it), with the
    closing speed it was asked at and the one up to which it answers, both [m/s].

    Parameters
    ----------
    closing : float
        The closing speed asked (the ball's speed plus the swing's) [m/s].
    limit : float
        The closing speed up to which this racket and ball are answered [m/s].
    why : str
        What went wrong at ``closing``, in words.
    """

    def __init__(self, closing: float, limit: float, why: str):
        self.closing, self.limit, self.why = closing, limit, why
        super().__init__(self.said_in("m/s"))

    def said_in(self, unit: str) -> str:
        """The refusal, its speeds in ``unit`` (a key of :data:`common.units.SPEED_UNITS`)."""
        size = SPEED_UNITS[unit]
        return (
            f"at {self.closing / size:.4g} {unit} (the ball's speed plus the swing's) "
            f"{self.why}; racket-impact answers this racket and ball up to about "
            f"{rounded(self.limit / size, 3, ROUND_FLOOR)} {unit}"
        )


def unclosed(fields: dict, ball) -> np.ndarray:
    """Which impacts (P,) break what a passive impact allows, or may: e above 1, an energy
    budget that does not close to :data:`BUDGET_TOL` of the energy the impact starts with,
    or a stiffening ball squashed beyond :data:`STIFF_FRACTION` of its limit.

    Parameters
    ----------
    fields : dict
        The Impact's fields as :func:`racket.solver.outcome.outcome` returns them (arrays
        over the impact points), with the ball's largest compression [m].
    ball : ball.Ball
        The ball.
    """
    limit = getattr(ball.law, "x_lim", np.inf) * STIFF_FRACTION
    if fields["e"].shape == (1,):  # one impact: in numbers (nothing for NaN to warn about)
        e, residual, initial = (fields[k].item() for k in ("e", "energy_residual",
                                                           "energy_initial"))  # fmt: skip
        closes = e <= 1.0 + BUDGET_TOL and abs(residual) <= BUDGET_TOL * initial
        return np.array([not (closes and fields["compression"].item() <= limit)])
    with np.errstate(invalid="ignore"):
        return ~(_closes(fields) & (fields["compression"] <= limit))


def _closes(fields: dict) -> np.ndarray:
    """Which impacts (P,) give e <= 1 and close their budget, both to :data:`BUDGET_TOL`
    (NaN does not: called within ``np.errstate(invalid="ignore")``).
    """
    residual = np.abs(fields["energy_residual"])
    return (fields["e"] <= 1.0 + BUDGET_TOL) & (residual <= BUDGET_TOL * fields["energy_initial"])


def refined(solve, steps: int):
    """The answer at :data:`REFINE` ** :data:`REFINEMENTS` times ``steps``, its histories'
    times, and which impacts it settles: they close their budget and their e moved by at
    most :data:`SETTLED_E` from the refinement before.

    Parameters
    ----------
    solve : callable
        ``solve(steps)``: the Impact's fields and the histories' times at that many steps
        per contact.
    steps : int
        The steps per contact of the answer refined.
    """
    before = None
    for level in range(1, REFINEMENTS + 1):
        fields, t = solve(steps * REFINE**level)
        if before is not None:
            moved = np.abs(np.atleast_1d(fields["e"]) - np.atleast_1d(before))
        before = fields["e"]
    with np.errstate(invalid="ignore"):
        return fields, t, _closes(fields) & (moved <= SETTLED_E)


def answered_up_to(answers, closing: float) -> float:
    """The largest closing speed [m/s] below ``closing`` at which ``answers(speed)`` holds,
    by bisection from 1 m/s (assumed answered: the ball's law near rest), each speed tried
    cut to three significant digits: the speed found is one tried and answered, as a refusal
    quotes it (near a stiffening ball's limit, where whether an impact is answered can flip
    from one speed to the next, a speed quoted rounded up may not be).

    Parameters
    ----------
    answers : callable
        ``answers(speed)``: True where the impact at that closing speed [m/s] is answered.
    closing : float
        A closing speed [m/s] that is not answered.
    """
    low, high = 1.0, closing
    for _ in range(LIMIT_BISECTIONS):
        middle = float(rounded(np.sqrt(low * high), 3, ROUND_FLOOR))
        if middle <= low:
            break
        if answers(middle):
            low = middle
        else:
            high = middle
    return low
