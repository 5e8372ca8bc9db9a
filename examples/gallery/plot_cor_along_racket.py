"""
The COR along the racket
========================

e (Eq. 21) and the apparent COR e_A at 201 points of the paper's racket, a tennis ball at
10 m/s: e peaks at the node of the first mode, e_A nearer the throat.
"""

import numpy as np

from racket import impact, paper_racket, tennis_ball
from studies.plots import plot_cor_along_racket
from studies.tables import impact_table

racket = paper_racket()
table = impact_table(impact(racket, tennis_ball(), np.linspace(0.0, 0.32, 201), 10.0))
ax = plot_cor_along_racket(table, racket)
