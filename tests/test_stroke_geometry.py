"""The geometry of a stroke (racket/stroke.py): the face frame, its way back to the world,
the spin conventions and the checks of the inputs."""

import math

import numpy as np
import pytest
from helpers import examples
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from racket.stroke import (
    LIMITS,
    RPM,
    STROKE_SOURCES,
    STROKES,
    Flight,
    Stroke,
    rad_per_s,
    rpm,
)

X, Y, Z = np.eye(3)


def _angle(name):
    low, high, _ = LIMITS[name]
    return st.floats(math.radians(low), math.radians(high))


@st.composite
def strokes(draw):
    """Any stroke that closes on the ball."""
    kwargs = {
        "head_speed": draw(st.floats(0.0, 60.0)),
        "path_angle": draw(_angle("path_angle")),
        "face_angle": draw(_angle("face_angle")),
        "ball_speed": draw(st.floats(0.0, 80.0)),
        "ball_angle": draw(_angle("ball_angle")),
        "swing_across": draw(_angle("swing_across")),
        "topspin": draw(st.floats(-1000.0, 1000.0)),
        "sidespin": draw(st.floats(-1000.0, 1000.0)),
        "shaft": draw(st.sampled_from(["horizontal", "vertical"])),
    }
    try:
        return Stroke(**kwargs)
    except ValueError as error:
        assert "misses the ball" in str(error)
        assume(False)


def _friction_spin(frame):
    """The direction [face components] of the spin that friction opposing the slip gives:
    the force -slip acts at the ball's contact point, -R e_n from its centre."""
    force = np.array([*(-frame.slip_velocity), 0.0])
    return np.cross(-np.array([0.0, 0.0, 1.0]), force)


def test_head_on_the_face_sees_no_slip_and_the_speeds_add():
    stroke = Stroke(20.0, 0.0, 0.0, 15.0, 0.0)
    frame = stroke.face_frame()
    assert frame.closing_speed == pytest.approx(35.0)
    assert frame.ball_normal_speed == pytest.approx(15.0)
    assert frame.racket_normal_speed == pytest.approx(20.0)
    assert frame.slip_velocity == pytest.approx([0.0, 0.0], abs=1e-12)
    assert frame.spin == pytest.approx([0.0, 0.0, 0.0], abs=1e-12)


@settings(max_examples=examples(200), deadline=None)
@given(strokes())
def test_the_face_axes_are_orthonormal_and_right_handed(stroke):
    basis = stroke.face_frame().basis
    assert basis @ basis.T == pytest.approx(np.eye(3), abs=1e-12)
    assert np.cross(basis[0], basis[1]) == pytest.approx(basis[2], abs=1e-12)
    assert np.linalg.det(basis) == pytest.approx(1.0)
    assert basis[2] == pytest.approx(stroke.normal())
    assert basis[2][0] > 0  # the normal points forward
    if stroke.shaft == "horizontal":
        assert basis[0] == pytest.approx(Y)  # the long axis to the player's left
        assert basis[1][2] > 0  # across: up the face
    else:
        assert basis[0][2] > 0 and basis[0][1] == 0  # the tip up, in the X-Z plane
        assert basis[1] == pytest.approx(-Y)


@settings(max_examples=examples(200), deadline=None)
@given(strokes())
def test_the_incoming_ball_goes_to_the_face_and_back(stroke):
    frame = stroke.face_frame()
    flight = stroke.to_world(frame.slip_velocity, -frame.closing_speed, frame.spin)
    scale = 1e-12 * (1 + stroke.head_speed + stroke.ball_speed)
    assert flight.velocity == pytest.approx(stroke.ball_velocity(), abs=scale)
    assert flight.spin == pytest.approx(stroke.ball_spin(), abs=1e-9)
    if stroke.ball_speed > 1e-3 * (1 + stroke.head_speed):  # else round-off sets its direction
        assert flight.topspin == pytest.approx(stroke.topspin, abs=1e-9)
        assert flight.sidespin == pytest.approx(stroke.sidespin, abs=1e-9)
        assert flight.rifle_spin == pytest.approx(0.0, abs=1e-9)
        assert flight.speed == pytest.approx(stroke.ball_speed)
        assert flight.launch_angle == pytest.approx(-stroke.ball_angle, abs=1e-9)
        assert abs(flight.direction) == pytest.approx(math.pi, abs=1e-9)


