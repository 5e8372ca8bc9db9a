"""Property tests of racket impacts: momentum conserved, 0 <= e <= 1, budget closes."""

import numpy as np
from helpers import drawn_law, examples
from hypothesis import given, settings
from hypothesis import strategies as st

from ball import Ball, GrowingHysteresis, LinearHysteresis, LinearSpring, PowerLawHysteresis
from ball.stiffening import StiffeningHysteresis
from beam import Beam
from racket import Racket, StringBed, impact

laws = st.one_of(
    drawn_law(LinearSpring, (1e4, 1e5)),
    drawn_law(LinearHysteresis, (1e4, 1e5), (0.3, 1.0)),
    drawn_law(PowerLawHysteresis.with_cor, (1e5, 1e7), (1.0, 1.8), (0.4, 1.0)),
    drawn_law(GrowingHysteresis, (1e5, 1e7), (1.0, 1.8), (0.4, 1.0), (0.0, 15.0)),
    drawn_law(StiffeningHysteresis, (1e4, 1e5), (0.02, 0.04), (0.4, 1.0), (0.0, 15.0)),
)


@settings(max_examples=examples(15), deadline=None)
@given(
    st.floats(0.03, 0.2),
    laws,
    st.floats(2.0, 40.0),
    st.floats(80.0, 250.0),
    st.floats(1e4, 1e5),
    st.floats(0.25, 0.45),
)
def test_impact_invariants(m1, law, speed, f1, k_s, mass):
    racket = Racket(Beam.uniform(0.68, mass, f1), StringBed(k_s, (0.0, 0.32)))
    r = impact(racket, Ball(m1, law), np.linspace(0.0, 0.32, 9), speed)
    p_after = m1 * -r.ball_rebound + mass * r.v_cm
    assert np.allclose(p_after, m1 * speed, rtol=1e-9)
    assert np.all((r.e >= 0) & (r.e <= 1 + 1e-9))
    assert np.all(np.abs(r.energy_residual) < 1e-4 * r.energy_initial)
