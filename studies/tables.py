"""Simulation results as tidy pandas tables (SI units in the column names)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ball import CollisionHistory
from common.typechecks import choice, instance
from common.units import MPH, SPEED_SUFFIXES, SPEED_UNITS
from racket import Impact

if TYPE_CHECKING:
    import pandas as pd


def impact_table(result: Impact) -> pd.DataFrame:
    """One row per impact of an :func:`racket.impact` result, with the summary numbers.

    Parameters
    ----------
    result : Impact
        The result of :func:`racket.impact` (SI).
    """
    import pandas as pd

    instance("result", result, Impact, "a racket.Impact (the result of racket.impact)")
    return pd.DataFrame(impact_columns(result))


def frame(columns: dict) -> pd.DataFrame:
    """The table of ``columns`` (name -> 1-D array, as :func:`studies.sweeps.sweep_columns`
    gives them); an array of words (dtype object) becomes a categorical column, its
    categories in the order they first appear.

    Parameters
    ----------
    columns : dict
        Column name -> 1-D array.
    """
    import pandas as pd

    table = {}
    for name, values in columns.items():
        if values.dtype == object:
            codes, categories = pd.factorize(values)
            values = pd.Categorical.from_codes(codes, categories.tolist())
        table[name] = values
    return pd.DataFrame(table, copy=False)


def impact_columns(result: Impact) -> dict:
    """The columns of :func:`impact_table` as a dict of 1-D arrays.

    Parameters
    ----------
    result : Impact
        The result of :func:`racket.impact` (SI).
    """
    columns = {
        "position_from_tip_cm": 100 * np.asarray(result.position),
        "position_from_tip_m": result.position,
        "offset_m": 0.0 * result.position if result.offset is None else result.offset,
        "e": result.e,
        "e_A": result.e_A,
        "effective_mass_kg": result.effective_mass,
        "v_cm_m_s": result.v_cm,
        "omega_rad_s": result.omega,
        "roll_rate_rad_s": result.roll_rate,
        "swing_speed_m_s": np.broadcast_to(result.swing_speed, np.shape(result.position)),
        "ball_rebound_m_s": result.ball_rebound,
        "exit_speed_mph": np.asarray(result.ball_rebound) / MPH,
        "vibration_energy_fraction": np.divide(result.vibration_energy, result.closing_energy),
        "contact_time_s": result.contact_time,
        "peak_force_N": result.peak_force,
        "e_van_zandt": result.e_van_zandt,
        "self_consistent": result.self_consistent,
        "recontacts": result.recontacts,
    }
    return {name: np.atleast_1d(value) for name, value in columns.items()}


def feel_table(feel) -> pd.DataFrame:
    """The histories of :func:`racket.feel.hand_feel`, one row per time step: the contact
    force, the handle's velocity and acceleration at the middle of the hand, the
    acceleration's two parts (the shock's rigid-body motion and the vibration, which add up
    to it) and, off the axis, the twist rate.

    Parameters
    ----------
    feel : HandFeel
        The handle's motion after an impact.
    """
    import pandas as pd

    columns = {
        "t_s": feel.t,
        "force_N": feel.force,
        "handle_velocity_m_s": feel.velocity,
        "handle_acceleration_m_s2": feel.acceleration,
        "handle_shock_acceleration_m_s2": feel.shock_acceleration,
        "handle_vibration_acceleration_m_s2": feel.vibration_acceleration,
    }
    if feel.twist_rate is not None:
        columns["handle_twist_rate_rad_s"] = feel.twist_rate
    return pd.DataFrame(columns)


def history_table(history: CollisionHistory) -> pd.DataFrame:
    """A two-ball collision's history, one row per time sample.

    Parameters
    ----------
    history : CollisionHistory
        The ``history`` of a :func:`ball.collide` result (SI).
    """
    import pandas as pd

    instance("history", history, CollisionHistory, "a ball.CollisionHistory (collide(...).history)")
    return pd.DataFrame(
        {
            "t_s": history.t,
            "force_N": history.force,
            "compression_a_m": history.compression_a,
            "compression_b_m": history.compression_b,
            "position_a_m": history.position_a,
            "position_b_m": history.position_b,
            "velocity_a_m_s": history.velocity_a,
            "velocity_b_m_s": history.velocity_b,
        }
    )


def speeds_in(table, unit: str, columns):
    """``table`` with each speed of ``columns`` (``NAME_m_s``) also in ``unit``, beside its m/s
    column (``NAME_mph`` or ``NAME_kmh``); as it is for m/s.

    Parameters
    ----------
    table : DataFrame
        A table with the columns ``NAME_m_s`` [m/s].
    unit : str
        "m/s", "mph" or "km/h".
    columns : sequence of str
        The speeds' NAMEs.
    """
    choice("unit", unit, tuple(SPEED_UNITS))
    if unit == "m/s":
        return table
    out, suffix = table.copy(), SPEED_SUFFIXES[unit]
    for name in columns:
        at = out.columns.get_loc(f"{name}_m_s") + 1
        out.insert(at, f"{name}_{suffix}", out[f"{name}_m_s"] / SPEED_UNITS[unit])
    return out
