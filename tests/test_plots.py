"""Each plot draws what it should (Agg backend)."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest

from ball import Ball, LinearSpring, SineLaw, collide
from racket import impact, paper_ball, paper_racket
from studies import plots
from studies.serve import serve_what_if
from studies.sweeps import sweep


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def labels(ax):
    return [line.get_label() for line in ax.get_lines()]


def test_cor_along_racket_marks_node_cop_and_maxima():
    racket = paper_racket()
    table = sweep(racket, paper_ball(), np.linspace(0, 0.32, 33), 10.0, progress=False)
    _fig, ax = plt.subplots()
    assert plots.plot_cor_along_racket(table, racket, ax=ax) is ax
    names = labels(ax)
    assert any(n.startswith("e (Eq. 21") for n in names)
    assert any(n.startswith("e_A") for n in names)
    node = next(n for n in names if n.startswith("mode-1 node"))
    assert "15.2 cm" in node
    assert any(n.startswith("centre of percussion") for n in names)
    biggest = next(line for line in ax.get_lines() if line.get_label().startswith("largest e "))
    assert biggest.get_ydata()[0] == pytest.approx(table["e"].max())
    assert ax.get_xlim()[1] >= 100 * racket.beam.length  # to scale, tip to butt in cm


def test_the_racket_is_drawn_in_its_own_strip_above_the_data_sharing_x():
    racket = paper_racket()
    table = sweep(racket, paper_ball(), np.linspace(0, 0.32, 9), 10.0, progress=False)
    ax = plots.plot_cor_along_racket(table, racket)
    assert not ax.patches  # nothing of the racket among the curves
    (strip,) = ax.child_axes
    assert len(strip.patches) >= 3  # frame, head, strings, grip
    assert strip.get_shared_x_axes().joined(ax, strip)
    assert strip.get_xlim() == ax.get_xlim()
    ax.figure.canvas.draw()
    assert strip.get_window_extent().y0 >= ax.get_window_extent().y1  # above, not on, the data


def test_impact_history_splits_dc_and_ac():
    r = impact(paper_racket(), paper_ball(), 0.03, 10.0, histories=True)
    axes = plots.plot_impact(r)
    assert len(axes) == 3
    names = labels(axes[2])
    assert "impact point, dc (rigid body)" in names and "impact point, ac (vibration)" in names
    total, dc, ac = (axes[2].get_lines()[i].get_ydata() for i in (1, 2, 3))
    # the curves are the impact's histories; the dc one ends at the rigid-body velocity that
    # momentum conservation gives the point (impulse / effective mass, Eq. 20)
    assert np.allclose(total, r.point_velocity, equal_nan=True)
    impulse = paper_ball().mass * (10.0 + r.ball_rebound)
    assert dc[np.isfinite(dc)][-1] == pytest.approx(impulse / r.effective_mass, rel=1e-9)
    assert np.nanmax(np.abs(ac)) > 0.1  # an impact 3 cm from the tip rings the frame
    assert axes[0].get_ylabel() == "force [N]"


def test_modes_plot_lists_frequencies_and_nodes():
    ax = plots.plot_modes(paper_racket(), count=3)
    names = labels(ax)
    assert names[0] == "mode 1: 120 Hz" and names[2] == "mode 2: 331 Hz"
    node_marks = ax.get_lines()[1].get_xdata()
    assert node_marks == pytest.approx(100 * paper_racket().beam.modes.nodes(1))


def test_collision_plot_is_fig3():
    r = collide(Ball(0.0103, SineLaw(2e4)), Ball(0.0103, LinearSpring(2e4)), 4.0)
    axes = plots.plot_collision(r, title="Fig. 3")
    assert axes[0].get_title() == "Fig. 3"
    assert labels(axes[1]) == ["X (ball a)", "Y (ball b)", "X_T = X + Y"]
    assert axes[2].get_lines()[1].get_ydata()[-1] == pytest.approx(3.034, abs=0.002)


def test_cor_vs_stiffness_compares_eq16_with_integration():
    ax = plots.plot_cor_vs_stiffness(ratios=[0.1, 1.0, 5.0])
    eq16, sim = ax.get_lines()[:2]
    assert sim.get_ydata() == pytest.approx([0.9387, 0.5171, 0.0], abs=1e-3)
    assert ax.get_xscale() == "log" and len(eq16.get_xdata()) > 100


def test_serve_what_if_plot():
    table = serve_what_if(
        paper_racket(), paper_ball(), string_stiffness=[2e4, 6e4], ball_stiffness=[3e4, 6e4]
    )
    ax = plots.plot_serve_what_if(table)
    assert labels(ax) == ["string-bed stiffness", "ball stiffness"]


def test_multi_panel_plots_check_their_axes():
    with pytest.raises(ValueError, match="3 Axes"):
        plots.plot_impact(
            impact(paper_racket(), paper_ball(), 0.1, 10.0, histories=True), ax=plt.subplots()[1]
        )


def test_cor_comparison_draws_each_racket_on_one_axes():
    from racket import CATALOG
    from studies.sweeps import compare

    rackets = {"paper": paper_racket(), "pd": CATALOG["pure-drive-2021"].racket()}
    table = compare(rackets, paper_ball(), 10.0, points=9)
    groups = dict(tuple(table.groupby("racket", sort=False)))
    ax = plots.plot_cor_comparison(groups)
    names = [n for n in labels(ax) if not n.startswith("_")]
    # (and the re-contacts' legend when the strings caught a ball again, on the real bed)
    names = [n for n in names if not n.startswith("re-contact")]
    assert [n.split(":")[0] for n in names] == ["paper", "pd"]
    best = table[table.racket == "pd"]["e"].max()
    assert f"largest {best:.3f}" in names[1]
    recontacts = int(table["recontacts"].gt(0).any()) if "recontacts" in table else 0
    assert len(ax.get_lines()) == 4 + recontacts  # e and e_A for each (and the marks)
    _fig, given = plt.subplots()
    assert plots.plot_cor_comparison(groups, ax=given, show_apparent=False) is given
    assert len(given.get_lines()) == 2 + recontacts


def test_a_grid_table_draws_one_labelled_curve_per_grid_point():
    racket = paper_racket()
    x = np.linspace(0, 0.32, 9)
    table = sweep(racket, paper_ball(), x, [10.0, 20.0], f1=[120.0, 180.0], progress=False)
    ax = plots.plot_cor_along_racket(table, racket)
    e_lines = [line for line in ax.get_lines() if line.get_label().startswith("e (")]
    assert len(e_lines) == 4  # 2 speeds x 2 frequencies, no zig-zag through all rows
    assert {line.get_label() for line in e_lines} == {
        f"e (ball at {v:g} m/s, f1 {f:g} Hz)" for v in (10, 20) for f in (120, 180)
    }
    for line in e_lines:
        assert np.all(np.diff(line.get_xdata()) > 0)
    with pytest.raises(ValueError, match="must hold one curve"):
        plots.plot_cor_comparison({"grid": table})


def test_unhappy_points_without_self_consistent_xo_are_marked():
    racket = paper_racket()
    with pytest.warns(UserWarning, match="no self-consistent"):
        r = impact(racket, Ball(0.057, SineLaw(4e4)), np.linspace(0, 0.32, 17), 10.0)
    ax = plots.plot_cor_along_racket(r, racket)
    marks = next(line for line in ax.get_lines() if line.get_label() == "no self-consistent Xo")
    assert np.allclose(marks.get_xdata(), 100 * r.position[~r.self_consistent])


def test_sweep_command_plots_the_whole_grid(tmp_path):
    from studies.cli import main

    out = tmp_path / "grid.png"
    assert main(["sweep", "--points", "5", "--speed", "10", "20", "--plot", str(out)]) == 0
    assert out.stat().st_size > 0


# ----- plots that fit, name their conditions and speak the user's units ---------------------
CONDITIONS = (
    "racket pure-drive-2021 (hand-held, firm grip, strings at 55 lb), ball itf-type-2 at "
    "16.5, 25, 33.3 m/s, swung at 30 m/s head speed about a pivot 5 cm beyond the butt"
)


@pytest.fixture(scope="module")
def results():
    """What each plot draws, small."""
    from dataclasses import replace

    from racket import CATALOG, Swing, default_ball
    from racket.feel import hand_feel
    from studies.bounce import rigid_bounce_table
    from studies.drop import drop
    from studies.face.maps import face_map
    from studies.sweeps import compare

    racket, ball = paper_racket(), paper_ball()
    pure_drive = CATALOG["pure-drive-2021"].racket()
    free = replace(pure_drive, support="free")
    rackets = {"paper": racket, "pure-drive-2021": pure_drive}
    table = compare(rackets, ball, 10.0, points=9)
    return {
        "racket": racket,
        "sweep": sweep(
            racket, ball, np.linspace(0, 0.32, 9), [10.0, 20.0], f1=[120.0, 180.0], progress=False
        ),
        "compare": dict(tuple(table.groupby("racket", sort=False))),
        "impact": impact(racket, ball, 0.03, 10.0, histories=True),
        "collision": collide(Ball(0.0103, SineLaw(2e4)), Ball(0.0103, LinearSpring(2e4)), 4.0),
        "drop": drop(default_ball(), 2.54),
        "bounce": rigid_bounce_table(default_ball(), [10.0, 30.0]),
        "face": face_map(free, default_ball(), 16.5, grid=(7, 5), swing=Swing(30.0)),
        "feel": hand_feel(free, default_ball(), free.strings.center, 16.5),
        "what_if": serve_what_if(
            racket, ball, string_stiffness=[2e4, 6e4], ball_stiffness=[3e4, 6e4]
        ),
    }


def _validation_table():
    import pandas as pd

    names = ["rebound-itf-type-2", "hamori-drive-polyester-67-forehand", "twu-pivot-periphery"]
    return pd.DataFrame(
        {"low": [0.7, 3.5, 0.1], "high": [0.8, 4.1, 0.2], "measured": [0.75, 3.8, 0.15],
         "model": [0.74, 4.5, 0.16], "agrees": [True, False, True],
         "kind": ["calibration", "validation", "validation"]},
        index=names,
    )  # fmt: skip


PLOTS = {
    "sweep": lambda r, **k: plots.plot_cor_along_racket(r["sweep"], r["racket"], **k),
    "compare": lambda r, **k: plots.plot_cor_comparison(r["compare"], **k),
    "impact": lambda r, **k: plots.plot_impact(r["impact"], **k),
    "modes": lambda r, **k: plots.plot_modes(r["racket"], **k),
    "collide": lambda r, **k: plots.plot_collision(r["collision"], **k),
    "drop": lambda r, **k: plots.plot_drop(r["drop"], **k),
    "happy": lambda r, **k: plots.plot_cor_vs_stiffness(ratios=[0.1, 1.0], **k),
    "ball": lambda r, **k: plots.plot_rigid_bounce(r["bounce"], radius=0.0335, **k),
    "map": lambda r, **k: plots.plot_face_map(r["face"], "exit_speed_swung", **k),
    "feel": lambda r, **k: plots.plot_hand_feel(r["feel"], **k),
    "what-if": lambda r, **k: plots.plot_serve_what_if(r["what_if"], **k),
    "validate": lambda r, **k: plots.plot_validation(_validation_table(), **k),
}


def _heading(fig):
    """The figure's heading (the conditions), the Text artist whose words they are."""
    from matplotlib.text import Text

    said = [t for t in fig.findobj(Text) if " ".join(t.get_text().split()) == CONDITIONS]
    assert len(said) == 1
    return said[0]


