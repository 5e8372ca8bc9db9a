"""A string bed a stringer can describe (issue 35): material, gauge, pattern, tension and
state, and the stiffness, stretch, loss and mass that follow, against the published numbers
(the ERT's range in play, the paper's 3e4 N/m, Kawazoe's steel ball, TWU's single strings,
the gauge charts) and against a string solved numerically.  No solver runs here.
"""

import csv
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import root
from scipy.special import j0, jn_zeros

from common.units import IN2, LB
from racket import (
    CATALOG,
    STRINGS,
    String,
    Stringing,
    default_ball,
    default_racket,
    from_specs,
    impact,
    paper_racket,
    stringing,
)
from racket.specs.restring import with_tension
from racket.strings.sizes import GAUGES
from racket.strings.stringing import MODAL_MASS_RATIO, restrung
from racket.strings.twu_test import BED_STRAIN, TWU_LENGTH, TWU_STEPS

DATA = Path(__file__).resolve().parent / "data"
HUNDRED = 100.0 * IN2
ERT_IN_PLAY = (28.0 * 980.665, 46.0 * 980.665)
"""ERT 300: "most players' DT values fall between 28-46" kp/cm (data/measurements.md
sec. 5), in N/m (1 kp/cm = 980.665 N/m)."""

TWU_LOSS = {"polyester": 0.448, "nylon": 0.217, "multifilament": 0.213, "natural-gut": 0.153}
"""Tension loss in TWU's impact test (data/measurements.md sec. 5; multifilament:
data/twu_multifilament/README.md)."""

TWU_EA_FAST_KN = {"polyester": (11.3, 9.4, 13.0), "nylon": (9.0, 8.1, 10.1),
                  "multifilament": (8.6, 7.6, 9.3), "natural-gut": (5.4, 4.8, 5.9)}  # fmt: skip
"""EA at 51 lb, Fast, from the tension at impact [kN]: median (range), *derived* from TWU's
single-string test over the reconstructed 317.6 mm (data/measurements.md sec. 8;
multifilament: k at 51 lb Fast of data/twu_multifilament/medians.csv, median 155 and
p10-p90 137-167 lb/in, times 0.3176 m)."""

KAWAZOE_BAND = (1.0 - 0.98**2, 1.0 - 0.96**2)
"""Bed losses that keep a steel ball's COR at Kawazoe's 0.97 +/- 0.01."""

CHARTS_MM = {
    "15": (1.41, 1.49),
    "15L": (1.33, 1.41),
    "16": (1.26, 1.34),
    "17": (1.16, 1.26),
    "18": (1.06, 1.16),
    "19": (1.00, 1.10),
}
"""Gauge ranges [mm]: Ashaway (15-18) and Tennis Express (19), as cited in GAUGES."""

HYBRIDS = [f"{a}/{b}" for a in STRINGS for b in STRINGS if a != b]


def _pinned_string_force(w, length, tension, ea, segments=8):
    """Force [N] that holds the middle of a string pinned at both ends (length [m],
    tension [N], axial stiffness EA [N] at that tension) at a deflection w [m]: the string
    as ``segments`` links, each at the tension plus EA times its strain, whose free nodes
    scipy puts in equilibrium."""
    link = length / segments
    middle = segments // 2
    straight = np.linspace(0.0, length, segments + 1)
    tent = np.minimum(straight, length - straight) * 2.0 * w / length

    def nodes(free):
        xy = np.column_stack([straight, tent])
        inner = [i for i in range(1, segments) if i != middle]
        xy[inner] = free.reshape(-1, 2)
        return xy, inner

    def pulls(xy):
        links = np.diff(xy, axis=0)
        lengths = np.linalg.norm(links, axis=1)
        tensions = tension + ea * (lengths - link) / link
        pull = tensions[:, None] * links / lengths[:, None]  # on each link's first node
        net = np.zeros_like(xy)
        net[:-1] += pull
        net[1:] -= pull
        return net

    def residual(free):
        xy, inner = nodes(free)
        return pulls(xy)[inner].ravel()

    start = np.column_stack([straight, tent])[[i for i in range(1, segments) if i != middle]]
    solved = root(residual, start.ravel(), tol=1e-14)
    assert solved.success
    xy, _ = nodes(solved.x)
    return -pulls(xy)[middle, 1]


