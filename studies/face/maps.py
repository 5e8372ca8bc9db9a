"""Maps of the whole string face: e, e_A, exit speed, vibration and twist over a grid.

:func:`face_map` runs every impact of a grid over the string bed together (one vectorized
call of :func:`racket.impact` with offsets, so the roll and torsion modes take part) and
returns a :class:`FaceMap`: the numbers on the grid, and the landmarks players ask about:
the first mode's node line, the centre of percussion for a hand at the grip, and the *sweet
area*, where e_A is within :data:`SWEET_FRACTION` of its largest value.
:func:`studies.plots.plot_face_map` draws it.
"""

from __future__ import annotations

from concurrent.futures import Executor
from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np

from ball import Ball
from common.checks import in_range, shown, whole
from common.checks import speed as check_speed
from common.units import MPH, SPEED_UNITS
from racket import TENNIS_BALL_RADIUS, Racket, Swing, impact
from studies.arguments import ball_argument, racket_argument, swing_argument
from studies.face.landmarks import hand_pivot, percussion_centre
from studies.scale import impacts_of, run_calls
from studies.sweeps import BALL_SPEED

SWEET_FRACTION = 0.05
"""The sweet area is where e_A is within this fraction of its largest value on the map."""

MAP_GRID = (15, 9)
"""Default grid (along the racket, across it): TWU measures 15 points over a face."""

FIELDS = ("e", "e_A", "exit_speed", "exit_speed_swung", "vibration_energy", "roll_rate")
"""The numbers a :class:`FaceMap` holds on its grid."""

MAX_MAP_POINTS = 100_000
"""Most grid points a map takes (e.g. 316 x 316, or 1000 x 100).  Measured on this
project's 2-core machine: 26-35 us per point for the impacts at rest (twice that with a
swing) and about 2.1 kB per point at the peak, the sweet area's spline being evaluated on a
grid :data:`_FINE` times finer each way (64 values per point); so 1e5 points take about 3 s
(6 s swung) and 0.2 GB more, while 1000 x 1000 would take half a minute to a minute and
2 GB.  TWU measures 15 points over a face; beyond 1e5 no number of a map changes."""

_FINE = 8  # the sweet area is counted on a grid this many times finer, linearly interpolated