@pytest.mark.parametrize("name", PLOTS)
def test_every_plot_names_its_conditions_and_everything_fits_in_the_figure(name, results):
    from studies.cli.files import DPI, _laid_out

    axes = PLOTS[name](results, conditions=CONDITIONS)
    with _laid_out(axes, ".png") as fig:  # as the command line saves a PNG, at its DPI
        fig.set_dpi(DPI)
        fig.canvas.draw()
        page = fig.bbox
        heading = _heading(fig).get_window_extent()
        wrapped = _heading(fig).get_text()
        assert "\n" in wrapped  # wrapped to the figure's width, at spaces: names kept whole
        assert "pure-drive-2021" in wrapped and "itf-type-2" in wrapped
        for ax in fig.axes:  # ticks, labels, title, legend, the racket's strip: all inside
            box = ax.get_tightbbox()
            assert page.x0 - 1 <= box.x0 and box.x1 <= page.x1 + 1, (name, ax, box, page)
            assert page.y0 - 1 <= box.y0 and box.y1 <= page.y1 + 1, (name, ax, box, page)
            assert heading.y0 >= box.y1 - 1, (name, ax)  # the heading above everything
            legend = ax.get_legend()
            if legend is not None:  # off the data
                assert not legend.get_window_extent().overlaps(ax.get_window_extent())
        assert page.x0 <= heading.x0 and heading.x1 <= page.x1
        assert heading.y1 <= page.y1
    plain = PLOTS[name](results)  # no conditions, no heading
    assert np.atleast_1d(plain)[0].figure.get_suptitle() == ""


