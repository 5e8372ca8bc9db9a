"""Property tests: momentum conserved, energy budget closed, 0 <= e <= 1, for any balls."""

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from ball import (
    WALL,
    Ball,
    GrowingHysteresis,
    LinearHysteresis,
    LinearSpring,
    PowerLawHysteresis,
    SineLaw,
    collide,
)

stiffness = st.floats(1e3, 1e6)
cor = st.floats(0.0, 1.0)
monotone_laws = st.one_of(
    st.builds(LinearSpring, stiffness),
    st.builds(LinearHysteresis, stiffness, cor),
    st.builds(
        PowerLawHysteresis.with_cor, st.floats(1e4, 1e8), st.floats(1.0, 2.0), st.floats(0.2, 1.0)
    ),
    st.builds(
        GrowingHysteresis,
        st.floats(1e4, 1e8),
        st.floats(1.0, 2.0),
        st.floats(0.3, 1.0),
        st.floats(0.0, 20.0),
    ),
)
mass = st.floats(1e-3, 1.0)
speed = st.floats(-30.0, 30.0)


def check_invariants(r, a, b):
    if b is not WALL:
        before = a.mass * r.v_a + b.mass * r.v_b
        after = a.mass * r.v_a_after + b.mass * r.v_b_after
        scale = a.mass * abs(r.v_a) + b.mass * abs(r.v_b)
        assert abs(after - before) <= 1e-9 * scale
    assert 0.0 <= r.e <= 1.0 + 1e-9
    assert r.energy_final <= r.energy_initial * (1 + 1e-9)
    budget = r.energy_lost - r.energy_dissipated_a - r.energy_dissipated_b
    assert abs(budget) <= 1e-6 * r.energy_initial
    assert r.contact_time > 0 and r.peak_force > 0


# 20 examples (60 before): each pair's event-located collision takes about 0.35 s, and this
# test took a fifth of the suite; CI derandomizes, so it checks the same 20 every run.
@settings(max_examples=20, deadline=None)
@given(mass, monotone_laws, mass, monotone_laws, speed, speed)
def test_monotone_pairs(m_a, law_a, m_b, law_b, v1, v2):
    if math.isclose(v1, v2, abs_tol=1e-3):
        v1 = v2 + 1.0
    v_a, v_b = max(v1, v2), min(v1, v2)
    a, b = Ball(m_a, law_a), Ball(m_b, law_b)
    check_invariants(collide(a, b, v_a, v_b), a, b)


@settings(max_examples=25, deadline=None)
@given(
    mass,
    stiffness,
    st.one_of(st.just(None), st.tuples(mass, monotone_laws)),
    st.floats(0.1, 30.0),
    st.booleans(),
)
def test_unhappy_ball_with_any_partner(m_u, k0, partner, closing, unhappy_first):
    u = Ball(m_u, SineLaw(k0))
    other = WALL if partner is None else Ball(*partner)
    if other is WALL or unhappy_first:
        a, b = u, other
    else:
        a, b = other, u
    r = collide(a, b, closing)
    check_invariants(r, a, b)