@dataclass(frozen=True)
class FaceMap:
    """Impacts over the string face (built by :func:`face_map`).

    Attributes
    ----------
    positions : (nx,) ndarray
        Rows of the grid along the racket [m from the tip].
    offsets : (nx, ny) ndarray
        The points of each row across the racket [m from the long axis, + towards 3
        o'clock]: ``ny`` evenly spaced over the row's chord, so that the grid fills the face
        (where the ball's centre may land).
    e, e_A : (nx, ny) ndarray
        COR from the dc motion (Eq. 21) and apparent COR [-], stationary racket.
    exit_speed : (nx, ny) ndarray
        Ball speed after the impact, stationary racket [m/s].
    exit_speed_swung : (nx, ny) ndarray or None
        Ball speed after the impact when the racket is swung (``swing``) [m/s]; None
        without a swing.
    vibration_energy : (nx, ny) ndarray
        Vibration energy left in the frame (bending and torsion modes, and the hand's
        spring if held) as a fraction of the ball's incoming kinetic energy [-], racket at rest.
    roll_rate : (nx, ny) ndarray
        The racket's twist rate about its long axis after the impact [rad/s], stationary.
    e_A_centre, e_A_side : float
        e_A [-] at the string bed's centre, on the axis and at 3 o'clock ``side_offset`` off it
        (the ball's centre ``margin`` inside the frame), stationary.
    side_offset : float
        Where ``e_A_side`` is taken [m from the long axis].
    speed : float
        Ball speed [m/s].
    swing : Swing or None
        The swing of ``exit_speed_swung``.
    node : ndarray
        Nodes of the first bending mode on the strings [m from the tip].
    center_of_percussion : float
        For a pivot at the hand (:func:`studies.face.landmarks.hand_pivot`) [m from the tip]: the
        impact point on the axis after which the hand's rigid-body velocity is zero, among
        the grid's rows (:func:`studies.face.landmarks.percussion_centre`; NaN if not among them,
        as for a clamped head, which does not recoil).
    sweet_threshold : float
        e_A [-] above which a point is in the sweet area.
    sweet_area_cm2 : float
        Area of the face where e_A >= ``sweet_threshold`` [cm^2] (a bicubic spline through
        the grid, counted on a grid :data:`_FINE` times finer).
    strings : StringBed
        The racket's string bed (for the outline).
    margin : float
        How far inside the bed's edge the ball's centre stays [m].
    length : float
        The racket's length [m] (for positions from the butt).
    support : str
        The racket's support (a clamped head has no centre of percussion).
    """

    positions: np.ndarray
    offsets: np.ndarray
    e: np.ndarray
    e_A: np.ndarray
    exit_speed: np.ndarray
    exit_speed_swung: np.ndarray | None
    vibration_energy: np.ndarray
    roll_rate: np.ndarray
    e_A_centre: float
    e_A_side: float
    side_offset: float
    speed: float
    swing: Swing | None
    node: np.ndarray
    center_of_percussion: float
    sweet_threshold: float
    sweet_area_cm2: float
    strings: object
    margin: float
    length: float
    support: str

    def to_frame(self):
        """One row per grid point on the face: position, offset and each field (pandas)."""
        import pandas as pd

        x = np.broadcast_to(self.positions[:, None], self.offsets.shape).ravel()
        columns = {
            "position_from_tip_cm": 100 * x,
            "position_from_tip_m": x,
            "offset_m": self.offsets.ravel(),
        }
        units = {
            "e": "e",
            "e_A": "e_A",
            "exit_speed": "exit_speed_m_s",
            "exit_speed_swung": "exit_speed_swung_m_s",
            "vibration_energy": "vibration_energy_fraction",
            "roll_rate": "roll_rate_rad_s",
        }
        for name, column in units.items():
            values = getattr(self, name)
            if values is not None:
                columns[column] = values.ravel()
        columns["in_sweet_area"] = self.e_A.ravel() >= self.sweet_threshold
        return pd.DataFrame(columns)

    def summary(self, unit: str = "m/s") -> list[str]:
        """The map in a few lines: where e_A is largest, the sweet area, e_A at the centre
        and at 3 o'clock near the frame, the node line and the centre of percussion.

        Parameters
        ----------
        unit : str
            Speeds in "m/s", "mph" or "km/h" (as the user typed them).
        """
        size = SPEED_UNITS[unit]
        i, j = np.unravel_index(np.argmax(self.e_A), self.e_A.shape)

        def butt(x):
            return f"{100 * x:.1f} cm from the tip"

        nodes = ", ".join(butt(n) for n in self.node)
        if self.support == "clamped-head":
            percussion = "no centre of percussion: a clamped head does not recoil"
        elif np.isnan(self.center_of_percussion):
            percussion = "no centre of percussion (hand pivot) among the grid's rows"
        else:
            percussion = f"centre of percussion (hand pivot) at {butt(self.center_of_percussion)}"
        lines = [
            f"ball at {self.speed / size:.4g} {unit} on a racket at rest; grid "
            f"{self.e_A.shape[0]} x {self.e_A.shape[1]} over the face (ball centre >= "
            f"{100 * self.margin:.1f} cm inside the frame)",
            f"largest e_A on the grid {self.e_A[i, j]:.4f} at {butt(self.positions[i])}, "
            f"{abs(100 * self.offsets[i, j]):.1f} cm off the axis",
            f"e_A at the string centre, {butt(self.strings.center)}: {self.e_A_centre:.4f} on "
            f"the axis, {self.e_A_side:.4f} at 3 o'clock ({100 * self.side_offset:.1f} cm off)",
            f"sweet area (e_A within {100 * SWEET_FRACTION:g} % of its largest) "
            f"{self.sweet_area_cm2:.1f} cm^2",
            (f"node of the first mode at {nodes}" if nodes else "no node on the strings")
            + f"; {percussion}",
            f"largest twist rate {np.abs(self.roll_rate).max():.1f} rad/s; vibration energy "
            f"{100 * self.vibration_energy.min():.1f}-{100 * self.vibration_energy.max():.1f} "
            "% of the ball's",
        ]
        if self.exit_speed_swung is not None:
            i, j = np.unravel_index(np.argmax(self.exit_speed_swung), self.e_A.shape)
            lines.append(
                f"swung at {self.swing.head_speed / size:.4g} {unit} head speed about a pivot "
                f"{self.swing.pivot_words()[6:]}: exit speed "
                f"{np.min(self.exit_speed_swung) / size:.2f}-"
                f"{np.max(self.exit_speed_swung) / size:.2f} {unit}, fastest at "
                f"{butt(self.positions[i])}"
            )
        return lines