def test_a_long_title_is_wrapped_to_fit(results):
    feel = results["feel"]
    _fig, given = plt.subplots(2, 1, figsize=(3.0, 5.0), layout="constrained")
    axes = plots.plot_hand_feel(feel, ax=given)
    axes[0].figure.canvas.draw()
    for ax in axes:
        assert ax.title.get_window_extent().width <= ax.figure.bbox.width
    assert "\n" in axes[1].get_title()


def test_compare_keeps_most_of_the_width_for_its_axes(results):
    from studies.cli.files import DPI, _laid_out

    long = {f"{name} strung at 62 lb with lead tape at 12 o'clock": group
            for name, group in results["compare"].items()}  # fmt: skip
    ax = plots.plot_cor_comparison(long)
    with _laid_out(ax, ".png") as fig:  # as the command line saves a PNG, at its DPI
        fig.set_dpi(DPI)
        fig.canvas.draw()
        area, legend = ax.get_window_extent(), ax.get_legend().get_window_extent()
        assert area.width >= 0.55 * fig.bbox.width  # tight_layout left it a third
        assert area.width >= 0.95 * 5.0 * fig.dpi  # layout.AXES_WIDTH
        assert legend.x0 >= area.x1 and legend.x1 <= fig.bbox.x1  # beside it, in the figure


