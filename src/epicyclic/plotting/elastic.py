"""Pictures of the elastic set: the Campbell diagram and the load of every planet over a carrier revolution.

* Campbell diagram: natural frequencies (one line per mode, coloured by its type at rest) against
  the input speed, the mesh harmonics and shaft orders as straight lines, the crossings in the
  operating range marked (filled where the mesh phasing lets the harmonic excite the mode,
  open where it cancels).
* Planet loads: the mesh force of every planet over the carrier angle with K_γ on a second axis.
* Face load: the load per unit face width w(y) of one or more meshes, the mean dashed.

References
----------
Cooley & Parker 2012 (Campbell diagrams of planetary gears); Parker & Lin 2004 (phasing);
Kahraman 1994 (planet loads over a carrier revolution).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ._common import pyplot, save_figure

__all__ = ["campbell_figure", "planet_loads_figure", "face_load_figure", "save_campbell", "save_planet_loads",
           "save_face_load"]

_KIND_COLOURS = {"rigid-body": "#999999", "rotational": "#1f77b4", "translational": "#d62728", "planet": "#2ca02c",
                 "mixed": "#9467bd"}


def campbell_figure(diagram: Any, *, title: str = "Campbell diagram", figsize=(8.0, 5.5)) -> Any:
    """A matplotlib Figure of :class:`~epicyclic.elastic.campbell.CampbellDiagram` ``diagram``."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=figsize)
    speeds = diagram.speeds
    # up to the highest excitation line (with room): the natural frequencies above cannot be crossed
    top = float(diagram.natural.max()) * 1.05
    if diagram.lines.size:
        top = min(top, max(1.25 * float(diagram.lines.max()), 1.0))
    shown = set()
    for j, kind in enumerate(diagram.kinds):
        if kind == "rigid-body":
            continue
        label = None if kind in shown else f"{kind} modes"
        shown.add(kind)
        ax.plot(speeds, diagram.natural[:, j], color=_KIND_COLOURS[kind], lw=1.2, label=label)
    for i, order in enumerate(diagram.orders):
        mesh = "mesh" in order
        ax.plot(speeds, diagram.lines[:, i], color="black" if mesh else "#777777", lw=0.9, ls="-" if mesh else ":")
        k = len(speeds) - 1
        if diagram.lines[k, i] > top:  # label where the line leaves the plot
            k = max(int((diagram.lines[:, i] <= top).sum()) - 1, 0)
        ax.annotate(order, (speeds[k], diagram.lines[k, i]), fontsize=8, ha="right",
                    va="bottom" if mesh else "top", color="black" if mesh else "#555555",
                    xytext=(0, 0 if mesh else -4 * (i % 3)), textcoords="offset points")
    for c in diagram.crossings:
        filled = c.excited is not False
        ax.plot(c.speed, c.frequency, "o", ms=5, mfc="black" if filled else "white", mec="black")
    if diagram.operating:
        ax.axvspan(*diagram.operating, color="#ffe9a8", alpha=0.5, lw=0, label="operating range")
    ax.set_xlim(speeds[0], speeds[-1])
    ax.set_ylim(0, top)
    ax.set_xlabel("input (sun) speed, 1/min")
    ax.set_ylabel("frequency, Hz")
    ax.set_title(title + ("" if diagram.gyroscopic else " (at rest)"))
    ax.plot([], [], "o", mfc="black", mec="black", label="crossing, excited")
    ax.plot([], [], "o", mfc="white", mec="black", label="crossing, cancelled by phasing")
    ax.legend(fontsize=8, loc="upper left")
    ax.grid(alpha=0.3)
    return fig


def planet_loads_figure(study: Any, *, title: str = "Load per planet", figsize=(8.0, 4.5)) -> Any:
    """A matplotlib Figure of a :class:`~epicyclic.elastic.sharing_results.SharingStudy` over carrier angle."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=figsize)
    for n in range(study.sun_mesh.shape[1]):
        ax.plot(study.values, study.sun_mesh[:, n], lw=1.4, label=f"planet {n + 1}")
    mean = study.total / study.sun_mesh.shape[1]
    ax.plot(study.values, mean, color="black", ls="--", lw=0.9, label="equal share")
    ax.set_xlabel(f"{study.parameter}, {study.unit}")
    ax.set_ylabel("mesh force, N")
    right = ax.twinx()
    right.plot(study.values, study.k_gamma, color="#555555", lw=0.8, ls=":")
    right.set_ylabel("K_gamma (dotted)")
    ax.set_title(title)
    ax.legend(fontsize=8, ncol=6, loc="upper center", bbox_to_anchor=(0.5, -0.14), frameon=False)
    ax.grid(alpha=0.3)
    return fig


def face_load_figure(loads: dict, *, title: str = "Load along the face width", figsize=(8.0, 4.0)) -> Any:
    """A matplotlib Figure of :class:`~epicyclic.elastic.face_load.FaceLoad` results by name (mesh → FaceLoad)."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=figsize)
    for name, load in loads.items():
        line, = ax.step(load.positions, load.line_load, where="mid", lw=1.4,
                        label=f"{name}: K_Hbeta {load.k_hbeta:.3f}")
        ax.axhline(load.force / load.face_width, color=line.get_color(), ls="--", lw=0.8)
    ax.set_xlabel("position along the face width (from the torque input end), mm")
    ax.set_ylabel("load per unit face width w, N/mm")
    ax.set_ylim(bottom=0)
    ax.set_title(title)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return fig


def save_face_load(loads: dict, path: str | Path, **kwargs: Any) -> Path:
    """Draw :func:`face_load_figure` to ``path`` (.svg, .png, .pdf)."""
    return save_figure(face_load_figure(loads, **kwargs), path)


def save_campbell(diagram: Any, path: str | Path, **kwargs: Any) -> Path:
    """Draw :func:`campbell_figure` to ``path`` (.svg, .png, .pdf)."""
    return save_figure(campbell_figure(diagram, **kwargs), path)


def save_planet_loads(study: Any, path: str | Path, **kwargs: Any) -> Path:
    """Draw :func:`planet_loads_figure` to ``path`` (.svg, .png, .pdf)."""
    return save_figure(planet_loads_figure(study, **kwargs), path)
