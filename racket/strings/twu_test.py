"""TWU's single-string test, reconstructed (``data/measurements.md`` sec. 8): a string's
tension against its strain, and the axial stiffness EA a string bed at its own tension sees.

TWU strikes one string at mid-span and reports a secant stiffness k [lb/in]: the tension's
rise per inch of stretch over the strain step the hammer imposes (0.8, 1.45 and 2.0 % at
Slow, Medium and Fast), starting from the tension the string holds at impact, well below the
51 lb it was strung at (polyester relaxes to about 28 lb).  Over the reconstructed free
length L = 317.6 mm a secant k is a secant EA = k L, so that the three speeds give the
string's tension against strain from the tension at impact:

    T(step) = T_i + k(step) L step at each of the three steps,

straight between these points and (0, T_i), on the first chord's line below T_i and on the
last chord's beyond the Fast step (**an assumption**: three points and no more;
polyester's k falls with amplitude, nylon's and gut's hardly change, so that polyester's
curve bends and theirs hardly do).  A bed string at tension T_bed sits at eps_0 with
T(eps_0) = T_bed, and an impact stretches it by a strain step of its own
(:data:`BED_STRAIN`): the EA it sees is the secant (T(eps_0 + step) - T_bed) / step.
That is TWU's k taken at the bed's tension and the bed's strain, not at the reference
tension as if the string held it.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import pairwise

import numpy as np

from common.checks import in_range, positive
from common.units import INCH, LB

TWU_LENGTH = 0.3176
"""Free length [m] of the string in TWU's single-string test: 317.6 mm (5th-95th percentile
315.6-320.3 mm over about 4,500 tests), *derived* from the 2019 scrape of the TWU string
database by solving each test's mid-span geometry (``data/measurements.md`` sec. 8; checked
there: the scrape's peak force matches 2 T sin(theta) for it, median ratio 1.01).  Before
this reconstruction the model assumed 0.30 m."""

TWU_STEPS = (0.008, 0.0145, 0.020)
"""The strain steps [-] of TWU's Slow, Medium and Fast impacts (``data/measurements.md``
sec. 8, *derived*: the mid-span deflections 19-20, 26-27 and 32-33 mm over 317.6 mm)."""

TWU_REFERENCE = 51.0 * LB
"""The tension [N] TWU strings the sample at: 51 lb (``data/measurements.md`` sec. 5, 8)."""

BED_STRAIN = 0.0145
"""The strain step [-] of a bed's middle string in an impact, at which its EA is taken:
TWU's Medium step, 1.45 %.  **An assumption**: the default racket's middle string (strain
2 w**2 / L**2, w the bed's peak deflection, L the bed's diameter) is strained by about half a
per cent at the sweeps' 16.5 m/s and by more than TWU's Fast step at a 40 m/s serve
(``tests/test_stringing.py`` simulates both and checks that this step lies between them):
the bed takes one EA for all speeds, so it is taken in the middle of the tool's speeds, and
only the bed's tension chooses where on TWU's curve it sits."""

LB_PER_IN = LB / INCH
"""One pound-force per inch [N/m] (TWU quotes string stiffness in lb/in): 175.1 N/m."""


@dataclass(frozen=True)
class TwuTest:
    """One material's single-string test at 51 lb: its secant stiffnesses and the tension
    the string held at impact.

    Parameters
    ----------
    secants : (float, float, float)
        k at Slow, Medium and Fast [N/m] (:data:`TWU_STEPS`), medians over the material.
    impact_tension : float
        The tension at impact [N], median over the material.
    """

    secants: tuple
    impact_tension: float

    def __post_init__(self):
        if len(self.secants) != len(TWU_STEPS):
            raise ValueError(f"secants needs one k per step {TWU_STEPS}, got {self.secants}")
        for k in self.secants:
            positive("secants", k, "N/m")
        rises = [k * step for k, step in zip(self.secants, TWU_STEPS, strict=True)]
        if any(b <= a for a, b in pairwise(rises)):
            raise ValueError(
                f"secants {self.secants} N/m make the tension fall as the string stretches: "
                "k x step must grow from Slow to Fast"
            )
        in_range("impact_tension", self.impact_tension, 0.0, TWU_REFERENCE, "N")

    @property
    def points(self) -> tuple[np.ndarray, np.ndarray]:
        """TWU's points of the curve: strains (0 and :data:`TWU_STEPS`) [-] and the tensions
        there (T_i and T_i + k L step) [N], increasing (checked at construction).
        """
        steps = np.array((0.0, *TWU_STEPS))
        rises = np.array((0.0, *self.secants)) * TWU_LENGTH * steps
        return steps, self.impact_tension + rises

    def tension(self, strain):
        """The tension [N] at ``strain`` [-] counted from the tension at impact: straight
        between TWU's points (:attr:`points`), below the first on the Slow secant's line and
        beyond the last on the last chord's (the module's docstring).

        Parameters
        ----------
        strain : float or array
            Strain from the tension at impact [-]; negative below it.
        """
        return _broken_line(strain, *self.points)

    def axial_stiffness(self, tension: float, step: float = BED_STRAIN) -> float:
        """The secant EA [N] of a string at ``tension`` [N] stretched by ``step`` [-]:
        (T(eps_0 + step) - tension) / step with T(eps_0) = tension (the same broken line,
        read the other way).

        Parameters
        ----------
        tension : float
            The string's tension [N].
        step : float, optional
            The strain step [-]; default :data:`BED_STRAIN`.
        """
        tension = positive("tension", tension, "N")
        strains, tensions = self.points
        start = _broken_line(tension, tensions, strains)
        return float(self.tension(start + step) - tension) / step


def _broken_line(x, xs: np.ndarray, ys: np.ndarray):
    """The broken line through the points (``xs``, ``ys``), ``xs`` increasing, at ``x``:
    straight between them, and on the first and the last chord's lines beyond them.
    """
    x = np.asarray(x, dtype=float)
    chords = np.diff(ys) / np.diff(xs)
    inside = np.interp(x, xs, ys)
    return (
        inside + chords[0] * np.minimum(x - xs[0], 0.0) + chords[-1] * np.maximum(x - xs[-1], 0.0)
    )
