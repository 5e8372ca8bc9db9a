"""A player's questions: the sweet spots in one convention, the feel at the hand, and
positions counted from the tip everywhere (issues 14 and 33)."""

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from racket import CATALOG, Swing, impact, paper_ball
from racket.feel import hand_feel
from racket.system import held_mode
from studies.cli import main
from studies.face.landmarks import HAND_FROM_BUTT
from studies.face.sweetspots import sweet_spots
from studies.tables import feel_table


@pytest.fixture(scope="module")
def racket():
    return CATALOG["pure-drive-2021"].racket()


def test_sweet_spots_agree_with_the_beam_and_count_from_the_tip(racket):
    table = sweet_spots(racket, paper_ball(), 10.0, swing=Swing(20.0)).set_index("spot")
    beam, length = racket.beam, racket.beam.length
    nodes = table[table.index.str.startswith("node of mode 1")]
    start, end = racket.strings.extent  # only where the ball can be centred on the strings
    on = [n for n in beam.modes.nodes(1) if start + 0.0335 <= n <= end - 0.0335]
    assert len(on) == 1 and len(beam.modes.nodes(1)) == 2  # the other is on the handle
    assert nodes["from_tip_cm"].to_numpy() / 100 == pytest.approx(on, abs=1e-9)
    assert not [c for c in table.columns if "butt" in c]  # one convention: from the tip
    # the hand the centre of percussion is for, from the tip too
    hand = table.loc["centre of percussion"]
    assert hand["unit"] == "cm from the tip (the hand)"
    assert hand["value"] / 100 == pytest.approx(length - HAND_FROM_BUTT, abs=1e-9)
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
    the solver found when it left (5e-3: the last step of the contact, and the string bed's
    push, which the feel does not carry on after the ball has left); a free racket's hand
    takes nothing; a hand-held one takes energy, and its handle rings at a held mode."""
    undamped = replace(racket, beam=replace(racket.beam, damping=0.0))
    feel = hand_feel(undamped, paper_ball(), 0.12, 20.0, duration=0.03)
    hit = impact(undamped, paper_ball(), 0.12, 20.0)
    assert feel.vibration_energy_end == pytest.approx(hit.vibration_energy, rel=5e-3)
    assert feel.hand_energy == 0.0
    held = replace(racket, support="hand-held")
    feel = hand_feel(held, paper_ball(), racket.strings.center, 20.0)
    assert 0 < feel.hand_vibration_energy < feel.hand_energy
    above = feel.frequencies > 20
    dominant = feel.frequencies[above][np.argmax(feel.spectrum[above])]
    # the handle rings at one of the held modes (those ``specs`` prints, racket.system)
    system = held.system
    held_hz = [held_mode(system, k)[0] for k in range(2, held.beam.modes.count)]
    assert min(abs(dominant - f) for f in held_hz) <= feel.frequencies[1]
    assert feel.peak_acceleration > 100.0 and feel_table(feel).shape[0] == feel.t.size
    off = hand_feel(held, paper_ball(), racket.strings.center, 20.0, offset=0.06)
    assert np.abs(off.twist_rate).max() > 1.0


def test_cli_positions_count_from_the_tip_with_the_cm_beside_the_m(tmp_path, capsys):
    """One convention: every table a command writes that names a position along the racket
    names it from the tip (none from the butt), and a position in m has the same position
    in cm beside it."""
    files = {}
    for name, argv in {
        "sweep": ["sweep", "--racket", "pure-drive-2021", "--points", "5"],
        "map": ["map", "--grid", "5", "5"],
        "compare": ["compare", "--racket", "paper", "--racket", "pure-drive-2021", "--points", "5"],
        "serve": ["serve", "--racket-speed", "30"],
        "sweetspots": ["sweetspots", "--racket", "pure-drive-2021"],
        "modes": ["modes"],
        "specs": ["specs"],
        "feel": ["feel", "--duration-ms", "10"],
    }.items():
        files[name] = tmp_path / f"{name}.json"
        assert main([*argv, "--out", str(files[name])]) == 0, name
    capsys.readouterr()
    for name, path in files.items():
        table = pd.DataFrame(json.loads(path.read_text()))
        columns = set(table.columns)
        assert not [c for c in columns if "butt" in c], name
        named = [c for c in columns if "from_tip" in c]
        assert bool(named) == (name != "feel"), name  # feel's table: histories at the hand
        for column in named:
            if column.endswith("_from_tip_m"):
                beside = column.replace("_from_tip_m", "_from_tip_cm")
                assert table[beside].to_numpy() == pytest.approx(
                    100 * table[column].to_numpy(), rel=1e-12
                ), (name, column)


def test_tension_strings_the_racket_as_its_spec_sheet_does(racket, capsys):
    from common.units import LB
    from racket import from_specs
    from racket.specs.restring import with_tension
    from studies.sweeps import sweep

    specs = CATALOG["pure-drive-2021"].specs
    for lb in (45.0, 62.0):
        sheet = from_specs(**(specs | {"tension_lb": lb}))
        restrung = with_tension(racket, lb * LB)
        assert restrung.strings.stiffness == pytest.approx(sheet.strings.stiffness, rel=1e-12)
    node = racket.beam.modes.nodes(1)[0]
    table = sweep(racket, paper_ball(), [node], 20.0, tension=[45 * LB, 55 * LB, 65 * LB],
                  progress=False)  # fmt: skip
    assert table["tension_N"].tolist() == pytest.approx([45 * LB, 55 * LB, 65 * LB])
    # e hardly moves with the tension (Kawazoe: "almost independent of ball velocity and
    # string tension"): the ball's loss, less at low tension, and the bed's mass, whose
    # vibration keeps less at high tension, pull against each other
    assert np.ptp(table["e"]) < 0.02
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
    # the default for a real racket (the real ball, issue 24), recorded
    assert record["inputs"]["ball"][0]["preset"] == "itf-type-2"
    assert record["options"]["pivot_cm_from_tip"] is None  # the wrist, said:
    assert "about the wrist (5 cm beyond the butt)" in record["conditions"]
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


def test_rerun_twice_is_the_same_table_and_sidecar_byte_for_byte(tmp_path, capsys, monkeypatch):
    # issue 46: the second rerun pointed at a temporary copy the first had named
    monkeypatch.chdir(tmp_path)
    (tmp_path / "mine.toml").write_text('[racket]\npreset = "pure-drive-2021"\n')
    assert main(["sweep", "--racket", "mine.toml", "--points", "3", "--out", "t.csv"]) == 0
    made = [(tmp_path / name).read_bytes() for name in ("t.csv", "t.csv.meta.json")]
    for _ in range(2):
        assert main(["rerun", "t.csv.meta.json"]) == 0
        again = [(tmp_path / name).read_bytes() for name in ("t.csv", "t.csv.meta.json")]
        assert again == made  # the record it reproduces, its time included
    record = json.loads(made[1])
    assert record["conditions"].startswith("racket mine.toml (")  # the user's own file
    assert "racket-impact-rerun" not in capsys.readouterr().out


def test_rerun_puts_back_only_whole_paths(tmp_path, capsys, monkeypatch):
    from studies.provenance import _restored

    monkeypatch.chdir(tmp_path)
    ball = "[ball]\nmass = 0.057\nlaw = \"linear-hysteresis\"\nk = 4e4\ne = {}\n"  # fmt: skip
    (tmp_path / "bb.toml").write_text(ball.format(0.7))
    (tmp_path / "b.toml").write_text(ball.format(0.8))
    argv = ["collide", "--a", "bb.toml", "--b", "b.toml", "--out", "o.csv"]
    assert main(argv) == 0
    first = (tmp_path / "o.csv").read_text()
    (tmp_path / "b.toml").write_text(ball.format(0.5))  # b.toml changes, bb.toml does not
    assert main(["rerun", "o.csv"]) == 0, capsys.readouterr().err
    assert (tmp_path / "o.csv").read_text() == first
    again = json.loads((tmp_path / "o.csv.meta.json").read_text())
    assert again["command"] == argv
    assert [again["inputs"][k][0]["toml_file"] for k in ("a", "b")] == ["bb.toml", "b.toml"]
    copies = {"/tmp/x/0/b.toml": "b.toml"}
    assert _restored("bb.toml", {"b.toml": "/c/b.toml"}) == "bb.toml"
    assert _restored("/tmp/x/0/b.toml", copies) == "b.toml"
    assert _restored("--b=/tmp/x/0/b.toml", copies) == "--b=b.toml"
    assert _restored("mine=/tmp/x/0/b.toml", copies) == "mine=b.toml"
    assert _restored("--b=/tmp/x/0/bb.toml", copies) == "--b=/tmp/x/0/bb.toml"


def test_rerun_records_the_recorded_inputs_of_racket_and_ball_files(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sheet = tmp_path / "r.toml"
    text = (
        "[racket.specs]\nmass_kg = 0.3\nbalance_cm = 33\nswingweight_kgcm2 = 315\n"
        "f1_hz = 150\nhead_size_in2 = 100\ntension_lb = 55\n"
    )
    sheet.write_text(text)
    assert main(["specs", "--racket", "r.toml", "--out", "s.csv"]) == 0
    sheet.write_text(text.replace("315", "330"))  # edited after the run
    assert main(["rerun", "s.csv"]) == 0
    again = json.loads((tmp_path / "s.csv.meta.json").read_text())
    assert again["inputs"]["racket"] == [
        {**again["inputs"]["racket"][0], "given": "r.toml", "toml_file": "r.toml", "toml": text}
    ]
    assert again["options"]["racket"] == "r.toml"
    ball = tmp_path / "h.toml"
    examples = Path(__file__).parent.parent / "examples"
    ball.write_text((examples / "hertz_ball.toml").read_text())
    assert main(["ball", "h.toml", "--speeds", "10", "20", "--out", "b.csv"]) == 0
    ball.unlink()  # deleted after the run
    assert main(["rerun", "b.csv"]) == 0
    again = json.loads((tmp_path / "b.csv.meta.json").read_text())
    assert again["command"][1] == "h.toml" and again["options"]["ball"] == "h.toml"
    assert again["inputs"]["ball"][0]["toml_file"] == "h.toml"
    assert again["inputs"]["ball"][0]["given"] == "h.toml"
    capsys.readouterr()


def test_sidecar_described_once_per_run_and_forgotten_after(tmp_path, capsys, monkeypatch):
    import studies.cli as cli
    import studies.provenance as provenance

    monkeypatch.chdir(tmp_path)
    calls = []
    describe = provenance.describe
    monkeypatch.setattr(provenance, "describe", lambda *a: calls.append(a) or describe(*a))
    argv = ["sweep", "--points", "3", "--out", "a.csv", "--csv", "c.csv", "--json", "j.json"]
    assert main(argv) == 0
    assert len(calls) == 1
    names = ("a.csv", "c.csv", "j.json")
    records = [json.loads((tmp_path / f"{n}.meta.json").read_text()) for n in names]
    assert all(r["command"] == argv for r in records)
    assert cli._RUN == {}  # a later write_table in this process records no old command
    cli.write_table(pd.DataFrame({"x": [1]}), str(tmp_path / "later.csv"))
    assert not (tmp_path / "later.csv.meta.json").exists()
    assert main(["sweep", "--points", "3", "--speed", "12", "--out", "a.csv"]) == 0
    assert json.loads((tmp_path / "a.csv.meta.json").read_text())["options"]["speed"] == [12.0]
    capsys.readouterr()


@pytest.mark.parametrize("lb, ok", [(20.0, True), (80.0, True), (19.9, False), (80.1, False)])
def test_tension_lb_is_one_range_for_sweep_compare_and_map(lb, ok, tmp_path, capsys):
    from common.units import LB
    from racket.specs.restring import with_tension
    from racket.specs.sheet import SPEC_RANGES
    from studies.sweeps import TENSION_RANGE

    assert TENSION_RANGE == pytest.approx([20 * LB, 80 * LB], rel=1e-15)
    assert SPEC_RANGES["tension_n"][:2] == TENSION_RANGE
    few = ["--tension-lb", str(lb)]
    commands = [
        ["sweep", "--points", "2", *few],
        ["compare", "--points", "2", *few],
        ["map", "--grid", "4", "4", *few],
    ]
    statuses = [main(argv) for argv in commands]
    err = capsys.readouterr().err
    assert statuses == ([0, 0, 0] if ok else [2, 2, 2]), err
    if not ok:
        assert err.count("--tension-lb must be in [20, 80] lb") == 3
        with pytest.raises(ValueError, match=r"tension must be in \[88.9"):
            with_tension(CATALOG["pure-drive-2021"].racket(), lb * LB)


def test_page_refuses_bad_lead_and_tension():
    from studies.page.dashboard import PageInputs, page_racket

    for lead in (-1.0, float("nan")):
        with pytest.raises(ValueError, match="lead_g must be"):
            page_racket(PageInputs(lead_g=lead))
    with pytest.raises(ValueError, match=r"tension_lb must be in \[20, 80\] lb, got 1000"):
        page_racket(PageInputs(tension_lb=1000.0))
    assert page_racket(PageInputs(lead_g=0.0)) is not None


def test_sweep_refuses_a_held_swing_before_any_impact(monkeypatch):
    import studies.sweeps as sweeps
    from racket import Swing, paper_racket

    ran = []
    monkeypatch.setattr(sweeps, "run_calls", lambda *a, **k: ran.append(a))
    with pytest.raises(ValueError, match="swing_speed must be 0 for a hand-held racket"):
        sweeps.sweep(paper_racket(), paper_ball(), [0.1], 0.0, support=["free", "hand-held"],
                     swing=Swing(20.0), progress=False)  # fmt: skip
    assert ran == []