def test_curves_and_landmarks_have_distinct_colours(results):
    from matplotlib.colors import to_rgba

    ax = plots.plot_cor_along_racket(results["sweep"], results["racket"])  # 4 curves
    curves = [to_rgba(line.get_color()) for line in ax.get_lines()
              if line.get_label().startswith("e (")]  # fmt: skip
    node = next(line for line in ax.get_lines() if line.get_label().startswith("mode-1 node"))
    cop = next(line for line in ax.get_lines() if line.get_label().startswith("centre of"))
    marks = [to_rgba(node.get_color()), to_rgba(cop.get_color())]
    assert len(curves) == 4 and len(set(curves + marks)) == 6
    many = plots.plot_modes(paper_racket(), count=12)
    shapes = [to_rgba(line.get_color()) for line in many.get_lines() if "Hz" in line.get_label()]
    assert len(set(shapes)) == len(shapes) > 9


def test_every_position_reads_from_the_tip_in_cm(results):
    ax = PLOTS["sweep"](results)
    assert ax.get_xlabel().endswith("from the tip [cm]")
    for name in ("compare", "modes"):
        assert PLOTS[name](results).get_xlabel().endswith("from the tip [cm]")
    face = PLOTS["map"](results)
    assert face.get_ylabel() == "from the tip [cm]" and face.yaxis_inverted()  # tip up
    for drawn in (ax, PLOTS["compare"](results), face):
        for text in drawn.get_legend().get_texts():
            if " cm" in text.get_text():
                assert "from the tip" in " ".join(text.get_text().split()), text.get_text()
    feel = PLOTS["feel"](results)[0]
    assert f"{100 * results['feel'].grip:.1f} cm from the tip" in feel.get_title()


