"""The bat-certification numbers, from the speeds of a ball fired at a bat at rest
(``data/bats.md`` section 4.3).

With the bat pivoted (the rig, :mod:`bat.pivot`) and rigid during the contact, angular
momentum about the pivot gives the bat-ball COR (the NCAA's BBCOR) from the ball's
collision efficiency e_A = v_out / v_in:

    BBCOR = e_A (1 + r) + r,   r = m_ball d**2 / I_pivot,

d the distance from the impact point to the pivot (derived from the COR's definition, as
WSU's Sports Science Laboratory defines BBCOR: "the ratio of the relative speed after impact
to the relative speed before impact").  The same relation with r = R_0 = m_ball / M (1 +
(b / r_g)**2) of a free bat (N2000 eq. 16) gives the collision efficiency of a free bat
(ASTM F2219-2023 derives e_a "assuming the bat is unconstrained").  BESR = e_a + 1/2 (WSU,
"Bat Performance Measures"; with the free bat's e_a, to which the old NCAA moving-bat ratio
reduces); BPF = BBCOR / the ball's COR (WSU).  The batted-ball speed of
a swing: BBS = e_a v_pitch + (1 + e_a) v_bat (Nathan, Am. J. Phys. 71, 134 (2003), as
quoted).  BBCOR must not exceed :data:`BBCOR_LIMIT`.
"""

from __future__ import annotations

import numpy as np

BBCOR_LIMIT = 0.500
"""The NCAA's limit: "The BBCOR ... at the maximum BBCOR location ... must not exceed 0.500"
(the standard, as summarised in ``data/bats.md`` section 4.1)."""


def mass_ratio(ball_mass: float, distance, inertia: float) -> np.ndarray:
    """The mass ratio r = m_ball d**2 / I [-] of a bat turning about an axis ``distance`` [m]
    from the impact point, of moment of inertia ``inertia`` [kg m^2] about it.

    Parameters
    ----------
    ball_mass : float
        The ball's mass [kg].
    distance : float or ndarray
        From the impact point to the axis [m].
    inertia : float
        The bat's moment of inertia about the axis [kg m^2].
    """
    return ball_mass * np.asarray(distance, dtype=float) ** 2 / inertia


def bbcor(e_a, r) -> np.ndarray:
    """The bat-ball COR [-]: e_a (1 + r) + r.

    Parameters
    ----------
    e_a : float or ndarray
        Collision efficiency v_out / v_in of the ball off the bat at rest [-].
    r : float or ndarray
        The mass ratio [-] (:func:`mass_ratio`).
    """
    return np.asarray(e_a, dtype=float) * (1.0 + np.asarray(r)) + r


def collision_efficiency(cor, r) -> np.ndarray:
    """The collision efficiency [-]: (cor - r) / (1 + r), :func:`bbcor` inverted.

    Parameters
    ----------
    cor : float or ndarray
        The bat-ball COR [-].
    r : float or ndarray
        The mass ratio [-] (:func:`mass_ratio`).
    """
    r = np.asarray(r, dtype=float)
    return (np.asarray(cor, dtype=float) - r) / (1.0 + r)


def besr(e_a) -> np.ndarray:
    """The ball exit speed ratio [-]: e_a + 1/2.

    Parameters
    ----------
    e_a : float or ndarray
        Collision efficiency [-].
    """
    return np.asarray(e_a, dtype=float) + 0.5


def bpf(bat_ball_cor, ball_cor: float) -> np.ndarray:
    """The bat performance factor [-]: the BBCOR over the ball's own COR.

    Parameters
    ----------
    bat_ball_cor : float or ndarray
        The BBCOR [-].
    ball_cor : float
        The ball's COR on a rigid wall [-].
    """
    if not 0.0 < ball_cor <= 1.0:  # a ball that keeps nothing has no performance to divide by
        raise ValueError(f"ball_cor must be in (0, 1], got {ball_cor!r}")
    return np.asarray(bat_ball_cor, dtype=float) / ball_cor


def batted_ball_speed(e_a, pitch_speed, bat_speed) -> np.ndarray:
    """Batted-ball speed [m/s]: e_a v_pitch + (1 + e_a) v_bat.

    Parameters
    ----------
    e_a : float or ndarray
        Collision efficiency [-].
    pitch_speed : float
        The pitch's speed towards the bat [m/s].
    bat_speed : float or ndarray
        The bat's speed at the impact point towards the ball [m/s].
    """
    e_a = np.asarray(e_a, dtype=float)
    return e_a * pitch_speed + (1.0 + e_a) * np.asarray(bat_speed, dtype=float)
