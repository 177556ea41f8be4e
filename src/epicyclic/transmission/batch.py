"""All gears × many operating points at once (engine: :func:`epicyclic.solver.batch.solve_batch`).

Per gear the equations depend only on the shift state and the loss-direction
pattern, so each gear is one batch solve over numpy arrays of input speeds and
torques.  Drive puts power in at the input; coast drives the
output with the torque ``input_torque · |i|`` (engine braking).

References
----------
Brandenberger 1952, eqs. 7–10.
"""

from __future__ import annotations

import html
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

import numpy as np

from ..errors import ModelError
from ..solver.batch import BatchSolution, solve_batch
from ..units import to_core_array
from .transmission import Transmission

__all__ = ["TransmissionBatch", "solve_gears"]


@dataclass(frozen=True, eq=False)
class TransmissionBatch:
    """Batch solutions of several gears at the same operating points.

    Attributes
    ----------
    name : str
    direction : str
        "drive" or "coast".
    ratios : mapping gear → float
    solutions : mapping gear → BatchSolution
    """

    name: str
    direction: str
    ratios: Mapping[str, float]
    solutions: Mapping[str, BatchSolution]

    def efficiency(self, gear: str) -> np.ndarray:
        """Efficiency array of ``gear`` (NaN where self-locking or no power)."""
        return self.solutions[gear].efficiency

    @property
    def points(self) -> int:
        return int(next(iter(self.solutions.values())).efficiency.size) if self.solutions else 0

    def summary(self) -> dict[str, dict[str, float]]:
        """min / mean / max efficiency and self-locking share per gear."""
        out = {}
        for gear, sol in self.solutions.items():
            eff = sol.efficiency
            ok = ~np.isnan(eff)
            out[gear] = {
                "ratio": self.ratios[gear],
                "efficiency_min": float(np.min(eff[ok])) if ok.any() else float("nan"),
                "efficiency_mean": float(np.mean(eff[ok])) if ok.any() else float("nan"),
                "efficiency_max": float(np.max(eff[ok])) if ok.any() else float("nan"),
                "self_locking_share": float(np.mean(sol.self_locking)),
            }
        return out

    HEADER = ("gear", "ratio", "η min", "η mean", "η max", "self-locking")

    def _rows(self) -> list[list[str]]:
        return [[g, f"{s['ratio']:.4f}", f"{s['efficiency_min']:.4f}", f"{s['efficiency_mean']:.4f}",
                 f"{s['efficiency_max']:.4f}", f"{100 * s['self_locking_share']:.1f} %"]
                for g, s in self.summary().items()]

    def table(self) -> str:
        rows = [list(self.HEADER)] + self._rows()
        widths = [max(len(r[k]) for r in rows) for k in range(len(self.HEADER))]
        lines = [f"{self.name}: {self.direction}, {self.points} operating points per gear"]
        for k, r in enumerate(rows):
            lines.append("  ".join(c.rjust(w) for c, w in zip(r, widths)))
            if k == 0:
                lines.append("  ".join("-" * w for w in widths))
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        head = "".join(f"<th>{html.escape(h)}</th>" for h in self.HEADER)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in self._rows())
        return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"

    def to_dict(self) -> dict[str, Any]:
        return {"name": self.name, "direction": self.direction, "points": self.points, "gears": self.summary()}

    def __str__(self) -> str:
        return self.table()

    def __repr__(self) -> str:
        return f"<TransmissionBatch {self.name!r}: {self.direction}, {len(self.solutions)} gears × {self.points} points>"


def solve_gears(
    transmission: Transmission,
    *,
    input_speed: object,
    input_torque: object,
    gears: Iterable[str] | None = None,
    direction: str = "drive",
) -> TransmissionBatch:
    """Solve every gear (or ``gears``) at arrays of input speeds (1/min) and torques (N·m).

    Parameters
    ----------
    transmission : Transmission
    input_speed, input_torque : array_like
        Broadcast to one shape; torques are magnitudes (> 0).  Values may carry units
        (``"2000 U/min"``, ``"15 kp*m"``) or be one pint quantity holding an array.
    gears : iterable of str, optional
        Default: all gears.
    direction : {"drive", "coast"}

    Returns
    -------
    TransmissionBatch

    Examples
    --------
    >>> from epicyclic.transmission.library import build
    >>> res = solve_gears(build("zf_8hp70", 0.98), input_speed=[1000.0, 3000.0], input_torque=[50.0, 300.0])
    >>> res.efficiency("1").round(4).tolist()
    [0.9843, 0.9843]
    """
    if direction not in ("drive", "coast"):
        raise ModelError(f"solve_gears: direction must be 'drive' or 'coast', got {direction!r}.")
    n = to_core_array(input_speed, "speed", field="solve_gears: input_speed")
    torque = np.abs(to_core_array(input_torque, "torque", field="solve_gears: input_torque"))
    chosen = list(transmission.gears if gears is None else gears)
    t = transmission
    solutions = {}
    ratios = {}
    batch = solve_batch
    spin = getattr(t, "spin", None)
    for gear in chosen:
        if getattr(t, "losses", None) or spin is not None:  # a file's loss models: every gear solved with them
            from functools import partial

            from ..losses import solve_batch_with_losses

            batch = partial(solve_batch_with_losses, losses=t.losses, spin=spin, gear=gear, input=t.input)
        train = t.gear_train(gear)
        ratio = t.ratio(gear)
        ratios[gear] = ratio
        if direction == "drive":
            solutions[gear] = batch(train, speeds={t.input: n}, torques={t.input: torque},
                                          drives=[t.input], loads=[t.output])
        else:
            solutions[gear] = batch(train, speeds={t.input: n}, torques={t.output: torque * abs(ratio)},
                                          drives=[t.output], loads=[t.input])
    return TransmissionBatch(t.name, direction, MappingProxyType(ratios), MappingProxyType(solutions))
