"""The handle's motion at the hand after an impact: histories and spectrum."""

from __future__ import annotations


def plot_hand_feel(feel, ax=None):
    """What the hand feels (:class:`racket.feel.HandFeel`): the handle's velocity and
    acceleration at the grip against time (the contact shaded), and the acceleration's
    spectrum.  ``ax``: two Axes, or None for a new figure; returns them.

    Parameters
    ----------
    feel : HandFeel
        What the hand feels (:class:`racket.feel.HandFeel`, SI).
    ax : sequence of 2 Axes, optional
        The Axes of the time and frequency panels; None: a new figure's.
    """
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(2, 1, figsize=(6.4, 6.0))
    top, bottom = ax
    t_ms = 1e3 * feel.t
    top.axvspan(0.0, 1e3 * feel.contact_time, color="0.9", label="ball on the strings")
    top.plot(t_ms, feel.velocity, color="C0", label="velocity [m/s]")
    top.set_xlabel("time since first contact [ms]")
    top.set_ylabel("handle velocity [m/s]", color="C0")
    twin = top.twinx()
    twin.plot(t_ms, feel.acceleration / 9.81, color="C3", lw=0.8, label="acceleration")
    twin.set_ylabel("handle acceleration [g]", color="C3")
    top.set_title(
        f"at the grip, {100 * feel.grip_from_butt:.1f} cm from the butt: peak "
        f"{feel.peak_velocity:.2f} m/s, {feel.peak_acceleration / 9.81:.0f} g"
    )
    top.legend(loc="upper left", bbox_to_anchor=(1.12, 1.0), fontsize="small")
    keep = feel.frequencies <= 2000.0
    bottom.plot(feel.frequencies[keep], feel.spectrum[keep] / 9.81, color="C3")
    bottom.set_xlabel("frequency [Hz]")
    bottom.set_ylabel("acceleration amplitude [g]")
    bottom.set_title(
        f"vibration reaching the hand {1e3 * feel.hand_vibration_energy:.1f} mJ "
        f"(all the hand absorbs {1e3 * feel.hand_energy:.0f} mJ)"
    )
    return ax