def check_map_points(nx: int, ny: int, what: str) -> None:
    """Raise ``ValueError`` if a grid of ``nx`` by ``ny`` points has more than
    :data:`MAX_MAP_POINTS`.

    Parameters
    ----------
    nx, ny : int
        Grid points along and across the racket [-].
    what : str
        What asks for the grid, as the message quotes it (e.g. "--grid 1000 1000").
    """
    if nx * ny > MAX_MAP_POINTS:
        raise ValueError(
            f"{what} asks for {nx * ny:,} points, more than a map takes, {MAX_MAP_POINTS:,} "
            "(about 3 s and 0.2 GB; e.g. 316 x 316)"
        )


def face_points(racket: Racket, grid=MAP_GRID, margin: float = 0.0):
    """The grid over the string bed shrunk by ``margin``: rows ``positions`` (nx,) [m from
    the tip], evenly spaced, and in each row ``offsets`` (nx, ny) [m] evenly spaced across
    its chord; also the half width of the shrunk bed [m].

    Parameters
    ----------
    racket : Racket
        The racket (its string bed).
    grid : (int, int)
        Points along and across [-], each a whole number in [4, 1000], at most
        :data:`MAX_MAP_POINTS` in all.
    margin : float
        How far inside the bed's edge the points stay [m].
    """
    if isinstance(grid, str) or np.ndim(grid) != 1 or np.size(grid) != 2:
        raise ValueError(
            f"grid must be two whole numbers (along, across the racket), each in [4, 1000], "
            f"got {shown(grid)}"
        )
    nx, ny = (whole(f"grid[{i}]", n, 4, 1000) for i, n in enumerate(grid))
    check_map_points(nx, ny, f"grid ({nx}, {ny})")
    strings = racket.strings
    half_length = 0.5 * (strings.extent[1] - strings.extent[0]) - margin
    half_width = 0.5 * strings.full_width - margin
    if half_length <= 0 or half_width <= 0:
        raise ValueError(
            f"margin must leave some string bed, < {min(half_length, half_width) + margin:g} "
            f"m, got {margin:g}"
        )
    s = np.linspace(-1.0, 1.0, nx)
    positions = strings.center + half_length * s
    chords = half_width * np.sqrt(np.clip(1.0 - s**2, 0.0, 1.0))
    return positions, chords[:, None] * np.linspace(-1.0, 1.0, ny), half_width


