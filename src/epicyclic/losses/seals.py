"""Friction of radial lip seals on shafts: the manufacturer's formula quoted in ISO/TR 14179-2.

The friction loss of an elastomer radial shaft seal (DIN 3760 / ISO 6194) in
oil grows with the square of the shaft diameter and with speed (Freudenberg
Simrit catalogue, adopted by ISO/TR 14179-2 for the seal losses P_VD):

.. math:: P = 7.69 \\cdot 10^{-6}\\, d^2 n \\qquad (W;\\ d\\ \\mathrm{in\\ mm},\\ n\\ \\mathrm{in}\\ 1/min)

so the torque T = P/ω = 7.34·10⁻⁵ d² N·m does not depend on speed.
Validity: radial lip seals of NBR or FKM on a shaft of 20 … 250 mm, lubricated
by the sump oil, at sump temperatures of about 60 … 100 °C and surface speeds
up to about 30 m/s; new seals run in; the scatter of seal friction is ±30 %.
Other seal kinds (rotating rectangular rings of a clutch feed) need their own
data: give them as a :class:`ShaftSeal` with a measured ``factor``.

References
----------
ISO/TR 14179-2:2001, *Gears — Thermal capacity — Part 2*, seal losses P_VD (after Simrit);
Freudenberg Simrit: *Technisches Handbuch Radial-Wellendichtringe* (friction loss diagram, 7.69·10⁻⁶ d² n).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..limits import SEAL_DIAMETER_RANGE
from ..results.solution import RPM_TO_RAD_S
from ._checks import positive
from .errors import LossModelError

__all__ = ["ShaftSeal", "SIMRIT_FACTOR"]

#: W per (mm² · 1/min) of the Simrit formula P = 7.69e-6 d² n.
SIMRIT_FACTOR = 7.69e-6


@dataclass(frozen=True)
class ShaftSeal:
    """Radial lip seals on one shaft (against the housing).

    Parameters
    ----------
    shaft : str
        The shaft they run on.
    diameter : float
        Shaft diameter at the seal, mm.
    count : int, default 1
        Number of seals of that diameter on the shaft.
    factor : float, default 7.69e-6
        W per (mm² · 1/min): the Simrit value, or a measured one.

    Examples
    --------
    >>> round(float(ShaftSeal("out", 50.0).loss(3000.0)), 2)  # W (7.69e-6 · 50² · 3000)
    57.67
    """

    shaft: str
    diameter: float
    count: int = 1
    factor: float = SIMRIT_FACTOR

    def __post_init__(self) -> None:
        owner = f"seal on {self.shaft!r}"
        if not isinstance(self.shaft, str) or not self.shaft:
            raise LossModelError(f"shaft seal: shaft must be a shaft name, got {self.shaft!r}.")
        d = positive(self.diameter, "diameter (mm)", owner)
        low, high = SEAL_DIAMETER_RANGE
        if not low <= d <= high:
            raise LossModelError(f"{owner}: diameter must lie in {low:g} ... {high:g} mm (see docs/limits.md), "
                                 f"got {d!r}.")
        if isinstance(self.count, bool) or not isinstance(self.count, int) or not 1 <= self.count <= 100:
            raise LossModelError(f"{owner}: count must be a whole number in 1 ... 100, got {self.count!r}.")
        object.__setattr__(self, "diameter", d)
        object.__setattr__(self, "factor", positive(self.factor, "factor (W per mm^2 per 1/min)", owner,
                                                    allow_zero=True))

    def torque(self) -> float:
        """Friction torque, N·m: count · factor · d² / (2π/60) (independent of speed).

        Returns
        -------
        float

        References
        ----------
        ISO/TR 14179-2:2001, P_VD = 7.69·10⁻⁶ d² n (Simrit).
        """
        return self.count * self.factor * self.diameter ** 2 / RPM_TO_RAD_S

    def loss(self, speed):
        """Power lost, W, at shaft speed ``speed`` (1/min): count · factor · d² |n|.

        Parameters
        ----------
        speed : float or array_like
            1/min.

        Returns
        -------
        ndarray or float
        """
        return self.count * self.factor * self.diameter ** 2 * np.abs(np.asarray(speed, dtype=float))
