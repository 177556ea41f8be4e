"""The test-bench picture of a simulated shift: speeds, torques, pressures and slip power on shared time axes.

Four panels over the same time axis, as a transmission test bench records a shift: the shaft
speeds (input and output bold, the others thin), the input and output torques with the torque of
every element that carries any, the pressure of every wet element, and the slip power of every
element that slips.  The torque and inertia phases are shaded in every panel and named in the top
one; a shift that did not complete says so in the title.

References
----------
Naunheimer, H., Bertsche, B., Ryborz, J., Novak, W.: *Automotive Transmissions*, 2nd ed., Springer
2011, §10.3 (the measured traces of a power shift: speeds, output torque, pressures; torque and
inertia phase).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ._common import pyplot

__all__ = ["shift_bench_figure"]

_PHASE_COLOURS = {"torque phase": "#f2c14e", "inertia phase": "#7fb8d8", "slip phase": "#7fb8d8"}


def shift_bench_figure(result: Any, *, figsize: tuple[float, float] = (9.0, 9.0), input_shaft: str | None = None,
                       output_shaft: str | None = None) -> Any:
    """A matplotlib Figure of :class:`~epicyclic.dynamics.results.ShiftResult` ``result``.

    Parameters
    ----------
    result : ShiftResult
    figsize : (float, float), default (9, 9)
        inches.
    input_shaft, output_shaft : str, optional
        Drawn bold (default: the first and last shafts of the traces that the result names).

    Returns
    -------
    matplotlib.figure.Figure
    """
    plt = pyplot()
    tr = result.traces
    t = tr.time
    fig, axes = plt.subplots(4, 1, sharex=True, figsize=figsize, constrained_layout=True)
    speeds, torques, pressures, powers = axes
    cycle = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    colour = {name: cycle[(k + 2) % len(cycle)] for k, name in enumerate(tr.elements)}  # the same in every panel
    bold = {input_shaft or result.__dict__.get("input_shaft", ""), output_shaft or ""}
    for shaft, values in tr.speeds.items():
        wide = shaft in bold or shaft in ("in", "out")
        speeds.plot(t, values, lw=2.0 if wide else 0.8, label=shaft, alpha=1.0 if wide else 0.7)
    speeds.set_ylabel("speed [1/min]")
    speeds.legend(ncol=4, fontsize=7, loc="best")
    torques.plot(t, tr.input_torque, lw=2.0, color="black", label="input")
    torques.plot(t, tr.output_torque, lw=2.0, color="0.45", label="output")
    for name, e in tr.elements.items():
        if np.any(np.abs(e.torque) > 1e-9):
            torques.plot(t, e.torque, lw=1.0, label=name, color=colour[name])
    torques.set_ylabel("torque [N·m]")
    torques.legend(ncol=4, fontsize=7, loc="best")
    for name, e in tr.elements.items():
        if np.any(e.pressure > 0):
            pressures.plot(t, e.pressure / 1e5, lw=1.2, label=name, color=colour[name])
    pressures.set_ylabel("pressure [bar]")
    pressures.legend(ncol=5, fontsize=7, loc="best")
    for name, e in tr.elements.items():
        if np.any(e.power > 1e-6):
            powers.plot(t, e.power / 1e3, lw=1.2, label=name, color=colour[name])
    powers.set_ylabel("slip power [kW]")
    powers.set_xlabel("time [s]")
    if powers.get_legend_handles_labels()[0]:
        powers.legend(ncol=5, fontsize=7, loc="best")
    for ax in axes:
        ax.grid(True, lw=0.3, alpha=0.6)
        for phase, (start, end) in result.phases.items():
            ax.axvspan(start, end, color=_PHASE_COLOURS.get(phase, "#dddddd"), alpha=0.25, lw=0)
    top = speeds.get_ylim()[1]
    for phase, (start, end) in result.phases.items():
        speeds.text(0.5 * (start + end), top, phase, ha="center", va="bottom", fontsize=8)
    what = f"shift {result.from_gear} → {result.to_gear}" if result.kind == "shift" else \
        f"launch in {result.to_gear}"
    state = "" if result.completed else " — NOT COMPLETED"
    fig.suptitle(f"{what}{state}", fontsize=11)
    return fig
