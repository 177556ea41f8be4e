"""A stacked bar picture of losses by source: one bar per element or gear, one colour per source."""

from __future__ import annotations

from typing import Any

import numpy as np

from ._common import pyplot

__all__ = ["loss_bar_figure", "SOURCE_COLOURS"]

#: A colour per loss source (load-dependent in blues, spin losses in warm colours).
SOURCE_COLOURS = {"mesh": "#1f4e79", "bearing": "#5b9bd5", "drag": "#9dc3e6", "clutch_drag": "#c00000",
                  "pump": "#ed7d31", "churning": "#ffc000", "windage": "#a9d18e", "seals": "#7f6000"}


def loss_bar_figure(breakdown: Any, *, figsize: tuple[float, float] = (8.0, 4.2)) -> Any:
    """A matplotlib Figure of a :class:`~epicyclic.losses.breakdown.LossBreakdown`: stacked bars in W.

    Parameters
    ----------
    breakdown : LossBreakdown
        Rows (elements or gears) × sources, W.
    figsize : tuple of float, default (8, 4.2)
        Inches.

    Returns
    -------
    matplotlib.figure.Figure
    """
    plt = pyplot()
    fig, ax = plt.subplots(figsize=figsize, constrained_layout=True)
    rows = list(breakdown.rows)
    x = np.arange(len(rows))
    bottom = np.zeros(len(rows))
    for source in breakdown.sources:
        values = np.array([breakdown.rows[r].get(source, 0.0) for r in rows])
        ax.bar(x, values, bottom=bottom, label=source.replace("_", " "), color=SOURCE_COLOURS.get(source),
               edgecolor="white", linewidth=0.5)
        bottom += values
    for k, total in enumerate(bottom):
        share = ""
        if breakdown.input_power and breakdown.input_power.get(rows[k]):
            share = f"\n{100 * total / breakdown.input_power[rows[k]]:.1f} %"
        ax.annotate(f"{total:.0f} W{share}", (x[k], total), ha="center", va="bottom", fontsize=8,
                    xytext=(0, 2), textcoords="offset points")
    ax.set_xticks(x, rows, rotation=30 if len(rows) > 6 else 0, ha="right" if len(rows) > 6 else "center")
    ax.set_ylabel("loss in W")
    ax.set_ylim(0, max(float(bottom.max(initial=0.0)) * 1.18, 1e-9))
    oil = f", oil at {breakdown.oil_temperature:.0f} °C" if breakdown.oil_temperature is not None else ""
    ax.set_title(f"Losses by source — {breakdown.title}{oil}", fontsize=10)
    if breakdown.sources:
        ax.legend(fontsize=8, ncols=min(4, len(breakdown.sources)), loc="upper left", frameon=False)
    ax.grid(axis="y", alpha=0.3)
    ax.set_axisbelow(True)
    return fig