def face_map(
    racket: Racket,
    ball: Ball,
    speed: float = BALL_SPEED,
    *,
    swing: Swing | None = None,
    grid=MAP_GRID,
    margin: float | None = None,
    executor: Executor | None = None,
) -> FaceMap:
    """e, e_A, exit speed, vibration and twist over a grid of the string face.

    Parameters
    ----------
    racket : Racket
        Its beam's roll inertia must be modelled (a spec-sheet racket).
    ball : Ball
    speed : float
        Ball speed towards the strings [m/s] (default :data:`studies.sweeps.BALL_SPEED`,
        TWU's test speed).
    swing : Swing, optional
        A swing of the (free) racket about a pivot for the swung exit speed, each point at
        its own speed (the ball coming in at ``speed``); None (default) for none.
    grid : (int, int)
        Grid lines along and across the racket, each in [4, 1000], at most
        :data:`MAX_MAP_POINTS` in all; default (15, 9).
    margin : float, optional
        How far inside the string bed's edge the ball's centre stays [m]; default the
        ball's radius (the whole ball on the strings), or the tennis ball's
        (:data:`racket.TENNIS_BALL_RADIUS`) for a ball without one.
    executor : concurrent.futures.Executor, optional
        Run the impacts on it, in chunks (:func:`studies.scale.run_calls`); bit-identical
        to the run in this process (the default).

    Returns
    -------
    FaceMap

    Examples
    --------
    >>> from racket import CATALOG, paper_ball
    >>> face = face_map(CATALOG["pure-drive-2021"].racket(), paper_ball())
    >>> face.e_A.shape, round(face.sweet_area_cm2)
    ((15, 9), 44)
    """
    racket, ball, swing = racket_argument(racket), ball_argument(ball), swing_argument(swing)
    speed = check_speed("speed", speed)
    if swing is not None and racket.support != "free":
        raise ValueError(
            f"swing must be None for a {racket.support} racket (the hand or clamp is at rest; "
            "swing a free racket)"
        )
    if racket.beam.roll_inertia is None:
        raise ValueError(
            "a face map needs a racket whose roll inertia is modelled (a spec-sheet racket: "
            "from_specs or a catalogue name)"
        )
    if margin is None:
        margin = TENNIS_BALL_RADIUS if ball.radius is None else ball.radius
    margin = in_range("margin", margin, 0.0, 1.0, "m")
    positions, offsets, half_width = face_points(racket, grid, margin)
    x = np.broadcast_to(positions[:, None], offsets.shape).ravel()
    y = offsets.ravel()
    if swing is not None:
        swing.check_points(racket, x)  # before any impact
    side = 0.5 * racket.strings.full_width - margin
    # The landmarks' points: the string centre on the axis and at 3 o'clock, and each row on
    # the axis (for the centre of percussion); those not on the grid join its impact call.
    nx, ny = offsets.shape
    extra_x, extra_y = [], []

    def point(on_grid, index, px, py):
        if on_grid:
            return index
        extra_x.append(px)
        extra_y.append(py)
        return x.size + len(extra_x) - 1

    middle = nx // 2 * ny  # the first point of the middle row (odd nx: at the centre)
    centre = point(nx % 2 and ny % 2, middle + ny // 2, racket.strings.center, 0.0)
    side_at = point(nx % 2, middle + ny - 1, racket.strings.center, side)
    axis = [point(ny % 2, i * ny + ny // 2, p, 0.0) for i, p in enumerate(positions)]
    calls = [impacts_of(racket, ball, np.r_[x, extra_x], speed, np.r_[y, extra_y])]
    if swing is not None:
        calls.append(impacts_of(racket, ball, x, speed, y, swing))
    hits, *swung = (SimpleNamespace(**part) for part in
                    run_calls(calls, _face_fields, executor, progress=False))  # fmt: skip
    swung = swung[0] if swung else None

    def on_grid(values, result=hits):  # the grid's points lead each call's impacts
        return np.reshape(np.broadcast_to(values, result.e.shape)[: x.size], offsets.shape)

    e_a = on_grid(hits.e_A)
    threshold, area = _sweet_area(positions, half_width, e_a)
    node = racket.beam.modes.nodes(1) if racket.system.count else np.array([])
    start, end = racket.strings.extent
    cop = percussion_centre(
        racket, positions, hits.v_cm[axis], hits.omega[axis], hand_pivot(racket)
    )
    return FaceMap(
        positions=positions,
        offsets=offsets,
        e=on_grid(hits.e),
        e_A=e_a,
        exit_speed=on_grid(hits.ball_rebound),
        exit_speed_swung=None if swung is None else on_grid(swung.ball_rebound, swung),
        vibration_energy=on_grid(hits.vibration_energy / hits.energy_initial),
        roll_rate=on_grid(hits.roll_rate),
        e_A_centre=float(hits.e_A[centre]),
        e_A_side=float(hits.e_A[side_at]),
        side_offset=side,
        speed=speed,
        swing=swing,
        node=node[(node >= start) & (node <= end)],
        center_of_percussion=cop,
        sweet_threshold=threshold,
        sweet_area_cm2=area,
        strings=racket.strings,
        margin=margin,
        length=racket.beam.length,
        support=racket.support,
    )


def _face_fields(result) -> dict:
    """The numbers of an impact that a :class:`FaceMap` reads (for
    :func:`studies.scale.run_calls`).
    """
    names = ("e", "e_A", "ball_rebound", "vibration_energy", "energy_initial", "roll_rate",
             "v_cm", "omega")  # fmt: skip
    return {name: np.atleast_1d(getattr(result, name)) for name in names}


def _sweet_area(positions, half_width, values) -> tuple[float, float]:
    """The sweet area's threshold and the area [cm^2] of the face at or above it.

    The threshold is (1 - :data:`SWEET_FRACTION`) times the largest value, from ``values``
    on the :func:`face_points` grid.  The grid is regular in (x, s = y / half chord): a
    bicubic spline through it is evaluated on a grid :data:`_FINE` times finer, and each
    fine point counts dx ds times its half chord (of an ellipse ``half_width`` [m] wide),
    with trapezoidal weights.  (Bilinear interpolation of the peaked e_A is 12 % low on a
    15 x 9 grid; the spline is within 0.5 % of a 113 x 65 grid.)

    Parameters
    ----------
    positions : ndarray
        The grid's rows [m from the tip].
    half_width : float
        Half width of the (shrunk) bed [m].
    values : ndarray
        e_A on the grid (nx, ny).
    """
    from scipy.interpolate import RectBivariateSpline

    s = np.linspace(-1.0, 1.0, values.shape[1])
    spline = RectBivariateSpline(positions, s, values, kx=3, ky=3)
    fx = np.linspace(positions[0], positions[-1], _FINE * (positions.size - 1) + 1)
    fs = np.linspace(-1.0, 1.0, _FINE * (s.size - 1) + 1)
    fine = spline(fx, fs)
    threshold = (1.0 - SWEET_FRACTION) * fine.max()
    centre, half_length = 0.5 * (positions[0] + positions[-1]), 0.5 * np.ptp(positions)
    half_chord = half_width * np.sqrt(np.clip(1.0 - ((fx - centre) / half_length) ** 2, 0, 1))
    wx, ws = (np.full(f.size, f[1] - f[0]) for f in (fx, fs))
    wx[[0, -1]] *= 0.5
    ws[[0, -1]] *= 0.5
    weight = (wx * half_chord)[:, None] * ws[None, :]
    return float(threshold), float(1e4 * np.sum(weight * (fine >= threshold)))


def compare_summary(rackets, table, ball: Ball, speed: float):
    """One row per racket of a :func:`studies.sweeps.compare` table: the largest e and
    where, e at the string centre and at the tip end of the strings, the largest exit speed
    [mph] and where (of a swing, if the table has one, with its head speed; without one the
    columns say ``largest_rebound_at_rest``: the ball's rebound off the racket at rest),
    the first mode's node and the centre
    of percussion for the hand (:func:`studies.face.landmarks.percussion_centre`, from the
    table's impacts, or for a swung table from impacts at the same points of the racket at
    rest hit at ``speed`` or :data:`BALL_SPEED`), and, for rackets whose
    roll inertia is modelled, the off-axis power (e_A at the centre's distance from the
    tip, at 3 o'clock with the ball's edge on the frame) and the sweet area of the
    :func:`face_map` of the racket at rest hit at ``speed`` (or :data:`BALL_SPEED` when
    ``speed`` is 0, a serve); for the others e_A at the string centre (one impact) and NaN,
    each NaN said in ``summary.attrs["notes"]`` (``compare`` prints them under its table).

    Parameters
    ----------
    rackets : mapping label -> Racket
    table : DataFrame
        Their :func:`studies.sweeps.compare` table.
    ball : Ball
    speed : float
        Ball speed towards the strings [m/s].
    """
    import pandas as pd

    rows, notes = [], []
    swung = bool(np.any(table["swing_speed_m_s"].to_numpy() != 0.0))
    for label, group in table.groupby("racket", sort=False):
        racket = rackets[label]
        best = group.loc[group["e"].idxmax()]
        fastest = group["position_from_tip_m"].iloc[group["exit_speed_mph"].argmax()]
        node = racket.beam.modes.nodes(1)[0]  # the one nearer the tip, on the strings
        x = group["position_from_tip_m"].to_numpy()
        if np.any(group["swing_speed_m_s"].to_numpy() != 0.0):  # the racket at rest instead
            hit = impact(racket, ball, x, speed or BALL_SPEED)
            v_cm, omega = hit.v_cm, hit.omega
        else:
            v_cm, omega = group["v_cm_m_s"].to_numpy(), group["omega_rad_s"].to_numpy()
        cop = percussion_centre(racket, x, v_cm, omega, hand_pivot(racket))
        row = {
            "racket": label,
            "largest_e": best["e"],
            "largest_e_from_tip_cm": 100 * best["position_from_tip_m"],
            "e_at_string_centre": float(
                np.interp(racket.strings.center, group["position_from_tip_m"], group["e"])
            ),
            "e_at_tip_end": group["e"].iloc[0],
            "head_speed_mph": (
                group["head_speed_m_s"].iloc[0] / MPH if "head_speed_m_s" in group else np.nan
            ),
            "largest_exit_mph": group["exit_speed_mph"].max(),
            "largest_exit_from_tip_cm": 100 * fastest,
            "node_from_tip_cm": 100 * node,
            "centre_of_percussion_from_tip_cm": 100 * cop,
            "e_A_centre": np.nan,
            "e_A_3_oclock": np.nan,
            "sweet_area_cm2": np.nan,
        }
        if racket.beam.roll_inertia is not None:  # the racket at rest (TWU's speed for a serve)
            face = face_map(racket, ball, speed or BALL_SPEED)
            row["e_A_centre"], row["e_A_3_oclock"] = face.e_A_centre, face.e_A_side
            row["sweet_area_cm2"] = face.sweet_area_cm2
        else:  # on the axis all the same; off it the frame has no width to roll
            row["e_A_centre"] = impact(racket, ball, racket.strings.center, speed or BALL_SPEED).e_A
            notes.append(f"{label}: e_A at 3 o'clock and sweet area '-': no roll inertia modelled")
        if np.isnan(cop):  # clamped: the racket does not move; else none on the strings
            notes.append(f"{label}: centre of percussion '-' ({racket.support}): none")
        if not swung:  # no swing, no exit speed: the ball's rebound off the racket at rest
            del row["head_speed_mph"]
            row = {k.replace("largest_exit", "largest_rebound_at_rest"): v for k, v in row.items()}
        rows.append(row)
    summary = pd.DataFrame(rows)
    summary.attrs["notes"] = notes
    return summary
