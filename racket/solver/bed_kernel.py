"""The string bed's law as the compiled time-steppers solve it: stiffening and loss.

The bed is massless and in series with the ball, so both carry the contact force F.  Loading,
it deflects by w(F), the root of

    F = k w (1 + s w**2),

k its stiffness at the impact point and s its stretch (:attr:`racket.StringBed.stretch`).
Unloading from the largest force F_max (deflection w_max), it returns (1 - loss) of the
energy W(w_max) = k w_max**2 (1/2 + s w_max**2 / 4) it stored: its deflection is the loading
curve's set back by delta (1 - F / F_max), with delta = 2 loss W(w_max) / F_max, the loop's
area being delta F_max / 2 = loss W (the ball's linear law unloads the same way, on a line).
The unloading curve keeps rising with F for a loss below a third
(:data:`racket.strings.bed.BED_LOSS_MAX`), so the force solve keeps a unique root.

The solver's linear part of the bed (F / k, in the series compliance ``a`` with the frame's
step) is unchanged; these functions give what the bed adds to it, h(F) = w(F) - F / k (+ the
set-back while unloading), and dh/dF.  A bed without stretch and loss (the paper's) adds
nothing, and the kernels then run the paper's bed exactly as before.

``bed`` is the array (s [1/m^2], loss [-]) of :class:`racket.solver.layout.BallModel`.
"""

from __future__ import annotations

import math

from numba import njit

_NEWTON_STEPS = 8  # the cubic's Newton iteration converges in at most six


@njit(cache=True)
def bed_active(bed) -> bool:
    """True when the bed stiffens or loses energy (not the paper's linear, lossless bed)."""
    return bed[0] > 0.0 or bed[1] > 0.0


@njit(cache=True)
def deflection(k, s, f):
    """The bed's loading deflection w [m] at force ``f`` [N] (k w (1 + s w**2) = f), and
    dw/df [m/N].

    In units of the linear deflection f / k, w = r f / k with eps r**3 + r - 1 = 0,
    eps = s (f / k)**2.  Up to eps = 1 Newton's method from r = 1 converges from the
    right (the cubic is convex there) in at most six steps; beyond, Cardano's root of
    r**3 + p r - p = 0 (p = 1 / eps <= 1), u - v with u**3 = p / 2 + d, v = p / (3 u),
    d = sqrt(p**2 / 4 + p**3 / 27), computed as p / (u**2 + u v + v**2) without the
    cancellation of u - v.
    """
    if f <= 0.0:
        return 0.0, 1.0 / k
    w0 = f / k
    if s == 0.0:
        return w0, 1.0 / k
    eps = s * w0 * w0
    if eps <= 1.0:
        r = 1.0
        for _ in range(_NEWTON_STEPS):
            step = (eps * r * r * r + r - 1.0) / (3.0 * eps * r * r + 1.0)
            r -= step
            if step <= 1e-16 * r:
                break
    else:
        p = 1.0 / eps
        d = math.sqrt(0.25 * p * p + p * p * p / 27.0)
        u = (0.5 * p + d) ** (1.0 / 3.0)
        v = p / (3.0 * u)
        r = p / (u * u + p / 3.0 + v * v)
    w = r * w0
    return w, 1.0 / (k * (1.0 + 3.0 * s * w * w))


@njit(cache=True)
def stored(k, s, w):
    """Energy [J] stored in the bed loaded to deflection ``w`` [m]: the area under
    F = k w (1 + s w**2).
    """
    return k * w * w * (0.5 + 0.25 * s * w * w)


@njit(cache=True)
def set_back(bed, inv_ks, f_max):
    """The unloading curve's set-back delta [m] at zero force after the largest force
    ``f_max`` [N] (0 for a lossless bed or before any force).
    """
    if bed[1] == 0.0 or f_max <= 0.0:
        return 0.0
    k = 1.0 / inv_ks
    w_max = deflection(k, bed[0], f_max)[0]
    return 2.0 * bed[1] * stored(k, bed[0], w_max) / f_max


@njit(cache=True)
def bed_extra(bed, inv_ks, f, f_max):
    """What the bed adds to its linear deflection f inv_ks [m] at force ``f`` [N] after the
    largest force ``f_max`` [N], and its derivative with f [m/N] (see the module docstring).

    Parameters
    ----------
    bed : ndarray (2,)
        Stretch s [1/m^2] and loss [-].
    inv_ks : float
        1 / the bed's stiffness at the impact point [m/N].
    f, f_max : float
        The force and the largest force so far [N].
    """
    k = 1.0 / inv_ks
    force = max(f, 0.0)
    w, dw = deflection(k, bed[0], force)
    h, dh = w - force * inv_ks, dw - inv_ks
    if force < f_max:
        delta = set_back(bed, inv_ks, f_max)
        h += delta * (1.0 - force / f_max)
        dh -= delta / f_max
    return h, dh


@njit(cache=True)
def bed_dissipated(bed, inv_ks, f_peak):
    """Energy [J] the bed has lost after a contact whose largest force was ``f_peak`` [N]:
    loss times what it stored then.
    """
    if bed[1] == 0.0 or f_peak <= 0.0:
        return 0.0
    k = 1.0 / inv_ks
    return bed[1] * stored(k, bed[0], deflection(k, bed[0], f_peak)[0])


@njit(cache=True)
def bed_losses(bed, inv_ks, f_peak, out):
    """:func:`bed_dissipated` of each impact into ``out`` [J] (P,), from the points' 1 /
    stiffness ``inv_ks`` [m/N] and largest forces ``f_peak`` [N] (P,).
    """
    for p in range(out.size):
        out[p] = bed_dissipated(bed, inv_ks[p], f_peak[p])
