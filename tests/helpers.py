"""Helpers shared by the tests of the model (the command line's are in clihelpers.py): the
force laws drawn by hypothesis and how many examples a property test draws, a ball preset's
round trip through TOML, and a script's numbers from the solver's Python code run
uncompiled."""

import json
import os
import subprocess
import sys

from hypothesis import strategies as st

LOCAL_SHARE = 4
"""Outside CI (``CI`` unset), a property test draws this many times fewer examples (at least
:data:`LOCAL_LEAST`): the suite a contributor runs often stays short, and CI, which sets
``CI`` and derandomizes the draws (``tests/conftest.py``), runs the full set every time."""

LOCAL_LEAST = 5


def examples(count: int) -> int:
    """The examples a property test draws: ``count`` on CI, a share of it elsewhere."""
    return count if os.environ.get("CI") else max(LOCAL_LEAST, count // LOCAL_SHARE)


def drawn_law(make, *ranges):
    """A hypothesis strategy of ``make(*values)`` (a force law), each value a float drawn
    from its ``(low, high)`` range, in order."""
    return st.builds(make, *(st.floats(low, high) for low, high in ranges))


def assert_round_trips_through_toml(name: str, ball, law_keys: str, folder) -> None:
    """The preset ``name`` (``ball``) is loaded again from a TOML ``[ball]`` table naming it,
    and from one giving its numbers: its mass and radius, then ``law_keys`` (the TOML lines
    of its law and the law's parameters)."""
    from studies.config import load_ball

    by_name = folder / "named.toml"
    by_name.write_text(f'[ball]\npreset = "{name}"\n')
    by_numbers = folder / "numbers.toml"
    by_numbers.write_text(f"[ball]\nmass = {ball.mass!r}\nradius = {ball.radius!r}\n{law_keys}")
    assert load_ball(str(by_name)) == ball
    assert load_ball(str(by_numbers)) == ball


def run_uncompiled(script: str):
    """What ``script`` prints (as JSON), run in a new Python with numba's compiler off
    (``NUMBA_DISABLE_JIT=1``): the solver's kernels as plain Python."""
    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    run = subprocess.run(
        [sys.executable, "-W", "ignore", "-c", script],
        capture_output=True,
        text=True,
        env=env,
        check=True,
    )
    return json.loads(run.stdout)
