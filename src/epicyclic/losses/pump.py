"""The oil pump of an automatic transmission: the power it takes from the shaft that drives it.

A positive-displacement pump (gear, crescent, vane) of displacement V turning at
n delivers Q = V n and raises the oil to the line pressure Δp; the torque it
takes from its drive shaft and the power lost to the transmission are

.. math:: T = \\frac{V \\Delta p}{2 \\pi \\eta_{hm}}, \\qquad P = T \\omega = \\frac{V n \\Delta p}{\\eta_{hm}}

with η_hm the pump's hydraulic-mechanical efficiency.  All of that power ends
as heat in the oil (the pressure is throttled back to the sump by the control
valves, the leakage and the clutch cooling), so it is all loss.  The line
pressure may differ by gear (a shift element's pressure level) or be constant.

Validity: a fixed-displacement pump with its pressure held by the line-pressure
valve; the volumetric losses (leakage) raise the delivered pressure's cost but
not this torque; a variable or electric pump is not this model.

References
----------
Naunheimer, H., Bertsche, B., Ryborz, J., Novak, W.: *Automotive Transmissions*, 2nd ed.,
Springer 2011, §9.2 (pump drive power P = Q Δp / η);
Will, D., Gebhardt, N.: *Hydraulik*, 5th ed., Springer 2011, §5.1 (M = V Δp / (2π η_hm)).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from ..results.solution import RPM_TO_RAD_S
from ._checks import fraction, positive
from .errors import LossModelError

__all__ = ["OilPump"]

#: bar → Pa and cm³ → m³.
_BAR, _CM3 = 1e5, 1e-6


@dataclass(frozen=True)
class OilPump:
    """An oil pump driven by a shaft of the train (default: the transmission's input).

    Parameters
    ----------
    displacement : float
        V, cm³ per revolution (automatic transmissions: 10–30).
    pressure : float or mapping gear → float
        Line pressure Δp, bar (one value, or one per gear; gears not named take ``default_pressure``).
    efficiency : float, default 0.85
        η_hm, (0, 1].
    shaft : str or None, default None
        The shaft that drives it; None: the transmission's input.
    default_pressure : float or None, default None
        Δp of gears the mapping does not name, bar (None: every gear must be named).

    Examples
    --------
    >>> pump = OilPump(20.0, 10.0)
    >>> round(float(pump.torque()), 4), round(float(pump.loss(2000.0)), 1)  # N·m, W
    (3.7448, 784.3)
    """

    displacement: float
    pressure: float | Mapping[str, float]
    efficiency: float = 0.85
    shaft: str | None = None
    default_pressure: float | None = None

    def __post_init__(self) -> None:
        owner = "oil pump"
        object.__setattr__(self, "displacement", positive(self.displacement, "displacement (cm^3)", owner))
        if isinstance(self.pressure, Mapping):
            if not self.pressure:
                raise LossModelError(f"{owner}: pressure by gear needs at least one gear, e.g. {{\"1\" = 12.0}}.")
            pressures = {str(g): positive(p, f"pressure[{g!r}] (bar)", owner, allow_zero=True)
                         for g, p in self.pressure.items()}
            object.__setattr__(self, "pressure", MappingProxyType(pressures))
        else:
            object.__setattr__(self, "pressure", positive(self.pressure, "pressure (bar)", owner, allow_zero=True))
        if self.default_pressure is not None:
            object.__setattr__(self, "default_pressure",
                               positive(self.default_pressure, "default_pressure (bar)", owner, allow_zero=True))
        object.__setattr__(self, "efficiency", fraction(self.efficiency, "efficiency (eta_hm)", owner))
        if self.shaft is not None and (not isinstance(self.shaft, str) or not self.shaft):
            raise LossModelError(f"{owner}: shaft must be a shaft name, got {self.shaft!r}.")

    def pressure_in(self, gear: str | None = None) -> float:
        """Line pressure in ``gear``, bar.

        Parameters
        ----------
        gear : str or None
            The gear (needed when the pressure is given per gear).

        Returns
        -------
        float

        Raises
        ------
        LossModelError
            A pressure by gear and a gear it does not name (and no default).
        """
        if not isinstance(self.pressure, Mapping):
            return self.pressure
        if gear is not None and gear in self.pressure:
            return self.pressure[gear]
        if self.default_pressure is not None:
            return self.default_pressure
        raise LossModelError(
            f"oil pump: no line pressure for gear {gear!r}; the pressure is given for gears "
            f"{', '.join(repr(g) for g in self.pressure)}: add this gear or a default_pressure."
        )

    def torque(self, gear: str | None = None) -> float:
        """Drive torque, N·m: V Δp / (2π η_hm) (independent of speed).

        Parameters
        ----------
        gear : str or None
            The gear, for a pressure by gear.

        Returns
        -------
        float

        References
        ----------
        Will & Gebhardt 2011, §5.1.
        """
        return self.displacement * _CM3 * self.pressure_in(gear) * _BAR / (2.0 * np.pi * self.efficiency)

    def loss(self, speed, gear: str | None = None):
        """Power taken, W: T |ω| = V |n| Δp / η_hm.

        Parameters
        ----------
        speed : float or array_like
            Speed of the drive shaft, 1/min.
        gear : str or None
            The gear, for a pressure by gear.

        Returns
        -------
        ndarray or float

        References
        ----------
        Naunheimer et al. 2011, §9.2.
        """
        return self.torque(gear) * np.abs(np.asarray(speed, dtype=float)) * RPM_TO_RAD_S
