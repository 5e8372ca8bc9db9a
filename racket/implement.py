"""What the impact solver strikes: an :class:`Implement`, a racket (:class:`racket.Racket`)
or a bat (:class:`bat.Bat`).  The solver (:mod:`racket.solver`) knows this face and nothing
of either kind, so a new implement is one more class derived from it, and the solver never
imports the packages that build on it (``tests/test_structure.py``).
"""

from __future__ import annotations


class Implement:
    """Base of what :func:`racket.impact` strikes: a free-free beam, how it is held, and
    what lies between it and the ball.

    A derived class (a frozen dataclass) gives the solver:

    * ``beam``: the beam (:class:`beam.Beam` or :class:`beam.ThickBeam`), tip at x = 0;
    * ``support``: how it is held (``"free"``, ``"hand-held"``, or a kind of its own);
    * ``contact``: what lies in series with the ball (a string bed, or a bat's bare
      surface), with its ``stiffness`` [N/m], ``stiffest`` [N/m], ``stretch`` [1/m^2],
      ``loss`` [-], ``moving_mass`` [kg] and ``plain`` (linear, lossless and massless);
    * ``system``: its block system for its support (:class:`racket.system.BlockSystem`);
    * ``point_dynamics(x, y)`` and ``effective_mass(x, y)`` [kg] at the impact points;
    * ``check_points(position, offset)``: the impact points [m from the tip], checked;
    * ``check_swing(pivot)``: refuses a swing its support cannot make.
    """

    __slots__ = ()