def test_the_racket_velocity_change_is_added_in_face_components():
    stroke = STROKES["kick-serve"]
    basis = stroke.basis()
    change = [0.5, -1.0, -3.0]
    base = stroke.to_world([1.0, 2.0], 30.0, [0.0, 0.0, 0.0])
    moved = stroke.to_world([1.0, 2.0], 30.0, [0.0, 0.0, 0.0], racket_velocity_change=change)
    assert moved.velocity - base.velocity == pytest.approx(basis.T @ change)
    assert base.velocity == pytest.approx(stroke.racket_velocity() + basis.T @ [1.0, 2.0, 30.0])


@pytest.mark.parametrize("w", [300.0, -150.0])
def test_the_spin_split_of_a_flight(w):
    forward = Flight([30.0, 0.0, 0.0], w * Y)  # the top of the ball moves forwards
    assert (forward.topspin, forward.sidespin, forward.rifle_spin) == (w, 0.0, 0.0)
    assert Flight([30.0, 0.0, 0.0], w * Z).sidespin == w
    assert Flight([30.0, 0.0, 0.0], w * X).rifle_spin == w
    left = Flight([0.0, 20.0, 5.0], w * np.cross(Z, Y))  # flying to the player's left
    assert left.direction == pytest.approx(math.pi / 2)
    assert left.topspin == pytest.approx(w)
    assert left.launch_angle == pytest.approx(math.atan2(5.0, 20.0))
    assert left.spin_rate == pytest.approx(abs(w))
    up = Flight([0.0, 0.0, 10.0], w * Y)  # vertical: the horizontal direction is +X
    assert (up.direction, up.launch_angle, up.topspin) == (0.0, pytest.approx(math.pi / 2), w)


def test_a_flight_is_frozen():
    flight = Flight([30.0, 1.0, 2.0], [0.0, 100.0, 0.0])
    with pytest.raises(ValueError, match="read-only"):
        flight.velocity[0] = 0.0
    with pytest.raises(AttributeError):
        flight.speed = 3.0


@pytest.mark.parametrize("shaft", ["horizontal", "vertical"])
def test_a_rising_racket_slides_the_ball_down_the_face_into_topspin(shaft):
    """A rising path with a vertical face: the ball slides down the face, friction drags
    its back upwards, and the ball leaves forwards with topspin > 0."""
    stroke = Stroke(25.0, math.radians(20.0), 0.0, 20.0, 0.0, shaft=shaft)
    frame = stroke.face_frame()
    down = frame.basis.T @ [*frame.slip_velocity, 0.0]
    assert down == pytest.approx(-25.0 * math.sin(math.radians(20.0)) * Z)
    out = stroke.to_world([0.0, 0.0], 20.0, 50.0 * _friction_spin(frame) / 25.0)
    assert out.velocity[0] > 0
    assert out.topspin > 0
    assert out.sidespin == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("name", ["slice-serve", "kick-serve"])
def test_the_serves_across_the_ball_give_a_right_handers_sidespin(name):
    """The racket path to the right of the face's aim (swing_across < 0) brushes the ball's
    back to the right: sidespin > 0, which curves the ball to the left."""
    stroke = STROKES[name]
    frame = stroke.face_frame()
    out = stroke.to_world([0.0, 0.0], 40.0, _friction_spin(frame))
    assert stroke.swing_across < 0
    assert out.sidespin > 0
    assert out.topspin > 0  # the racket rises along the face too


def test_the_presets():
    assert (
        set(STROKES)
        == set(STROKE_SOURCES)
        == {
            "flat-serve",
            "slice-serve",
            "kick-serve",
            "topspin-forehand",
            "flat-forehand",
            "slice-backhand",
            "volley",
        }
    )
    serves = [s for name, s in STROKES.items() if name.endswith("serve")]
    assert {s.head_speed for s in serves} == {38.0}  # Gordon's "slightly more than 85 mph"
    assert {s.shaft for s in serves} == {"vertical"}
    others = [s for name, s in STROKES.items() if not name.endswith("serve")]
    assert {s.shaft for s in others} == {"horizontal"}
    forehand = STROKES["topspin-forehand"]  # Landlinger's 33.1 m/s along Kwon's 18.6 deg
    assert forehand.head_speed * math.cos(forehand.path_angle) == pytest.approx(33.1, abs=1e-12)
    assert forehand.path_angle == pytest.approx(math.radians(18.6))
    assert STROKES["flat-forehand"].head_speed == pytest.approx(21.9, abs=0.01)  # 49 mph
    for name, stroke in STROKES.items():
        assert stroke.face_frame().closing_speed > 0, name
        assert "assum" in STROKE_SOURCES[name], name


