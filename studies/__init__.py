"""Studies on top of the physics: sweeps, serve what-ifs, the paper reproduced, plots, CLI."""

from common.version import __version__

__all__ = ["__version__"]
