"""
The serve what-if
=================

How much slower would serves be with a zero-COR ball (paper Sec. VIII), against string and
ball stiffness.
"""

from racket import paper_racket, tennis_ball
from studies.plots import plot_serve_what_if
from studies.serve import serve_what_if

table = serve_what_if(paper_racket(), tennis_ball(), racket_speed=30.0)
ax = plot_serve_what_if(table)
