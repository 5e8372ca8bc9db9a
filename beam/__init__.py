"""Free-free Euler-Bernoulli beams by modal superposition (paper Sec. VII).

Public API: :class:`Beam` (profile, mass properties, effective mass of Eq. 20, modes),
:class:`Modes` (rigid-body plus bending modes, mass-normalised).
"""

from beam.beam import DEFAULT_DAMPING, DEFAULT_MODES, SWINGWEIGHT_AXIS, Beam
from beam.modes import Modes
from common.version import __version__

__all__ = [
    "DEFAULT_DAMPING",
    "DEFAULT_MODES",
    "SWINGWEIGHT_AXIS",
    "Beam",
    "Modes",
    "__version__",
]
