"""The accuracy/cost frontier of the impact solver: error in e against a 64-mode, 16x-step
solution, and time, for bending modes x steps per contact, with and without the static
correction for the modes left out.

    python benchmarks/accuracy.py

The reference and every variant run on the paper racket (free and hand-held), tennis ball
at 20 m/s, 161 points across the strings.  The defaults (DEFAULT_MODES modes, 300 steps per contact,
static correction) must keep max |de| <= 2e-5 (issue 10); the table shows what the other
choices would give.
"""

from __future__ import annotations

import contextlib
import time
from unittest import mock

import numpy as np

from beam import Beam
from beam.beam import DEFAULT_MODES
from racket import Racket, impact, paper_ball, paper_racket
from racket.solver import DEFAULT_STEPS_PER_CONTACT

SPEED = 20.0
TARGET = 2e-5


def _racket(modes: int, support: str) -> Racket:
    return Racket(
        Beam.uniform(length=0.68, mass=0.34, f1=120.0, n_modes=modes),
        paper_racket().strings,
        support=support,
    )


def _no_static_correction():
    """The solver with the residual flexibility of the modes left out taken as zero."""
    return mock.patch.object(Beam, "residual_flexibility", lambda self, x, shapes=None: 0.0 * x)


def main() -> None:
    """Print the error frontier (modes x steps) beside the defaults."""
    ball, x = paper_ball(), np.linspace(0.0, 0.32, 161)
    for support in ("free", "hand-held"):
        ref = impact(_racket(64, support), ball, x, SPEED, steps_per_contact=4800).e
        print(f"\n{support} racket: max |e - e_ref| over 161 points (time of the sweep)")
        print(f"{'modes':>6} {'steps':>6} {'static correction':>20} {'without':>20}")
        for modes in (4, 6, 8, 12):
            for steps in (150, 300, 600):
                cells = []
                for corrected in (True, False):
                    racket = _racket(modes, support)
                    with contextlib.nullcontext() if corrected else _no_static_correction():
                        impact(racket, ball, x, SPEED, steps_per_contact=steps)
                        t0 = time.perf_counter()
                        e = impact(racket, ball, x, SPEED, steps_per_contact=steps).e
                        seconds = time.perf_counter() - t0
                    cells.append(f"{np.abs(e - ref).max():.1e} ({1e3 * seconds:4.1f} ms)")
                default = (modes, steps) == (DEFAULT_MODES, DEFAULT_STEPS_PER_CONTACT)
                mark = " <- default" if default else ""
                print(f"{modes:>6} {steps:>6} {cells[0]:>20} {cells[1]:>20}{mark}")
    print(f"\ntarget at the default: max |de| <= {TARGET:g}")


if __name__ == "__main__":
    main()
