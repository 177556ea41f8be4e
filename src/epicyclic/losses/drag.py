"""Load-independent (drag) losses: a torque against a member's speed.

Churning, splash and windage losses of gears and bearings do not depend on the
transmitted torque but on speed (and oil level, viscosity, temperature).  Here
each drag term is a torque on one member of an element, opposing that member's
speed relative to the housing or to another member (e.g. the planets churning
relative to the carrier):

.. math:: T_d(n) = c_0 + c_1 |n| + c_2 n^2 + \\dots \\quad (N·m, n\\ \\mathrm{in}\\ 1/min)

with coefficients c_i ≥ 0 from measurement or a no-load model (the
load-independent gear losses P_VZ0 of ISO/TR 14179-2 are such a function of
speed).  The loss is T_d |ω| ≥ 0 and grows with speed; the torque acts on the
member's shaft and, opposite, on the housing or the other member's shaft.  This
is the form of Simscape Driveline's viscous losses (c_1) extended by a constant
and a quadratic term.

References
----------
ISO/TR 14179-2:2001 (load-independent losses P_VZ0 as functions of speed);
Höhn, Michaelis, Hinterstoißer, *Optimization of gearbox efficiency*, Goriva i maziva 48 (2009) 441–480
(P_V = P_VZP + P_VZ0 + P_VLP + P_VL0 + ...: load-dependent and no-load losses add up).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..results.solution import RPM_TO_RAD_S
from ._checks import finite_array
from .errors import LossModelError

__all__ = ["DragTorque"]


@dataclass(frozen=True)
class DragTorque:
    """A drag torque on one member of an element, opposing its relative speed.

    Parameters
    ----------
    member : str
        The port it acts on: ``sun``, ``ring``, ``carrier`` (set) or ``first``, ``second`` (stage).
    coefficients : sequence of float
        c_0, c_1, c_2, … ≥ 0: T_d = Σ c_i |n|^i in N·m with n in 1/min.
    relative_to : str, default "housing"
        ``housing`` or another port of the element (the reaction acts there).

    Examples
    --------
    >>> d = DragTorque("carrier", (0.05, 1e-4))
    >>> round(float(d.torque(1000.0)), 6), round(float(d.loss(1000.0)), 4)  # N·m, W
    (0.15, 15.708)
    """

    member: str
    coefficients: Sequence[float]
    relative_to: str = "housing"

    def __post_init__(self) -> None:
        coefficients = tuple(self.coefficients) if isinstance(self.coefficients, (list, tuple)) else None
        if not coefficients:
            raise LossModelError(
                f"DragTorque on {self.member!r}: coefficients must be a list such as [0.05, 1e-4, 0] "
                f"(N*m, N*m per 1/min, ...), got {self.coefficients!r}."
            )
        for k, c in enumerate(coefficients):
            if isinstance(c, bool) or not isinstance(c, (int, float)) or not math.isfinite(c) or c < 0:
                raise LossModelError(
                    f"DragTorque on {self.member!r}: coefficients[{k}] must be a number >= 0 (a drag torque "
                    f"opposes motion and grows with speed), got {c!r}."
                )
        if self.member == self.relative_to:
            raise LossModelError(f"DragTorque: member and relative_to are both {self.member!r}.")
        object.__setattr__(self, "coefficients", tuple(float(c) for c in coefficients))

    def torque(self, speed):
        """Drag torque magnitude (N·m) at relative speed ``speed`` (1/min; floats or arrays)."""
        n = np.abs(finite_array(speed, "speed (1/min)", f"DragTorque on {self.member!r}"))
        total = np.zeros_like(n)
        with np.errstate(over="ignore", invalid="ignore"):
            for power, c in enumerate(self.coefficients):
                if c:
                    total = total + c * n ** power
        if not np.all(np.isfinite(total)):
            worst = float(n[~np.isfinite(total)].ravel()[0])
            raise LossModelError(
                f"DragTorque on {self.member!r}: the polynomial of degree {len(self.coefficients) - 1} overflows "
                f"at {worst:g} 1/min (no finite drag torque); give coefficients of a lower degree."
            )
        return np.where(n > 0, total, 0.0)

    def loss(self, speed):
        """Power lost, W: T_d |ω| ≥ 0."""
        with np.errstate(over="ignore"):
            power = self.torque(speed) * np.abs(np.asarray(speed, dtype=float)) * RPM_TO_RAD_S
        if not np.all(np.isfinite(power)):
            raise LossModelError(f"DragTorque on {self.member!r}: the drag loss overflows (no finite power); "
                                 "give coefficients of a lower degree or smaller values.")
        return power
