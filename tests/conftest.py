"""Test configuration for hypothesis.

* No "explain" phase: it traces every line a failing example runs, which through solve_ivp
  turns a quick failure report into many minutes.
* On CI (``CI`` set) the examples are derandomized, so every CI run checks the same cases
  and a failure is reproducible; local runs draw new examples each time.
"""

import os

from hypothesis import Phase, settings

settings.register_profile(
    "racket-impact",
    phases=[Phase.explicit, Phase.reuse, Phase.generate, Phase.target, Phase.shrink],
    derandomize=bool(os.environ.get("CI")),
)
settings.load_profile("racket-impact")