def test_rpm_conversions():
    assert RPM == pytest.approx(2 * math.pi / 60)
    assert rpm(2 * math.pi) == pytest.approx(60.0)
    assert rad_per_s(60.0) == pytest.approx(2 * math.pi)
    assert rpm(rad_per_s(np.array([1000.0, 3000.0]))) == pytest.approx([1000.0, 3000.0])


GOOD = {"head_speed": 20.0, "path_angle": 0.2, "face_angle": 0.0, "ball_speed": 15.0}
GOOD["ball_angle"] = 0.1


@pytest.mark.parametrize(
    "name, value, words",
    [
        ("face_angle", math.pi / 2, ["face_angle must be in [-1.047, 1.047] rad", "90 deg"]),
        ("face_angle", 30.0, ["degrees typed as radians? 30 deg would be 0.5236 rad"]),
        ("path_angle", -1.2, ["path_angle must be in [-1.047, 1.396] rad", "-60 to 80 deg"]),
        ("swing_across", 2.0, ["swing_across must be in"]),
        ("ball_angle", float("nan"), ["ball_angle must be a finite number rad"]),
        ("head_speed", 100.0, ["head_speed must be in [0, 60] m/s", "mph typed as m/s?"]),
        ("head_speed", -1.0, ["head_speed must be in [0, 60] m/s, got -1"]),
        ("ball_speed", 81.0, ["ball_speed must be in [0, 80] m/s"]),
        ("topspin", 3000.0, ["topspin must be in [-1000, 1000] rad/s", "rpm typed as rad/s?"]),
        ("sidespin", -1001.0, ["sidespin must be in [-1000, 1000] rad/s"]),
        ("shaft", "diagonal", ["shaft must be 'horizontal' or 'vertical', got 'diagonal'"]),
    ],
)
def test_bad_inputs_are_named_with_their_range(name, value, words):
    with pytest.raises(ValueError) as caught:
        Stroke(**{**GOOD, name: value})
    message = str(caught.value)
    for word in words:
        assert word in message
    assert "\n" not in message


def test_a_racket_that_does_not_close_on_the_ball_misses():
    """A still racket, its face open by 60 deg, and a ball rising at 60 deg: the ball moves
    away from the face at 5 m/s (10 cos 120 deg)."""
    with pytest.raises(ValueError, match="misses the ball: they close at -5 m/s"):
        Stroke(0.0, 0.0, math.radians(60.0), 10.0, math.radians(-60.0))
    with pytest.raises(ValueError, match="misses the ball"):
        Stroke(0.0, 0.0, 0.0, 0.0, 0.0)


@pytest.mark.parametrize(
    "args, words",
    [
        (([1.0], 20.0, [0, 0, 0]), "tangential_velocity must hold 2 numbers"),
        (([1.0, 0.0], float("inf"), [0, 0, 0]), "normal_velocity must be a finite number"),
        (([1.0, 0.0], 20.0, [0, 0]), "spin_face must hold 3 numbers"),
        (([1.0, 0.0], 20.0, [0, 0, 0], [1.0]), "racket_velocity_change must hold 3 numbers"),
    ],
)
def test_to_world_names_a_bad_input(args, words):
    with pytest.raises(ValueError, match=words):
        STROKES["volley"].to_world(*args)


def test_a_tangential_stiffness_falling_to_zero_gives_a_finite_answer():
    """Issue 44: the tangential stiffness follows the ball's normal one, 0 at no force; its
    interpolation between samples may round to -1 ulp there, which once made the dashpot's
    sqrt NaN (the topspin forehand at a 26 degree path and a face 4 degrees closed)."""
    import math
    from dataclasses import replace

    import numpy as np

    from racket import STROKES, default_ball, default_racket, hit

    stroke = replace(STROKES["topspin-forehand"], path_angle=math.radians(26.0),
                     face_angle=math.radians(-4.0))  # fmt: skip
    out = hit(stroke, default_racket(), default_ball())
    assert np.all(np.isfinite(out.oblique.grip.velocity))
    assert np.all(np.isfinite(out.oblique.grip.spin))
