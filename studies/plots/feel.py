"""What the hand feels after an impact: the shock and the vibration of the handle against
time, and the vibration's spectrum.
"""

from __future__ import annotations

from common.units import GRAVITY
from studies.plots.axes import _axes
from studies.plots.layout import finish, legend_outside


def plot_hand_feel(feel, ax=None, conditions: str | None = None):
    """What the hand feels (:class:`racket.feel.HandFeel`): the two parts of the handle's
    acceleration at the grip against time, the shock (the racket's rigid-body motion in the
    hand) and the vibration (the contact shaded), and the vibration's spectrum.  ``ax``: two
    Axes, or None for a new figure; returns them.

    Parameters
    ----------
    feel : HandFeel
        What the hand feels (:class:`racket.feel.HandFeel`, SI).
    ax : sequence of 2 Axes, optional
        The Axes of the time and frequency panels; None: a new figure's.
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    """
    made = ax is None
    ax = _axes(ax, 2, figsize=(6.4, 6.4), sharex=False)
    top, bottom = ax
    t_ms = 1e3 * feel.t
    top.axvspan(0.0, 1e3 * feel.contact_time, color="0.9", label="ball on the strings")
    top.plot(t_ms, feel.vibration_acceleration / GRAVITY, color="C3", lw=0.8, label="vibration")
    on = feel.t <= feel.contact_time
    shock = feel.shock_acceleration / GRAVITY
    top.plot(t_ms[on], shock[on], color="C0", label="shock: the rigid-body motion")
    top.plot(t_ms[~on], shock[~on], color="C0", lw=0.8, ls=":",
             label="the same after: racket and hand moving on")  # fmt: skip
    top.set_xlabel("time since first contact [ms]")
    top.set_ylabel("handle acceleration [g]")
    top.set_title(
        f"at the grip, {100 * feel.grip:.1f} cm from the tip: shock {feel.shock / GRAVITY:.1f} g "
        f"(ball on the strings), vibration {feel.vibration / GRAVITY:.0f} g (after)"
    )
    legend_outside(top)
    keep = feel.frequencies <= 2000.0
    bottom.plot(feel.frequencies[keep], feel.spectrum[keep] / GRAVITY, color="C3")
    bottom.set_xlabel("frequency [Hz]")
    bottom.set_ylabel("vibration amplitude [g]")
    bottom.set_title(
        f"vibration reaching the hand {1e3 * feel.hand_vibration_energy:.1f} mJ "
        f"(all the hand absorbs {1e3 * feel.hand_energy:.0f} mJ)"
    )
    return finish(ax, conditions, made)
