"""The paper's closed-form results, each as its own function.

These are estimates and exact special cases to compare the simulation with; no simulated
number is computed from them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from common.checks import finite_array, in_range, non_negative, positive


def energy_loss_fraction(e: float) -> float:
    """Fractional kinetic-energy loss in the centre-of-mass frame, f = 1 - e**2 (Eq. 4).

    Parameters
    ----------
    e : float
        Coefficient of restitution [-], 0 <= e <= 1.
    """
    e = in_range("e", e, 0.0, 1.0)
    return 1.0 - e**2


def series_cor(e1: float, k1: float, k2: float) -> float:
    """COR of a lossy ball (rigid-surface COR ``e1``, stiffness ``k1``) on a lossless spring
    ``k2`` (Eq. 6): 1 - e**2 = k2 / (k1 + k2) (1 - e1**2).

    Parameters
    ----------
    e1 : float
        The ball's COR on a rigid surface [-].
    k1, k2 : float
        Stiffness of the ball and of the lossless partner [N/m].
    """
    e1 = in_range("e1", e1, 0.0, 1.0)
    k1 = positive("k1", k1, "N/m")
    k2 = positive("k2", k2, "N/m")
    return float(np.sqrt(1.0 - k2 / (k1 + k2) * (1.0 - e1**2)))


def unhappy_cor(k0: float, k2: float) -> float:
    """COR of an unhappy ball (k0) on a happy ball (k2) by the analytic solution (Eq. 16):
    e = (pi k0 - k2) / (pi k0 + k2).

    Negative for k2 > pi k0, where the analytic solution no longer applies.

    Parameters
    ----------
    k0 : float
        The unhappy ball's Fo / Xo [N/m], > 0.
    k2 : float
        Stiffness of the happy ball [N/m], > 0.

    References
    ----------
    .. [1] R. Cross, Am. J. Phys. 68, 1025-1031 (2000), doi:10.1119/1.1285945.

    Examples
    --------
    >>> round(unhappy_cor(2e4, 2e4), 4)  # equal stiffness: the collision of Fig. 3
    0.5171
    """
    k0 = positive("k0", k0, "N/m")
    k2 = positive("k2", k2, "N/m")
    return (np.pi * k0 - k2) / (np.pi * k0 + k2)


@dataclass(frozen=True)
class UnhappySolution:
    """Eqs. 12-15 evaluated at times ``t`` (arrays, SI): ball positions x and y, the unhappy
    ball's compression X, the happy ball's Y, the force F, and the constants omega, Xo, Fo.

    Parameters
    ----------
    t : ndarray
        Times since first touch [s].
    x : ndarray
        Displacement of the unhappy ball's centre, x of Eq. 14 [m].
    y : ndarray
        Displacement of the happy ball's centre, y of Eq. 15 [m].
    compression_unhappy : ndarray
        Compression X of the unhappy ball (Eq. 12) [m].
    compression_happy : ndarray
        Compression Y of the happy ball [m].
    force : ndarray
        Contact force F [N].
    omega : float
        Angular frequency of Eq. 13 [rad/s].
    x_o : float
        Largest compression Xo of the unhappy ball [m].
    f_o : float
        Largest force Fo = k0 Xo [N].
    """

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    compression_unhappy: np.ndarray
    compression_happy: np.ndarray
    force: np.ndarray
    omega: float
    x_o: float
    f_o: float


def unhappy_solution(t, m1: float, m2: float, k0: float, k2: float, v1: float) -> UnhappySolution:
    """The analytic solution (Eqs. 12-15) of an unhappy ball (m1, k0) at ``v1`` on a happy
    ball (m2, k2) at rest, for 0 <= omega t <= pi.

    Eq. 13 gives omega**2 = k2 (1/m1 + 1/m2).  Xo follows from the initial condition: by
    Eq. 12 the unhappy ball compresses at the constant rate dX/dt = Xo omega / pi, and
    dX/dt + dY/dt = v1 at first touch with Y = Fo sin(omega t) / k2, so
    Xo = v1 / (omega (1/pi + k0/k2)) and Fo = k0 Xo.

    Parameters
    ----------
    t : float or array_like
        Times since first touch [s].
    m1 : float
        Mass of the unhappy ball [kg], > 0.
    m2 : float
        Mass of the happy ball [kg], > 0.
    k0, k2
        As in :func:`unhappy_cor`.
    v1 : float
        Speed of the unhappy ball at first touch [m/s], > 0.
    """
    m1, m2 = positive("m1", m1, "kg"), positive("m2", m2, "kg")
    k0, k2 = positive("k0", k0, "N/m"), positive("k2", k2, "N/m")
    v1 = positive("v1", v1, "m/s")
    t = finite_array("t", t, "s")
    omega = np.sqrt(k2 * (1.0 / m1 + 1.0 / m2))  # Eq. 13
    x_o = v1 / (omega * (1.0 / np.pi + k0 / k2))
    f_o = k0 * x_o
    wt = omega * t
    x = (v1 - f_o / (omega * m1)) * t + f_o / (omega**2 * m1) * np.sin(wt)  # Eq. 14
    y = f_o / (omega**2 * m2) * (wt - np.sin(wt))  # Eq. 15
    return UnhappySolution(
        t=t,
        x=x,
        y=y,
        compression_unhappy=x_o * wt / np.pi,  # Eq. 12
        compression_happy=f_o * np.sin(wt) / k2,
        force=f_o * np.sin(wt),
        omega=omega,
        x_o=x_o,
        f_o=f_o,
    )


def serve_speed(e: float, m1: float, m2: float, v2: float) -> float:
    """Ball speed after a racket of effective mass ``m2`` at ``v2`` hits a ball (``m1``) at
    rest (Eq. 22): V1 = (1 + e) m2 v2 / (m1 + m2).  Masses [kg], speeds [m/s].

    Parameters
    ----------
    e : float
        Coefficient of restitution [-], 0 <= e <= 1.
    m1 : float
        Ball mass [kg], > 0.
    m2 : float
        Effective mass of the racket at the impact point [kg], > 0.
    v2 : float
        Racket speed before the impact [m/s], >= 0.

    References
    ----------
    .. [1] R. Cross, Am. J. Phys. 68, 1025-1031 (2000), doi:10.1119/1.1285945.

    Examples
    --------
    >>> round(serve_speed(0.86, 0.057, 0.171, 40.0), 2)  # m2 = 3 m1: V1 = 1.39 v2
    55.8
    """
    e = in_range("e", e, 0.0, 1.0)
    m1, m2 = positive("m1", m1, "kg"), positive("m2", m2, "kg")
    v2 = non_negative("v2", v2, "m/s")
    return (1.0 + e) * m2 * v2 / (m1 + m2)


def energy_loss_fraction_lab(e: float, m1: float, m2: float, v1: float, v2: float) -> float:
    """Fraction of the lab-frame kinetic energy lost when a ball (m1, v1) and a racket
    (m2, v2) meet head-on, approaching each other (Eq. 23):
    f = (1 - e**2) m1 m2 (v1 + v2)**2 / ((m1 + m2)(m1 v1**2 + m2 v2**2)).

    With e = 0 it is the fraction turned into elastic energy at the moment of closest
    approach.  Speeds are magnitudes [m/s], at least one > 0.

    Parameters
    ----------
    e, m1, v2
        As in :func:`serve_speed`.
    m2 : float
        Effective mass of the racket [kg], > 0.
    v1 : float
        Ball speed before the impact [m/s], >= 0.

    References
    ----------
    .. [1] R. Cross, Am. J. Phys. 68, 1025-1031 (2000), doi:10.1119/1.1285945.

    Examples
    --------
    >>> round(energy_loss_fraction_lab(0.0, 0.057, 0.171, 20.0, 40.0), 3)
    0.519
    """
    e = in_range("e", e, 0.0, 1.0)
    m1, m2 = positive("m1", m1, "kg"), positive("m2", m2, "kg")
    v1, v2 = non_negative("v1", v1, "m/s"), non_negative("v2", v2, "m/s")
    if v1 == 0.0 and v2 == 0.0:
        raise ValueError("v1 and v2 cannot both be 0 m/s (there is no collision)")
    return (1 - e**2) * m1 * m2 * (v1 + v2) ** 2 / ((m1 + m2) * (m1 * v1**2 + m2 * v2**2))
