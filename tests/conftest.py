"""Test configuration: hypothesis without its "explain" phase, which traces every line a
failing example runs and turns a quick failure report into minutes through solve_ivp."""

from hypothesis import Phase, settings

settings.register_profile(
    "racket-impact",
    phases=[Phase.explicit, Phase.reuse, Phase.generate, Phase.target, Phase.shrink],
)
settings.load_profile("racket-impact")
