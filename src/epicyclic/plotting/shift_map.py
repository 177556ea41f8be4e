"""The picture of a shift map: best-gear regions over output speed × torque, the envelope, a schedule.

Left, in the style of a shift map (Schaltkennfeld): the region where each gear
has the least loss, filled in its own colour and labelled with the gear at its
centre; points no gear can carry hatched grey; the efficiency envelope as
labelled contour lines; a given schedule's upshift lines drawn over it (black,
labelled ``1-2``, ``2-3``, …).  Right, with a schedule: the loss the best gear
saves against the schedule's gear, in W.  Drawn from the map's arrays only.

References
----------
Naunheimer et al., *Automotive Transmissions* (2011), §7.4 (shift maps).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ._common import pyplot

__all__ = ["shift_map_figure"]


def _envelope_levels(values: np.ndarray) -> np.ndarray:
    """Up to 8 contour levels of η at quantiles of the envelope (where its points are)."""
    values = values[np.isfinite(values)]
    if values.size < 4 or float(values.max() - values.min()) < 1e-6:
        return np.array([])
    levels = np.unique(np.round(np.quantile(values, np.linspace(0.05, 0.95, 8)), 4))
    return levels[(levels > values.min()) & (levels < values.max())]


def shift_map_figure(smap: Any, *, figsize: tuple[float, float] = (10.0, 6.0)) -> Any:
    """A matplotlib Figure of :class:`~epicyclic.transmission.shift_map.ShiftMap` ``smap``."""
    plt = pyplot()
    from matplotlib.colors import BoundaryNorm, ListedColormap

    panels = 2 if smap.schedule is not None else 1
    fig, axes = plt.subplots(1, panels, figsize=(figsize[0] * (1.0 if panels == 1 else 1.6), figsize[1]),
                             constrained_layout=True, squeeze=False)
    left = axes[0][0]
    n, t = np.meshgrid(smap.output_speeds, smap.output_torques)
    gears = smap.gears
    # the light tones of tab20 without its grey (kept for "no gear"): labels stay legible
    palette = plt.get_cmap("tab20").colors[1::2]
    palette = [c for k, c in enumerate(palette) if k != 7]
    colours = ListedColormap([palette[k % len(palette)] for k in range(len(gears))])
    best = np.ma.masked_less(smap.best, 0)
    if smap.output_speeds.size > 1 and smap.output_torques.size > 1:
        left.pcolormesh(n, t, best, cmap=colours, norm=BoundaryNorm(np.arange(len(gears) + 1) - 0.5, colours.N),
                        shading="nearest")
        none = smap.best < 0
        if none.any():
            left.contourf(n, t, none.astype(float), levels=[0.5, 1.5], colors=["0.85"], hatches=["xx"])
        for k, gear in enumerate(gears):
            rows, cols = np.nonzero(smap.best == k)
            if rows.size:  # the label at the region's median point (inside it for a convex region)
                j = int(np.argsort(cols)[cols.size // 2])
                i = int(np.argsort(rows)[rows.size // 2])
                x, y = smap.output_speeds[cols[j]], smap.output_torques[rows[i]]
                if smap.best[rows[i], cols[j]] != k:  # not inside: the region's own point nearest its middle
                    m = int(np.argmin((cols - cols[j]) ** 2 + (rows - rows[i]) ** 2))
                    x, y = smap.output_speeds[cols[m]], smap.output_torques[rows[m]]
                left.text(x, y, gear, ha="center", va="center", fontsize=13, fontweight="bold", color="0.15")
        levels = _envelope_levels(smap.envelope)
        if levels.size:
            lines = left.contour(n, t, np.ma.masked_invalid(smap.envelope), levels=levels, colors="0.25",
                                 linewidths=0.7, linestyles="--")
            left.clabel(lines, fmt="%.4f", fontsize=7)
    else:
        left.text(0.5, 0.5, "a map needs two speeds and two torques or more", ha="center", va="center",
                  transform=left.transAxes)
    if smap.schedule is not None:
        s = smap.schedule
        for k, line in enumerate(s.upshift_speeds):
            torques = s.torques if s.torques.size > 1 else np.array([smap.output_torques[0], smap.output_torques[-1]])
            speeds = line if line.size > 1 else np.repeat(line, 2)
            left.plot(speeds, torques, color="black", linewidth=1.6)
            inside = (speeds >= smap.output_speeds[0]) & (speeds <= smap.output_speeds[-1])
            at = int(np.flatnonzero(inside)[len(np.flatnonzero(inside)) // 2]) if inside.any() else 0
            left.annotate(s.label(k, s.gears), (speeds[at], torques[at]), xytext=(3, 3), textcoords="offset points",
                          fontsize=8, color="black", backgroundcolor=(1, 1, 1, 0.7))
    left.set_xlim(smap.output_speeds[0], smap.output_speeds[-1])
    left.set_ylim(smap.output_torques[0], smap.output_torques[-1])
    left.set_xlabel("output speed in 1/min")
    left.set_ylabel("output torque in N·m")
    left.set_title("best gear (least loss); dashed: efficiency envelope"
                   + ("; black: the schedule's upshift lines" if smap.schedule is not None else "")
                   + "\n" + smap.limits.describe() + "; hatched: no gear carries the point", fontsize=9)
    if panels == 2:
        right = axes[0][1]
        saved = np.ma.masked_invalid(smap.saved)
        if saved.count() >= 4 and float(saved.max()) > 0:
            filled = right.pcolormesh(n, t, saved, cmap="Greens", shading="nearest", vmin=0.0)
            fig.colorbar(filled, ax=right, label="loss saved by the best gear in W")
        else:
            right.text(0.5, 0.5, "the schedule's gear is the best gear wherever both carry the point",
                       ha="center", va="center", transform=right.transAxes, fontsize=9)
        right.set_xlim(left.get_xlim())
        right.set_ylim(left.get_ylim())
        right.set_xlabel(left.get_xlabel())
        right.set_ylabel(left.get_ylabel())
        summary = smap.summary()
        share = summary.get("saved_share")
        right.set_title(f"loss saved against {smap.schedule.name}"
                        + (f": {100 * share:.2f} % of its loss over the map" if share is not None else ""), fontsize=9)
    fig.suptitle(smap.title(), fontsize=11)
    return fig
