"""Free-free Euler-Bernoulli and Timoshenko beams by modal superposition (paper Sec. VII).

Public API: :class:`Beam` (profile, mass properties, effective mass of Eq. 20, modes),
:class:`ThickBeam` (the same with shear and rotary inertia, a bat's), :class:`Modes`
(rigid-body plus bending modes, mass-normalised).  Each loads on first use
(:mod:`common.lazy`).
"""

from typing import TYPE_CHECKING

from common.lazy import lazy_names
from common.version import __version__

if TYPE_CHECKING:  # the public names, loaded on first use (common.lazy): by module below
    from beam.beam import DEFAULT_DAMPING, DEFAULT_MODES, SWINGWEIGHT_AXIS, Beam
    from beam.modes import Modes
    from beam.thick import ThickBeam

__all__ = [
    "DEFAULT_DAMPING",
    "DEFAULT_MODES",
    "SWINGWEIGHT_AXIS",
    "Beam",
    "Modes",
    "ThickBeam",
    "__version__",
]

__getattr__, __dir__ = lazy_names(
    __name__,
    {
        "beam.beam": ("DEFAULT_DAMPING", "DEFAULT_MODES", "SWINGWEIGHT_AXIS", "Beam"),
        "beam.modes": ("Modes",),
        "beam.thick": ("ThickBeam",),
    },
)
