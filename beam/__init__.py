"""Free-free Euler-Bernoulli and Timoshenko beams by modal superposition (paper Sec. VII).

Public API: :class:`Beam` (profile, mass properties, effective mass of Eq. 20, modes),
:class:`ThickBeam` (the same with shear and rotary inertia, a bat's), :class:`Modes`
(rigid-body plus bending modes, mass-normalised).
"""

from beam.beam import DEFAULT_DAMPING, DEFAULT_MODES, SWINGWEIGHT_AXIS, Beam
from beam.modes import Modes
from beam.thick import ThickBeam
from common.version import __version__

__all__ = [
    "DEFAULT_DAMPING",
    "DEFAULT_MODES",
    "SWINGWEIGHT_AXIS",
    "Beam",
    "Modes",
    "ThickBeam",
    "__version__",
]
