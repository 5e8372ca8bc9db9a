"""A player's questions: the sweet spots in one convention, the feel at the hand, and
positions counted from the butt everywhere (issue 14)."""

import json
from dataclasses import replace

import numpy as np
import pandas as pd
import pytest

from racket import CATALOG, Swing, impact, tennis_ball
from racket.feel import hand_feel
from studies.cli import main
from studies.landmarks import HAND_FROM_BUTT, sweet_spots
from studies.tables import feel_table


@pytest.fixture(scope="module")
def racket():
    return CATALOG["pure-drive-2021"].racket()


def test_sweet_spots_agree_with_the_beam_and_count_from_the_butt(racket):
    table = sweet_spots(racket, tennis_ball(), 10.0, swing=Swing(20.0)).set_index("spot")
    beam, length = racket.beam, racket.beam.length
    nodes = table[table.index.str.startswith("node of mode 1")]
    assert nodes["from_tip_cm"].to_numpy() / 100 == pytest.approx(beam.modes.nodes(1), abs=1e-9)
    assert nodes["from_butt_cm"].to_numpy() / 100 == pytest.approx(
        length - beam.modes.nodes(1), abs=1e-9
    )
    # the centre of percussion: an impulse there leaves the hand's pivot at rest, checked
    # on the rigid body (Eq. 20's motion): v_cm + (x_cm - pivot) omega = 0
    cop = table.loc["centre of percussion", "from_tip_cm"] / 100
    pivot = length - HAND_FROM_BUTT
    v_cm, omega = 1.0 / beam.mass, (beam.center_of_mass - cop) / beam.inertia_cm
    assert abs(v_cm + (beam.center_of_mass - pivot) * omega) < 1e-9 * v_cm
    for spot in ("largest e", "largest e_A", "dead spot", "largest exit speed", "sweet area"):
        assert spot in table.index
    assert table.loc["dead spot", "value"] < table.loc["largest e_A", "value"]


def test_feel_at_the_hand_is_the_impact_carried_on(racket):
    """The handle's motion comes from driving the racket's modes with the solver's contact
    force: without damping, the frame's vibration energy after the ball has left stays what
    the solver found when it left (1e-3: the last step of the contact); a free racket's hand
    takes nothing; a hand-held one takes energy, and its handle rings at the held first
    mode."""
    undamped = replace(racket, beam=replace(racket.beam, damping=0.0))
    feel = hand_feel(undamped, tennis_ball(), 0.12, 20.0, duration=0.03)
    hit = impact(undamped, tennis_ball(), 0.12, 20.0)
    assert feel.vibration_energy_end == pytest.approx(hit.vibration_energy, rel=1e-3)
    assert feel.hand_energy == 0.0
    held = replace(racket, support="hand-held")
    feel = hand_feel(held, tennis_ball(), racket.strings.center, 20.0)
    assert 0 < feel.hand_vibration_energy < feel.hand_energy
    above = feel.frequencies > 20
    dominant = feel.frequencies[above][np.argmax(feel.spectrum[above])]
    assert abs(dominant - 152.9) <= feel.frequencies[1]  # specs: held mode 1 at 152.9 Hz
    assert feel.peak_acceleration > 100.0 and feel_table(feel).shape[0] == feel.t.size
    off = hand_feel(held, tennis_ball(), racket.strings.center, 20.0, offset=0.06)
    assert np.abs(off.twist_rate).max() > 1.0


def test_cli_positions_count_from_the_butt_with_the_tip_beside(tmp_path, capsys):
    """One convention: every table a command writes that names a distance from the tip has
    the distance from the butt beside it."""
    files = {}
    for name, argv in {
        "sweep": ["sweep", "--racket", "pure-drive-2021", "--points", "5"],
        "map": ["map", "--grid", "5", "5"],
        "compare": ["compare", "--racket", "paper", "--racket", "pure-drive-2021", "--points", "5"],
        "serve": ["serve", "--racket-speed", "30"],
        "sweetspots": ["sweetspots", "pure-drive-2021"],
        "modes": ["modes"],
        "feel": ["feel", "--duration-ms", "10"],
    }.items():
        files[name] = tmp_path / f"{name}.json"
        assert main([*argv, "--out", str(files[name])]) == 0, name
    capsys.readouterr()
    for name, path in files.items():
        rows = json.loads(path.read_text())
        columns = set(pd.DataFrame(rows).columns)
        for column in columns:
            if "from_tip" in column:
                assert column.replace("from_tip", "from_butt").replace("_m", "_cm") in columns or (
                    column.replace("from_tip", "from_butt") in columns
                ), (name, column)


def test_tension_strings_the_racket_as_its_spec_sheet_does(racket, capsys):
    from common.units import LB
    from racket import from_specs
    from racket.specs.strings import with_tension
    from studies.sweeps import sweep

    specs = CATALOG["pure-drive-2021"].specs
    for lb in (45.0, 62.0):
        sheet = from_specs(**(specs | {"tension_lb": lb}))
        restrung = with_tension(racket, lb * LB)
        assert restrung.strings.stiffness == pytest.approx(sheet.strings.stiffness, rel=1e-12)
    node = racket.beam.modes.nodes(1)[0]
    table = sweep(racket, tennis_ball(), [node], 20.0, tension=[45 * LB, 55 * LB, 65 * LB],
                  progress=False)  # fmt: skip
    assert table["tension_N"].tolist() == pytest.approx([45 * LB, 55 * LB, 65 * LB])
    assert np.all(np.diff(table["e"]) < 0)  # tighter strings, lower e at the node
    assert main(["sweep", "--tension-lb", "55", "--string-stiffness", "3e4"]) == 2
    assert "not both" in capsys.readouterr().err


def test_tables_describe_themselves_and_rerun_from_the_sidecar(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sheet = tmp_path / "mine.toml"
    sheet.write_text(
        "[racket.specs]\nmass_kg = 0.3\nbalance_cm = 33\nswingweight_kgcm2 = 315\n"
        "f1_hz = 150\nhead_size_in2 = 100\ntension_lb = 55\n"
    )  # fmt: skip
    argv = ["sweep", "--racket", "mine.toml", "--points", "4", "--swing-speed-mph", "60",
            "--speed", "0", "--out", "s.csv"]  # fmt: skip
    assert main(argv) == 0
    record = json.loads((tmp_path / "s.csv.meta.json").read_text())
    assert record["command"] == argv and record["versions"]["numpy"] == np.__version__
    assert record["inputs"]["racket"][0]["spec_sheet"]["swingweight_kgcm2"] == 315
    assert record["inputs"]["ball"][0]["preset"] == "tennis"  # the default, recorded
    assert record["options"]["pivot_cm_from_butt"] == -5.0
    first = (tmp_path / "s.csv").read_text()
    sheet.write_text(sheet.read_text().replace("315", "330"))  # the file changes ...
    (tmp_path / "s.csv").unlink()
    assert main(["rerun", "s.csv.meta.json"]) == 0
    assert (tmp_path / "s.csv").read_text() == first  # ... the rerun uses the recorded one
    again = json.loads((tmp_path / "s.csv.meta.json").read_text())
    assert again["command"] == argv  # the user's file, not the rerun's copy
    assert again["inputs"]["racket"][0]["toml_file"] == "mine.toml"
    sheet.unlink()  # and a rerun of the rerun, the file gone
    assert main(["rerun", "s.csv"]) == 0
    assert (tmp_path / "s.csv").read_text() == first
    assert main(["rerun", "mine.toml"]) == 2
    assert "sidecar" in capsys.readouterr().err
