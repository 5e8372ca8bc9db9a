"""The model against published measurements: one :class:`Comparison` per measured number.

Every comparison runs the model under the measurement's own conditions (ball type and speed,
support, hand, racket, tension) and asks whether its value lies in the measured band.  The
numbers are those of ``data/measurements.md`` (sources and conditions there), each
with its source beside it; where a source states no uncertainty, the band used is **an
assumption** and says so (``band``).

Two kinds, kept apart (:attr:`Comparison.kind`):

* ``"calibration"``: the number was used to set a parameter of the model (the ITF rebound
  bands and the 254 cm drop's contact time and compression set the ball presets,
  :mod:`ball.catalog`; Savage's hand-held frequencies set the grips, :data:`racket.GRIPS`;
  the TWU table sets the RA regression, :mod:`racket.specs.ra`).  Agreement shows the
  calibration holds, not that the model is right.
* ``"validation"``: no parameter of the model was set from it.

:func:`validation_table` runs them all (a few seconds).  Where the model falls outside a
band the table says so; nothing is tuned to move it in (``tests/test_validation.py`` keeps
each disagreement as an expected failure with the measured gap).  A calibration row outside
its band says why (:attr:`Comparison.gap`, which ``validate`` prints), and a band that a guide
states too is the same band there (``tests/test_one_band.py``).
"""

from studies.validation.comparison import COLUMNS, KINDS, Comparison
from studies.validation.conditions import (
    BALL,
    CROSS_BED,
    DROP_1M_SPEED,
    EDGE_INSET,
    GRABINER_SPEED,
    HAMORI,
    HAMORI_BAND,
    HAMORI_RACKETS,
    PIN,
    SEED_BED,
    STROKE_SPEEDS,
    TWU_LEAD,
    TWU_OFFSET,
    TWU_PIVOT_SPEED,
    TWU_SPEED,
)
from studies.validation.measurements import comparisons
from studies.validation.table import GROUPS, groups, summary, validation_table

__all__ = [
    "BALL",
    "COLUMNS",
    "CROSS_BED",
    "DROP_1M_SPEED",
    "EDGE_INSET",
    "GRABINER_SPEED",
    "GROUPS",
    "HAMORI",
    "HAMORI_BAND",
    "HAMORI_RACKETS",
    "KINDS",
    "PIN",
    "SEED_BED",
    "STROKE_SPEEDS",
    "TWU_LEAD",
    "TWU_OFFSET",
    "TWU_PIVOT_SPEED",
    "TWU_SPEED",
    "Comparison",
    "comparisons",
    "groups",
    "summary",
    "validation_table",
]
