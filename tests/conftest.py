"""Test configuration: hypothesis, and the solver compiled before the tests.

* No "explain" phase: it traces every line a failing example runs, which through solve_ivp
  turns a quick failure report into many minutes.
* On CI (``CI`` set) the examples are derandomized, so every CI run checks the same cases
  and a failure is reproducible; local runs draw new examples each time.
"""

import os

import pytest
from hypothesis import Phase, settings

from racket import impact, paper_racket, tennis_ball

settings.register_profile(
    "racket-impact",
    phases=[Phase.explicit, Phase.reuse, Phase.generate, Phase.target, Phase.shrink],
    derandomize=bool(os.environ.get("CI")),
)
settings.load_profile("racket-impact")


@pytest.fixture(scope="session", autouse=True)
def _compiled_solver():
    """Compile (or load) the solver once before any test, so that no test's captured
    output holds the one-off "compiling the solver" notice."""
    impact(paper_racket(), tennis_ball(), 0.1, 10.0)
