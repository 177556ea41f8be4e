"""The picture of an efficiency map: η contours over speed × torque and the share of the drag loss.

Left: filled contours of the efficiency with labelled iso-efficiency lines
(self-locking points hatched grey).  Right: the share of the load-independent
(drag) loss in the total loss, where it dominates (high speed, low torque) and
where the load-dependent mesh and bearing friction do, on a colour scale over
the share's own range (logarithmic when it spans more than a decade,
:func:`share_levels`), so that a drag of 0.1 % still shows where it grows.  Drawn from the map's
arrays only (compute, then draw).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ._common import pyplot

__all__ = ["efficiency_map_figure", "share_levels"]


def share_levels(values: np.ndarray) -> tuple[np.ndarray, str]:
    """Colour levels (in %) that show how a share varies over the map, and the scale's name.

    A share that spans more than a decade (drag 0.004 … 7 % of the loss at low
    torque and high speed) gets logarithmic levels from its least to its
    largest value; a narrower one linear levels over its own range; one that
    hardly varies a band around its value.  (A fixed 0 … 100 % scale paints a
    map whose drag stays below 10 % in one colour.)

    >>> levels, scale = share_levels(np.array([0.01, 0.1, 1.0, 7.0]))
    >>> scale, round(float(levels[0]), 4), round(float(levels[-1]), 4), levels.size
    ('log scale', 0.01, 7.0, 13)
    >>> share_levels(np.array([20.0, 30.0]))[1]
    'linear scale'
    """
    low, high = float(np.min(values)), float(np.max(values))
    if high - low <= 1e-9 * max(high, 1e-12):
        return np.array([low * 0.99, low * 1.01 + 1e-12]), f"{low:.3g} % everywhere"
    if low > 0 and high / low > 10:
        return np.geomspace(low, high, 13), "log scale"
    return np.linspace(low, high, 11), "linear scale"


def efficiency_map_figure(emap: Any, *, figsize: tuple[float, float] = (11.0, 4.6)) -> Any:
    """A matplotlib Figure of :class:`~epicyclic.losses.efficiency_map.EfficiencyMap` ``emap``."""
    plt = pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=figsize, constrained_layout=True)
    (speeds, speed_unit), (torques, torque_unit) = emap.shown("speed"), emap.shown("torque")  # the file's units
    speed_unit, torque_unit = speed_unit.replace("*", "·"), torque_unit.replace("*", "·")
    n, t = np.meshgrid(speeds, torques)
    eta = np.ma.masked_invalid(emap.efficiency)
    fig.suptitle(f"Efficiency map — {emap.title()}", fontsize=11)

    if eta.count() >= 4 and emap.speeds.size > 1 and emap.torques.size > 1:
        low, high = float(eta.min()), float(eta.max())
        if high - low < 1e-6:
            levels = np.linspace(low - 1e-4, high + 1e-4, 3)
        else:  # levels at quantiles of η: the bulk of the map, not only its low-torque corner, gets contours
            levels = np.unique(np.round(np.quantile(eta.compressed(), np.linspace(0.0, 1.0, 13)), 6))
            levels[0], levels[-1] = low - 1e-9, high + 1e-9
        from matplotlib.colors import BoundaryNorm

        # one colour per band (the quantile bands are unequal in η: a linear colour scale would paint the
        # narrow bands of the bulk of the map in nearly one colour)
        cmap = plt.get_cmap("viridis")
        filled = left.contourf(n, t, eta, levels=levels, cmap=cmap, norm=BoundaryNorm(levels, cmap.N))
        lines = left.contour(n, t, eta, levels=levels[2:-1:2], colors="white", linewidths=0.7)
        left.clabel(lines, fmt="%.4f", fontsize=7)
        fig.colorbar(filled, ax=left, label="efficiency η", spacing="uniform", format="%.4f")
    else:
        left.text(0.5, 0.5, "too few points with a defined efficiency", ha="center", va="center",
                  transform=left.transAxes)
    if emap.self_locking.any():
        left.contourf(n, t, emap.self_locking.astype(float), levels=[0.5, 1.5], colors="none", hatches=["xx"])
    left.set_xlabel(f"input speed n_{emap.input} in {speed_unit}")
    left.set_ylabel(f"input torque M_{emap.input} in {torque_unit}" if emap.direction == "drive"
                    else f"output torque / |i| in {torque_unit}")
    left.set_title("efficiency η = P_out / P_in", fontsize=10)

    total = np.where(emap.loss > 0, emap.loss, np.nan)
    spin = [v for k, v in emap.losses.items() if k not in ("mesh", "bearing")]  # drag, clutch drag, pump, ...
    drag = sum(spin) if spin else None
    split = emap.loss_split()
    text = ", ".join(f"{k} {100 * v:.1f} %" for k, v in split.items())
    if drag is not None and np.any(drag > 0) and emap.speeds.size > 1 and emap.torques.size > 1:
        share = np.ma.masked_invalid(100.0 * drag / total)
        levels, scale = share_levels(share.compressed())
        from matplotlib.colors import BoundaryNorm

        cmap = plt.get_cmap("magma_r")
        filled = right.contourf(n, t, share, levels=levels, cmap=cmap, norm=BoundaryNorm(levels, cmap.N))
        bar = fig.colorbar(filled, ax=right, label=f"load-independent share of the loss in % ({scale})", spacing="uniform")
        bar.set_ticks(levels[::2] if levels.size > 7 else levels)
        bar.ax.set_yticklabels([f"{v:.2g}" for v in (levels[::2] if levels.size > 7 else levels)])
        right.set_title(f"load-independent (drag, spin) share of the loss: {float(share.min()):.2g} … "
                        f"{float(share.max()):.2g} %", fontsize=10)
    else:
        filled = right.contourf(n, t, np.ma.masked_invalid(total), levels=12, cmap="magma_r")
        fig.colorbar(filled, ax=right, label="total loss in W")
        right.set_title("total loss (no drag or spin-loss model)", fontsize=10)
    right.set_xlabel(left.get_xlabel())
    right.set_ylabel(left.get_ylabel())
    import textwrap

    summed = textwrap.fill(f"sum over the map: {text}", 72)  # many sources: wrapped, not over the colour bar
    right.set_title(right.get_title() + "\n" + summed, fontsize=10 if "\n" not in summed else 9)
    return fig
