"""Head-on collision of two balls, or of a ball and the wall (paper Secs. II-VI, Fig. 1).

:func:`collide` integrates the contact in the relative coordinate (Eqs. 8-11) with
:mod:`ball.monotone` or, for the unhappy ball, :mod:`ball.unhappy`, then puts the two
bodies back in the lab frame: the centre of mass moves uniformly, and each body is
displaced from it in proportion to the other's mass.  Every number in the result (speeds
after, e, contact time, peak force, energies) is read off that integration.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ball.bodies import Ball, Wall, warn_if_squashed
from ball.contact import RelativeContact
from ball.laws import SineLaw
from ball.monotone import monotone_contact
from common.checks import SPEED_RANGE, ends, in_range, shown, whole
from common.typechecks import instance


@dataclass(frozen=True)
class CollisionHistory:
    """Time histories of a collision, from first touch to separation (all arrays, SI).

    Attributes
    ----------
    t : ndarray
        Time since first touch [s].
    force : ndarray
        Contact force F [N] (Eq. 11).
    compression_a, compression_b : ndarray
        Compression of ball a (X) and of ball b (Y) [m] (zero for the wall).
    position_a, position_b : ndarray
        Displacement of each ball's centre since first touch [m] (x and y of Eqs. 8-10).
    velocity_a, velocity_b : ndarray
        Velocity of each ball [m/s].
    """

    t: np.ndarray
    force: np.ndarray
    compression_a: np.ndarray
    compression_b: np.ndarray
    position_a: np.ndarray
    position_b: np.ndarray
    velocity_a: np.ndarray
    velocity_b: np.ndarray

    @property
    def total_compression(self) -> np.ndarray:
        """X_T = X + Y [m], the total compression (Fig. 3)."""
        return self.compression_a + self.compression_b


@dataclass(frozen=True)
class Collision:
    """Outcome of :func:`collide`.

    Attributes
    ----------
    v_a, v_b : float
        Velocities before [m/s] (positive along the line from a to b).
    v_a_after, v_b_after : float
        Velocities after [m/s].
    e : float
        Coefficient of restitution [-] (Eq. 1): relative speed after / relative speed before.
    contact_time : float
        Duration of the contact [s].
    peak_force : float
        Largest contact force [N].
    energy_initial, energy_final : float
        Kinetic energy of both bodies before and after, lab frame [J] (Eqs. 2-3; the wall
        has none).
    energy_dissipated_a, energy_dissipated_b : float
        Energy lost in each ball's hysteresis [J].
    x_o : float or None
        The unhappy ball's self-consistent largest compression Xo [m] (Eq. 7), else None.
    history : CollisionHistory
        Force, compressions, positions and velocities against time.
    """

    v_a: float
    v_b: float
    v_a_after: float
    v_b_after: float
    e: float
    contact_time: float
    peak_force: float
    energy_initial: float
    energy_final: float
    energy_dissipated_a: float
    energy_dissipated_b: float
    x_o: float | None
    history: CollisionHistory

    @property
    def energy_lost(self) -> float:
        """Kinetic energy lost [J]: energy_initial - energy_final (Eqs. 4, 23)."""
        return self.energy_initial - self.energy_final

    @property
    def energy_lost_fraction(self) -> float:
        """F = energy_lost / energy_initial (Eqs. 4 and 23)."""
        return self.energy_lost / self.energy_initial


def largest_closing_speed(a: Ball, b: Ball | Wall) -> float:
    """The fastest closing speed [m/s] at which ``a`` and ``b`` can collide: their force
    laws must store the collision's energy in the centre-of-mass frame, mu v**2 / 2, short of
    their limits (``law.storable``: a stiffening ball squashed flat); inf when neither law
    has a limit.

    Parameters
    ----------
    a : Ball
        One ball.
    b : Ball or Wall
        The other, or :data:`~ball.WALL`.
    """
    wall = isinstance(b, Wall)
    mu = a.mass if wall else a.mass * b.mass / (a.mass + b.mass)
    storable = a.law.storable + (0.0 if wall else b.law.storable)
    return float(np.sqrt(2.0 * storable / mu))


def too_fast_to_store(
    name: str, typed, fastest: float, unit: str = "m/s", size: float = 1.0
) -> ValueError:
    """The refusal of a closing speed above :func:`largest_closing_speed`, naming the input
    as the user gave it: "v_a must be in [0.001, 170.7] m/s for these balls: faster, the
    collision's energy is more than the balls' force laws can store ..., got 300".

    Parameters
    ----------
    name : str
        The input, as the message quotes it (an argument's name, a flag).
    typed : float or str
        Its value as typed [``unit``]: a number, or a text such as "300 - 10" for two
        velocities.
    fastest : float
        The largest closing speed [m/s] (:func:`largest_closing_speed`).
    unit : str, optional
        The unit the speed was typed in.
    size : float, optional
        That unit's size [m/s].
    """
    low = SPEED_RANGE[0]
    said = f"in [{ends(low / size, fastest / size)}]" if fastest >= low else (
        f"at most {fastest / size:.3g}"  # below any speed accepted: no collision at all
    )  # fmt: skip
    return ValueError(
        f"{name} must be {said} {unit} for these balls: faster, the collision's energy is more "
        "than the balls' force laws can store short of their limits (a stiffening ball "
        f"squashed flat), got {typed if isinstance(typed, str) else shown(typed)}"
    )


def collide(a: Ball, b: Ball | Wall, v_a: float, v_b: float = 0.0, samples: int = 400) -> Collision:
    """Collide ball ``a`` head-on with ball ``b`` (or :data:`~ball.WALL`) in the lab frame.

    Each ball's spring is compressed in series with the other's (Eqs. 8-11); the contact is
    integrated from first touch until the force returns to zero.

    Parameters
    ----------
    a : Ball
        The ball on the left, moving at ``v_a``.
    b : Ball or Wall
        The ball on the right, or the wall.
    v_a, v_b : float
        Velocities before the collision [m/s], positive from a towards b, each within
        +-300 m/s; the balls must approach (``v_a - v_b >= 0.001`` m/s).  The wall does not
        move (``v_b = 0``).
    samples : int
        Points per phase in the returned history, in [2, 100000].

    Returns
    -------
    Collision

    References
    ----------
    .. [1] R. Cross, Am. J. Phys. 68, 1025-1031 (2000), doi:10.1119/1.1285945.

    Examples
    --------
    >>> from ball import Ball, LinearSpring, SineLaw
    >>> unhappy = Ball(0.0103, SineLaw(k0=2e4))
    >>> happy = Ball(0.0103, LinearSpring(k=2e4))
    >>> r = collide(unhappy, happy, 4.0)  # Fig. 3
    >>> round(r.e, 4), round(r.v_b_after, 4)
    (0.5171, 3.0342)
    """
    instance("a", a, Ball, "a ball.Ball")
    instance("b", b, (Ball, Wall), "a ball.Ball or ball.WALL")
    samples = whole("samples", samples, 2, 100_000)
    v_a = in_range("v_a", v_a, -SPEED_RANGE[1], SPEED_RANGE[1], "m/s")
    v_b = in_range("v_b", v_b, -SPEED_RANGE[1], SPEED_RANGE[1], "m/s")
    wall = isinstance(b, Wall)
    if wall and v_b != 0.0:
        raise ValueError(f"v_b must be 0 for the wall (it cannot move), got {v_b!r}")
    if v_a - v_b < SPEED_RANGE[0]:
        raise ValueError(
            f"the balls must approach: v_a must exceed v_b = {shown(v_b)} m/s by at least "
            f"{SPEED_RANGE[0]:g} m/s, got {shown(v_a)}"
        )

    closing = v_a - v_b
    fastest = largest_closing_speed(a, b)
    if closing > fastest:
        if v_b == 0.0:
            raise too_fast_to_store("v_a", v_a, fastest)
        raise too_fast_to_store("v_a - v_b", f"{shown(v_a)} - {shown(v_b)}", fastest)
    mu = a.mass if wall else a.mass * b.mass / (a.mass + b.mass)
    law_b = None if wall else b.law
    from ball.unhappy import unhappy_contact  # scipy loads on first use (import time)

    if isinstance(a.law, SineLaw) and isinstance(law_b, SineLaw):
        raise ValueError(
            "a and b cannot both be unhappy (SineLaw) balls: the split of the "
            "compression between two falling force laws is not determined"
        )
    if isinstance(a.law, SineLaw):
        rel = unhappy_contact(a.law, law_b, mu, closing, samples=samples)
    elif isinstance(law_b, SineLaw):
        swapped = unhappy_contact(law_b, a.law, mu, closing, samples=samples)
        rel = RelativeContact(
            swapped.t,
            swapped.force,
            swapped.compression_b,
            swapped.compression_a,
            swapped.closing_speed,
            swapped.dissipated_b,
            swapped.dissipated_a,
            swapped.x_o,
        )
    else:
        rel = monotone_contact(a.law, law_b, mu, closing, samples=samples)

    # Back to the lab frame: z = x - y, with the centre of mass moving uniformly.
    z = rel.compression_a + rel.compression_b
    if wall:
        share_a, share_b, v_cm = 1.0, 0.0, 0.0
    else:
        total = a.mass + b.mass
        share_a, share_b = b.mass / total, a.mass / total
        v_cm = (a.mass * v_a + b.mass * v_b) / total
    # The relative speed dz/dt runs from +closing down; velocities follow from it.
    vel_a = v_cm + share_a * rel.closing_speed
    vel_b = v_cm - share_b * rel.closing_speed
    history = CollisionHistory(
        t=rel.t,
        force=rel.force,
        compression_a=rel.compression_a,
        compression_b=rel.compression_b,
        position_a=v_cm * rel.t + share_a * z,
        position_b=v_cm * rel.t - share_b * z,
        velocity_a=vel_a,
        velocity_b=vel_b,
    )

    def kinetic(va, vb):
        return 0.5 * a.mass * va**2 + (0.0 if wall else 0.5 * b.mass * vb**2)

    warn_if_squashed(a, rel.compression_a)
    if not wall:
        warn_if_squashed(b, rel.compression_b)
    v_a_after, v_b_after = float(vel_a[-1]), float(vel_b[-1])
    return Collision(
        v_a=v_a,
        v_b=v_b,
        v_a_after=v_a_after,
        v_b_after=v_b_after,
        e=(v_b_after - v_a_after) / closing,
        contact_time=float(rel.t[-1]),
        peak_force=float(np.max(rel.force)),
        energy_initial=kinetic(v_a, v_b),
        energy_final=kinetic(v_a_after, v_b_after),
        energy_dissipated_a=rel.dissipated_a,
        energy_dissipated_b=rel.dissipated_b,
        x_o=rel.x_o,
        history=history,
    )
