"""
The model against measurements, by group
========================================

Every published measurement the model can predict (``racket-impact validate``), one panel per
group: each measured band mapped to [-1, 1], the model filled where it validates and open where
the number calibrated it, green inside the band and red outside.
"""

import matplotlib.pyplot as plt

from studies.plots import plot_validation
from studies.validation import groups, validation_table

table = validation_table()
panels = list(groups(table))
sizes = [len(rows) + 2 for _, rows in panels]
fig, axes = plt.subplots(len(panels), 1, figsize=(7.0, 0.25 * sum(sizes)),
                         gridspec_kw={"height_ratios": sizes})  # fmt: skip
legend = {}
for ax, (group, rows) in zip(axes, panels, strict=True):
    plot_validation(rows, ax=ax)
    ax.set_title(group, fontsize="small")
    legend.update(zip(*reversed(ax.get_legend_handles_labels()), strict=True))
    ax.get_legend().remove()
axes[0].legend(legend.values(), legend.keys(), fontsize="x-small", loc="upper right")
fig.tight_layout()