@pytest.mark.parametrize("name", STRINGS)
def test_the_papers_3e4_at_55_lb_on_100_in2_is_the_reference_patterns(name):
    strung = stringing(name, tension_n=245.0)  # the paper's 55 lb, as its Sec. VIII says
    assert strung.stiffness(HUNDRED) == pytest.approx(3e4, rel=1e-12)
    # the ERT's DT: the force at 1 cm, per cm, the bed's stiffening by then included
    at_1_cm = 3e4 * (1.0 + strung.stretch(HUNDRED) * 0.01**2)
    assert strung.dt(HUNDRED) == pytest.approx(at_1_cm / 980.665, rel=1e-12)


LOW_TENSION = pytest.mark.xfail(
    strict=True,
    reason="the membrane model's k is proportional to the tension and calibrated to the "
    "paper's 3e4 N/m at 55 lb, so 40 lb gives 2.2e4 N/m, below the ERT's 2.75e4: the two "
    "calibrations meet only at 53-80 lb (missing: a bed stiffness that does not scale with "
    "the tension alone)",
)


@pytest.mark.parametrize("name", STRINGS)
@pytest.mark.parametrize("head_in2", [95.0, 100.0])
@pytest.mark.parametrize("tension_lb", [pytest.param(40.0, marks=LOW_TENSION), 55.0, 65.0])
def test_every_preset_bed_lies_in_the_erts_range_in_play(name, head_in2, tension_lb):
    k = stringing(name, tension_n=tension_lb * LB).stiffness(head_in2 * IN2)
    assert ERT_IN_PLAY[0] <= k <= ERT_IN_PLAY[1]


@pytest.mark.parametrize("name", [*STRINGS, *HYBRIDS])
def test_played_strings_are_softer_by_their_materials_tension_loss(name):
    fresh = stringing(name, tension_n=55 * LB)
    played = stringing(name, tension_n=55 * LB, state="played")
    mains, crosses = (part if "/" in name else name for part in (name.split("/") * 2)[:2])
    kept = 1.0 - 0.5 * (TWU_LOSS[mains] + TWU_LOSS[crosses])
    assert played.stiffness(HUNDRED) / fresh.stiffness(HUNDRED) == pytest.approx(kept, 1e-12)


@pytest.mark.parametrize("name", STRINGS)
def test_twus_test_over_its_fast_step_gives_the_derived_ea_and_scales_with_the_stress(name):
    preset = STRINGS[name]
    twu = preset.material.twu
    median, low, high = (1e3 * v for v in TWU_EA_FAST_KN[name])
    fast = twu.axial_stiffness(twu.impact_tension, TWU_STEPS[-1])  # TWU's own impact
    assert fast == pytest.approx(median, abs=50.0)  # the table's rounding to 0.1 kN
    assert low < fast < high
    # a thinner string at the same stress: the same curve, EA scaled by the area
    thin = String(preset.material, "18")
    scale = (thin.gauge / preset.gauge) ** 2
    tension = 55.0 * LB
    assert thin.axial_stiffness(scale * tension) == pytest.approx(
        scale * preset.axial_stiffness(tension), rel=1e-9
    )


@pytest.mark.parametrize("name", ["polyester", "nylon", "natural-gut"])
def test_the_ea_a_bed_sees_comes_from_its_own_tension_on_twus_curve(name):
    twu = STRINGS[name].material.twu
    # the curve passes through TWU's three secants from the tension at impact
    for step, k in zip(TWU_STEPS, twu.secants, strict=True):
        assert twu.tension(step) - twu.impact_tension == pytest.approx(k * TWU_LENGTH * step)
    # at the tension at impact and TWU's step, EA is TWU's secant k L, whatever the tension
    # at which the string was strung
    assert twu.axial_stiffness(twu.impact_tension, TWU_STEPS[0]) == pytest.approx(
        twu.secants[0] * TWU_LENGTH, rel=1e-9
    )
    # on the curve, a bed string strung higher sees a lower EA (the curve bends over)
    ea = [twu.axial_stiffness(t * LB) for t in (40.0, 55.0, 70.0)]
    assert ea[0] > ea[1] > ea[2]


def _spread(name: str) -> float:
    """How much the EA a bed sees falls from 40 to 70 lb, relative to 55 lb's [-]."""
    twu = STRINGS[name].material.twu
    ea = [twu.axial_stiffness(t * LB) for t in (40.0, 55.0, 70.0)]
    return (ea[0] - ea[2]) / ea[1]


def test_polyester_s_ea_falls_with_tension_most():
    # its k falls from Slow to Fast (254 / 225 / 204 lb/in); nylon's and gut's hardly do
    assert _spread("polyester") > max(_spread("nylon"), _spread("natural-gut"))


