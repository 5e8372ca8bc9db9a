"""Helpers shared by the physics packages (input checks); no physics lives here."""

from common.version import __version__

__all__ = ["__version__"]
