"""What a racket is strung with when its description names no strings (issue 45): one rule
for every entry point (:func:`racket.specs.from_specs`, the catalogue, a TOML spec sheet,
the page), so that the same five numbers give the same racket wherever they are typed.

The rule is the catalogue's: fresh polyester 16L, 16x19, at the sheet's tension
(:data:`STRUNG`, an assumption with its sources in :data:`STRUNG_SOURCES`).  The paper's
linear, lossless, massless spring is asked for by name,
:data:`racket.strings.stringing.LINEAR`.
"""

from racket.strings.stringing import LINEAR

__all__ = ["LINEAR", "STRUNG", "STRUNG_SOURCES"]

STRUNG = dict(string="polyester", gauge="16L", pattern=(16, 19))
"""What a racket is strung with unless its description says otherwise: fresh polyester
16L, 16x19 (an assumption, see :data:`STRUNG_SOURCES`)."""

STRUNG_SOURCES = dict(
    string="an assumption: fresh polyester, the commonest string (TWU string database: 406 "
    "polyesters, 213 nylons, 15 guts; data/measurements.md sec. 5)",
    gauge="an assumption: 16L (1.25 mm), polyester's usual gauge",
    pattern="an assumption: 16x19, the commonest pattern (377 of the 622 rackets of "
    "tests/data/twu_racquets_half.csv)",
)
"""Where each of :data:`STRUNG` comes from."""
