"""The Axes a plot draws on: the ones given, or a new figure's."""

from __future__ import annotations

import numpy as np


def _axes(ax, count: int):
    """``count`` Axes: the ones given, or a new figure's."""
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(count, 1, sharex=True, figsize=(6.4, 2.2 + 1.8 * count), squeeze=False)
        return ax[:, 0] if count > 1 else ax[0, 0]
    if count > 1 and len(np.atleast_1d(ax)) != count:
        raise ValueError(f"ax must be {count} Axes, got {ax!r}")
    return ax