def test_the_bed_strain_step_lies_among_the_default_racket_s_impacts():
    # the middle string's strain 2 w^2 / L^2 at the bed's peak deflection w, simulated at
    # the sweeps' speed and a serve's: BED_STRAIN lies between, and within TWU's steps
    racket, ball = default_racket(), default_ball()
    length = 2.0 * np.sqrt(racket.strings.area / np.pi)
    strains = []
    for speed in (16.5, 40.0):
        hit = impact(racket, ball, racket.strings.center, speed, histories=True)
        strains.append(2.0 * float(np.max(hit.string_deflection)) ** 2 / length**2)
    assert strains[0] < BED_STRAIN < strains[1]
    assert TWU_STEPS[0] <= BED_STRAIN <= TWU_STEPS[-1]


@pytest.mark.parametrize(
    "name, gauge, tension_lb, head_in2, state",
    [
        ("polyester", "16L", 55.0, 100.0, "fresh"),
        ("polyester", "18", 20.0, 120.0, "played"),
        ("natural-gut", "15", 80.0, 85.0, "fresh"),
        ("natural-gut/polyester", "17", 45.0, 98.0, "played"),
    ],
)
def test_the_stretch_is_a_pinned_strings_cubic_solved_numerically(
    name, gauge, tension_lb, head_in2, state
):
    strung = stringing(name, gauge, tension_n=tension_lb * LB, state=state)
    area = head_in2 * IN2
    length = 2.0 * np.sqrt(area / np.pi)  # the circle of the bed's area
    w = np.linspace(0.5e-3, 15e-3, 30)
    ea = strung.axial_stiffness(strung.bed_tension)
    force = [_pinned_string_force(x, length, strung.bed_tension, ea) for x in w]
    a, b, *_ = np.linalg.lstsq(np.column_stack([w, w**3, w**5, w**7]), force, rcond=None)[0]
    assert a == pytest.approx(4.0 * strung.bed_tension / length, rel=1e-6)
    assert strung.stretch(area) == pytest.approx(b / a, rel=1e-4)


def test_a_polyester_16l_bed_at_55_lb_is_about_a_tenth_stiffer_at_1_cm():
    stretch = stringing("polyester", "16L", tension_n=55 * LB).stretch(HUNDRED)
    assert 300.0 < stretch < 1500.0
    assert 0.05 < stretch * 0.01**2 < 0.2


@pytest.mark.parametrize("name", [*STRINGS, *HYBRIDS])
def test_every_beds_loss_keeps_kawazoes_steel_ball_at_0_97(name):
    for gauge in [*GAUGES, None]:
        for tension_lb in (20.0, 55.0, 80.0):
            for state in ("fresh", "played"):
                strung = stringing(name, gauge, tension_n=tension_lb * LB, state=state)
                assert KAWAZOE_BAND[0] <= strung.loss <= KAWAZOE_BAND[1]
                bed = strung.bed((0.02, 0.34))
                assert bed.loss == strung.loss and bed.stretch > 0.0


def test_nylon_loses_what_kawazoes_steel_ball_does_and_gut_least():
    loss = {name: stringing(name, tension_n=55 * LB).loss for name in STRINGS}
    assert loss["nylon"] == pytest.approx(1.0 - 0.97**2, rel=1e-12)
    # multifilament returns a little more than nylon in TWU's test (94.9 against 94.7 %)
    assert loss["natural-gut"] < loss["multifilament"] < loss["nylon"] < loss["polyester"]


@pytest.mark.parametrize("name", HYBRIDS)
@pytest.mark.parametrize("state", ["fresh", "played"])
def test_a_hybrid_lies_between_its_two_strings(name, state):
    mains, crosses = name.split("/")
    beds = [stringing(n, tension_n=55 * LB, state=state) for n in (mains, crosses, name)]
    for quantity in (
        lambda s: s.stiffness(HUNDRED),
        lambda s: s.stretch(HUNDRED),
        lambda s: s.loss,
        lambda s: s.mass(HUNDRED),
    ):
        one, other, hybrid = map(quantity, beds)
        assert min(one, other) - 1e-12 <= hybrid <= max(one, other) + 1e-12
    assert beds[2].hybrid and not beds[0].hybrid


