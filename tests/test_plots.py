"""Each plot draws what it should (Agg backend)."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest

from ball import Ball, LinearSpring, SineLaw, collide
from racket import impact, paper_racket, tennis_ball
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
    table = sweep(racket, tennis_ball(), np.linspace(0, 0.32, 33), 10.0, progress=False)
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
    assert len(ax.patches) >= 3  # the racket drawn: frame, head, strings, grip
    assert ax.get_xlim()[1] >= 100 * racket.beam.length  # to scale, tip to butt in cm


def test_impact_history_splits_dc_and_ac():
    r = impact(paper_racket(), tennis_ball(), 0.03, 10.0, histories=True)
    axes = plots.plot_impact(r)
    assert len(axes) == 3
    names = labels(axes[2])
    assert "impact point, dc (rigid body)" in names and "impact point, ac (vibration)" in names
    total, dc, ac = (axes[2].get_lines()[i].get_ydata() for i in (1, 2, 3))
    # the curves are the impact's histories; the dc one ends at the rigid-body velocity that
    # momentum conservation gives the point (impulse / effective mass, Eq. 20)
    assert np.allclose(total, r.point_velocity, equal_nan=True)
    impulse = tennis_ball().mass * (10.0 + r.ball_rebound)
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
        paper_racket(), tennis_ball(), string_stiffness=[2e4, 6e4], ball_stiffness=[3e4, 6e4]
    )
    ax = plots.plot_serve_what_if(table)
    assert labels(ax) == ["string-bed stiffness", "ball stiffness"]


def test_multi_panel_plots_check_their_axes():
    with pytest.raises(ValueError, match="3 Axes"):
        plots.plot_impact(
            impact(paper_racket(), tennis_ball(), 0.1, 10.0, histories=True), ax=plt.subplots()[1]
        )


def test_cor_comparison_draws_each_racket_on_one_axes():
    from racket import CATALOG
    from studies.sweeps import compare

    rackets = {"paper": paper_racket(), "pd": CATALOG["pure-drive-2021"].racket()}
    table = compare(rackets, tennis_ball(), 10.0, points=9)
    groups = dict(tuple(table.groupby("racket", sort=False)))
    ax = plots.plot_cor_comparison(groups)
    names = [n for n in labels(ax) if not n.startswith("_")]
    assert [n.split(":")[0] for n in names] == ["paper", "pd"]
    best = table[table.racket == "pd"]["e"].max()
    assert f"largest {best:.3f}" in names[1]
    assert len(ax.get_lines()) == 4  # e and e_A for each
    _fig, given = plt.subplots()
    assert plots.plot_cor_comparison(groups, ax=given, show_apparent=False) is given
    assert len(given.get_lines()) == 2


def test_a_grid_table_draws_one_labelled_curve_per_grid_point():
    racket = paper_racket()
    x = np.linspace(0, 0.32, 9)
    table = sweep(racket, tennis_ball(), x, [10.0, 20.0], f1=[120.0, 180.0], progress=False)
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
