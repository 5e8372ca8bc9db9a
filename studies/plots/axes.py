"""The Axes a plot draws on: the ones given, or a new figure's (laid out by matplotlib's
constrained layout, so that labels, legends, colour bars and headings fit in it).
"""

from __future__ import annotations

import numpy as np


def _axes(ax, count: int, figsize=None, sharex: bool = True):
    """``count`` Axes: the ones given, or a new figure's (``figsize`` [in], default 6.4 wide
    and 2.2 + 1.8 per panel high), stacked and sharing x unless ``sharex`` is False.
    """
    if ax is None:
        import matplotlib.pyplot as plt

        figsize = (6.4, 2.2 + 1.8 * count) if figsize is None else figsize
        _, ax = plt.subplots(
            count, 1, sharex=sharex, figsize=figsize, squeeze=False, layout="constrained"
        )
        return ax[:, 0] if count > 1 else ax[0, 0]
    if count > 1 and len(np.atleast_1d(ax)) != count:
        raise ValueError(f"ax must be {count} Axes, got {ax!r}")
    return ax
