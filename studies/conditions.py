"""The conditions an output was computed for, said in one line: racket (support, grip,
strings), ball, speeds.  Every printed table's header line, every plot's caption, every
sidecar and every card of the page says them (:func:`conditions_line`,
:func:`racket_details`).
"""

from __future__ import annotations

import numpy as np

from common.checks import finite_array, shown
from common.typechecks import choice, instance
from common.units import SPEED_UNITS


def speed_text(value, unit: str = "m/s") -> str:
    """Speeds said in the unit the user typed, to 4 significant digits at most (no trailing
    zeros): "16.5 m/s", "89.48 mph", "10, 20 m/s".

    Parameters
    ----------
    value : float or sequence of float
        One speed or several [m/s].
    unit : str
        "m/s", "mph" or "km/h".
    """
    values = [value] if np.ndim(value) == 0 else list(value)
    said = ", ".join(shown(float(f"{v / SPEED_UNITS[unit]:.4g}")) for v in values)
    return f"{said} {unit}"


PLAIN_BED = "the paper's linear spring"
"""How outputs name a bed with no stringing: the paper's linear, lossless, massless spring
(:data:`racket.specs.strung.LINEAR`)."""


def racket_details(racket, tension: str | None = None) -> dict:
    """How a racket is held and strung, for :func:`conditions_line`: its ``support``, the
    ``grip`` of a hand-held racket (a preset's name of :data:`racket.GRIPS`, or "own grip")
    and its ``strings``: what it is strung with and its bed's stiffness ("polyester 1.25 mm
    16x19 at 55 lb, fresh, 30 kN/m"; "the paper's linear spring at 55 lb" or "the paper's
    linear spring, 30 kN/m" for the paper's plain bed, by name).

    Parameters
    ----------
    racket : Racket
        The racket.
    tension : str, optional
        The tension as typed, with its unit ("55 lb", "25 kg", "50, 55 lb"): said instead of
        the stringing's.
    """
    from racket import GRIPS

    grip = None
    if racket.support == "hand-held":
        names = [name for name, hand in GRIPS.items() if hand == racket.hand]
        grip = f"{names[0]} grip" if names else "own grip"
    stiffness = f"{racket.strings.stiffness / 1e3:.3g} kN/m"
    strung = racket.strings.stringing
    if strung is None:
        strings = PLAIN_BED + (f" at {tension}" if tension else f", {stiffness}")
    elif tension:
        strings = f"{strung.describe(tension)}, {stiffness}"
    else:
        strings = f"{strung.describe()}, {stiffness}"
    return {"support": racket.support, "grip": grip, "strings": strings}


def conditions_line(
    racket_name: str | None,
    ball_name: str | None,
    speed=None,
    unit: str = "m/s",
    swing: str | None = None,
    support: str | None = None,
    grip: str | None = None,
    strings: str | None = None,
) -> str:
    """One line naming what an output was computed for.

    Parameters
    ----------
    racket_name, ball_name : str or None
        The racket and the ball as the user named them (a preset or a file); None: not part
        of this output.
    speed : float or sequence of float, optional
        The ball's speed(s) towards the strings [m/s], said in ``unit``.
    unit : str
        The unit the user typed speeds in: "m/s", "mph" or "km/h".
    swing : str, optional
        How the racket moves, in words ("swung at 30 m/s head speed about the wrist");
        default the racket at rest (said only with a speed).
    support, grip, strings : str, optional
        :func:`racket_details`.

    Examples
    --------
    >>> conditions_line("pure-drive-2021", "itf-type-2", 16.5, support="free")
    'racket pure-drive-2021 (free), ball itf-type-2 at 16.5 m/s, the racket at rest'
    """
    for name, value in (("racket_name", racket_name), ("ball_name", ball_name), ("swing", swing),
                        ("support", support), ("grip", grip), ("strings", strings)):  # fmt: skip
        instance(name, value, str | type(None), "a str or None")
    choice("unit", unit, tuple(SPEED_UNITS))
    if speed is not None and finite_array("speed", speed, "m/s").size == 0:
        raise ValueError("speed must be one speed or more [m/s], or None; got none")
    parts = []
    if racket_name is not None:
        details = [d for d in (support, grip, strings) if d]
        parts.append(f"racket {racket_name}" + (f" ({', '.join(details)})" if details else ""))
    if ball_name is not None:
        at = "" if speed is None else f" at {speed_text(speed, unit)}"
        parts.append(f"ball {ball_name}{at}")
    if swing:
        parts.append(swing)
    elif speed is not None and racket_name is not None:
        parts.append("the racket at rest")
    return ", ".join(parts)