def test_gauge_names_lie_in_the_published_charts_thickest_first():
    for name, (low, high) in CHARTS_MM.items():
        assert low <= 1e3 * GAUGES[name] <= high
    assert list(GAUGES.values()) == sorted(GAUGES.values(), reverse=True)
    assert String("poly", "16l").gauge == String("poly", 1.25e-3).gauge == GAUGES["16L"]


def test_the_bed_mass_counts_every_strings_chord_and_the_modal_mass_is_a_membranes():
    strung = stringing("polyester", tension_n=55 * LB)
    length = np.sqrt(4.0 * HUNDRED * 1.33 / np.pi)  # racket.strings.head.HEAD_ASPECT
    width = length / 1.33

    def chords(count, span, across):  # strings evenly spaced across the ellipse
        y = (np.arange(count) + 0.5) / count - 0.5
        return span * np.sqrt(1.0 - (2.0 * y) ** 2).sum()

    metres = chords(16, length, width) + chords(19, width, length)
    assert strung.mass(HUNDRED) == pytest.approx(metres * STRINGS["polyester"].linear_density, 0.02)
    assert 0.008 < strung.mass(HUNDRED) < 0.02  # the issue: a 16x19 bed weighs about 15-20 g
    j01 = jn_zeros(0, 1)[0]
    modal = 2.0 * quad(lambda r: j0(j01 * r) ** 2 * r, 0.0, 1.0)[0]  # / (pi R^2) of the mass
    assert modal == pytest.approx(MODAL_MASS_RATIO, abs=1e-4)
    assert strung.moving_mass(HUNDRED) == pytest.approx(modal * strung.mass(HUNDRED), rel=1e-3)


def test_a_measured_stiffness_is_kept_and_sets_the_stretch_by_its_tension():
    strung = stringing("polyester", tension_n=55 * LB)
    bed = strung.bed((0.02, 0.34))
    same = strung.bed((0.02, 0.34), stiffness=bed.stiffness)
    assert same.stretch == pytest.approx(bed.stretch, rel=1e-12)
    measured = Stringing("polyester").bed((0.02, 0.34), stiffness=40 * 980.665)
    assert measured.stiffness == 40 * 980.665 and measured.stringing.tension is None
    assert measured.stretch < bed.stretch  # a stiffer bed: a higher tension, a smaller ratio


def test_the_description_says_what_a_stringer_would():
    assert stringing("poly", tension_n=55 * LB).describe() == (
        "polyester 1.25 mm 16x19 at 55 lb, fresh"
    )
    hybrid = stringing("gut/poly", pattern="18x20", tension_n=52 * LB, state="played")
    assert hybrid.describe() == "natural gut 1.30 mm/polyester 1.25 mm 18x20 at 52 lb, played"
    assert stringing("gut/nylon", "17").describe().startswith("natural gut/nylon 1.20 mm 16x19")


def test_catalogue_rackets_are_strung_in_their_own_pattern_and_the_paper_keeps_its_spring():
    with open(DATA / "twu_racquets_half.csv", newline="") as f:
        patterns = {row["Model"]: row["String Pattern"] for row in csv.DictReader(f)}
    twu = {"pure-drive-2021": "Pure Drive (2021)", "pro-staff-97l-cv": "Pro Staff 97L v13"}
    for name, model in twu.items():
        strung = CATALOG[name].racket().strings.stringing
        assert "{}x{}".format(*strung.pattern) == patterns[model]
    bed = default_racket().strings
    assert bed.stretch > 0.0 and bed.loss > 0.0
    assert bed.stringing.describe() == "polyester 1.25 mm 16x19 at 55 lb, fresh"
    assert paper_racket().strings.plain and paper_racket().strings.stringing is None
    assert all(set(entry.strung_sources) == set(entry.strung) for entry in CATALOG.values())


def test_from_specs_strings_a_racket_and_gives_the_papers_bed_by_name():
    sheet = dict(CATALOG["pure-drive-2021"].specs)
    plain = from_specs(**sheet, string="linear")
    assert plain.strings.plain and plain.strings.stringing is None
    assert from_specs(**sheet).strings.stringing.describe() == (
        "polyester 1.25 mm 16x19 at 55 lb, fresh"  # the one rule (racket.specs.strung)
    )
    gut = from_specs(**sheet, string="gut", gauge="17", pattern="18x20", state="played")
    assert gut.strings.stringing.describe() == "natural gut 1.20 mm 18x20 at 55 lb, played"
    assert gut.strings.stiffness == pytest.approx(
        gut.strings.stringing.stiffness(gut.strings.area), rel=1e-12
    )
    del sheet["tension_lb"]
    measured = from_specs(**sheet, string_stiffness_n_m=3.5e4, string="poly")
    assert measured.strings.stiffness == 3.5e4 and measured.strings.loss > 0.0


