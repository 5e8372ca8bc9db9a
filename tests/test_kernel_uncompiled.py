"""The compiled kernel against the same Python code run uncompiled (NUMBA_DISABLE_JIT=1).

Compilation must change nothing but the speed: a hand-held racket (coupled modes in real
blocks), a linear and a power-law ball, near the tip and at the centre.  Both sides run BLAS on
one thread; a racket's modes cached earlier in the process on several BLAS threads may still
differ in their last bits (e by up to 1e-9, :func:`racket.solver.one_blas_thread`), which the
tolerance allows: a difference of compilation would be far larger.
"""

import numpy as np
from helpers import run_uncompiled

from ball import Ball, PowerLawHysteresis
from racket import impact, paper_ball, paper_racket
from racket.solver import one_blas_thread

SCRIPT = """
import json
from ball import Ball, PowerLawHysteresis
from racket import impact, paper_racket, paper_ball
from racket.solver import one_blas_thread
out = {}
power = Ball(0.057, PowerLawHysteresis(2e6, 1.5, 3.0))
for name, ball in (("linear", paper_ball()), ("power", power)):
    with one_blas_thread():
        r = impact(paper_racket("hand-held"), ball, [0.02, 0.16], 10.0)
    out[name] = [*r.e.tolist(), *r.vibration_energy.tolist(), *r.contact_time.tolist()]
print(json.dumps(out))
"""


def test_compiled_kernel_matches_the_uncompiled_code():
    uncompiled = run_uncompiled(SCRIPT)
    for name, ball in (
        ("linear", paper_ball()),
        ("power", Ball(0.057, PowerLawHysteresis(2e6, 1.5, 3.0))),
    ):
        with one_blas_thread():
            r = impact(paper_racket("hand-held"), ball, [0.02, 0.16], 10.0)
        compiled = [*r.e, *r.vibration_energy, *r.contact_time]
        assert np.allclose(compiled, uncompiled[name], rtol=1e-8, atol=0.0)