@pytest.mark.parametrize("unit", ["mph", "km/h", "m/s"])
def test_a_face_maps_speeds_are_in_the_unit_typed(unit, results):
    from common.units import SPEED_UNITS

    face = results["face"]
    ax = plots.plot_face_map(face, "exit_speed_swung", unit=unit)
    colour_bar = ax.figure.axes[-1]
    assert colour_bar.get_ylabel() == f"exit speed, swung racket [{unit}]"
    top = colour_bar.get_ylim()[1]
    assert top == pytest.approx(face.exit_speed_swung.max() / SPEED_UNITS[unit], rel=0.1)
    assert f"ball at {16.5 / SPEED_UNITS[unit]:.4g} {unit}" in ax.get_title()
    with pytest.raises(ValueError, match="unit must be one of m/s, mph, km/h, got 'kph'"):
        plots.plot_face_map(face, "exit_speed", unit="kph")


def test_a_face_map_draws_the_peak_region_of_the_field_it_shows(results):
    face = results["face"]
    swung = plots.plot_face_map(face, "exit_speed_swung")
    names = labels(swung)
    assert not any("sweet area" in n for n in names)  # e_A's, at rest: its peak is elsewhere
    assert "exit speed, swung racket within 5 % of its largest" in names
    star = next(line for line in swung.get_lines() if line.get_label().startswith("largest"))
    i, j = np.unravel_index(np.argmax(face.exit_speed_swung), face.e_A.shape)
    assert star.get_ydata()[0] == pytest.approx(100 * face.positions[i])
    assert star.get_xdata()[0] == pytest.approx(100 * face.offsets[i, j])
    assert face.exit_speed == pytest.approx(16.5 * face.e_A, rel=1e-12)  # same peak region
    for field in ("e_A", "exit_speed"):  # the sweet area is theirs
        assert any("sweet area" in n for n in labels(plots.plot_face_map(face, field)))
    for field in ("vibration_energy", "roll_rate"):  # no peak to seek
        names = labels(plots.plot_face_map(face, field))
        assert not any("sweet area" in n or "largest" in n for n in names)


def test_speeds_against_time_and_impact_speeds_are_in_the_unit_typed(results):
    from common.units import KMH, MPH

    axes = plots.plot_impact(results["impact"], unit="km/h")
    assert axes[2].get_ylabel() == "velocity [km/h]"
    ball = axes[2].get_lines()[0].get_ydata()
    assert ball == pytest.approx(results["impact"].ball_velocity / KMH)
    axes = plots.plot_collision(results["collision"], unit="mph")
    assert axes[2].get_ylabel() == "velocity [mph]"
    axes = plots.plot_rigid_bounce(results["bounce"], unit="mph")
    assert axes[3].get_xlabel() == "impact speed [mph]"
    assert axes[0].get_lines()[0].get_xdata() == pytest.approx(np.array([10.0, 30.0]) / MPH)


def test_a_sweep_typed_in_kmh_labels_its_curves_in_kmh(results):
    from common.units import KMH

    table = results["sweep"].copy()
    table["speed_kmh"] = table["speed_m_s"] / KMH
    ax = plots.plot_cor_along_racket(table, results["racket"])
    names = {n for n in labels(ax) if n.startswith("e (")}
    assert names == {f"e (ball at {v / KMH:.4g} km/h, f1 {f:g} Hz)"
                     for v in (10, 20) for f in (120, 180)}  # fmt: skip