def test_restringing_at_another_tension_keeps_the_strings():
    racket = with_tension(default_racket(), 60 * LB)
    strung = racket.strings.stringing
    assert strung.tension == pytest.approx(60 * LB) and strung.mains.material.name == "polyester"
    assert racket.strings.stiffness == pytest.approx(strung.stiffness(racket.strings.area))


@pytest.mark.parametrize(
    "make, said",
    [
        (lambda: String("poly", 1.25), "mm typed as m? 1.25 mm would be 0.00125 m"),
        (lambda: String("poly", 0.05), "inches typed as m? 0.05 in would be 0.00127 m"),
        (lambda: String("poly", 16), "a gauge name is a word: '16'"),
        (lambda: String("poly", "16LL"), "16L, 17, 17L, 18, 19) or a diameter [m], got '16LL'"),
        (lambda: String("polx", "16"), "unknown string material 'polx'; materials: polyester"),
        (lambda: Stringing("poly", pattern="16-19"), "pattern must be MAINSxCROSSES"),
        (lambda: Stringing("poly", pattern=(30, 19)), "pattern mains must be in [12, 22]"),
        (lambda: Stringing("poly", pattern=(16, 10)), "pattern crosses must be in [14, 24]"),
        (lambda: Stringing("poly", tension=55), "lb typed as N? 55 lb would be 244.7 N"),
        (lambda: Stringing("poly", tension=25), "kg typed as N? 25 kg would be 245.2 N"),
        (lambda: Stringing("poly", state="old"), "state must be one of 'fresh', 'played'"),
        (lambda: stringing("gut/poly/nylon"), "name must be a preset or MAINS/CROSSES"),
        (lambda: Stringing("poly").stiffness(HUNDRED), "this stringing has no tension"),
        (lambda: from_specs(string="linear", gauge="16L"), "gauge describes a string, and"),
    ],
)
def test_each_bad_input_is_refused_in_one_line_with_its_range_or_a_hint(make, said):
    with pytest.raises(ValueError) as refused:
        make()
    assert said in str(refused.value) and "\n" not in str(refused.value)


def test_restringing_replaces_what_is_given_and_keeps_the_rest():
    bed = default_racket().strings
    nylon = restrung(bed, string="nylon")
    assert nylon.stringing.describe() == "nylon 1.30 mm 16x19 at 55 lb, fresh"
    assert nylon.stiffness == pytest.approx(bed.stiffness, rel=1e-12)  # same tension, same k
    assert nylon.loss == pytest.approx(1.0 - 0.97**2, rel=1e-12)
    played = restrung(bed, pattern="18x20", state="played")
    ratio = played.stiffness / bed.stiffness
    assert ratio == pytest.approx((1.0 - TWU_LOSS["polyester"]) * 38 / 35, rel=1e-12)
    measured = restrung(bed, stiffness=3.5e4)
    assert measured.stiffness == 3.5e4 and measured.stringing.tension is None
    paper = paper_racket().strings
    assert restrung(paper, string="gut").stiffness == paper.stiffness
    with pytest.raises(ValueError, match=r"^gauge describes a string, and this string bed has"):
        restrung(paper, gauge="17")


@pytest.mark.parametrize("name", [*STRINGS, "natural-gut/polyester"])
def test_a_dt_reads_back_or_is_refused_in_one_line(name):
    # every DT a command accepts (studies.strings.inputs.DT_RANGE) either gives the centre
    # stiffness that reads it, or a one-line refusal naming the input: never a solver's error
    from racket.strings.ert import dt_reading, stiffness_from_dt
    from studies.strings.inputs import DT_RANGE

    for gauge, pattern in (("16L", "16x19"), ("19", "18x20"), ("15", "16x19")):
        bed = stringing(name, gauge, pattern, 55 * LB).bed((0.02, 0.34))
        for dt in np.geomspace(*DT_RANGE, 12):
            try:
                k = stiffness_from_dt(bed, dt, "--string-bed-dt")
            except ValueError as refused:
                said = str(refused)
                assert said.startswith("--string-bed-dt ") and "\n" not in said
                continue
            bed_k = restrung(bed, stiffness=k)
            assert dt_reading(bed_k.stiffness, bed_k.stretch) == pytest.approx(dt, rel=1e-8)
