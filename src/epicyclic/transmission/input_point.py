"""The input speed and torque every gear of a transmission is analysed at, and where they came from.

The mesh friction, bearing and drag models make a gear's efficiency depend on
the operating point, so ``epicyclic gears`` (and the page's gear table) analyse
every gear at one stated input point:

1. ``--speed`` / ``--torque`` (with units) where given;
2. else the file's ``[operating_point]``: the speed of the transmission's input
   shaft, and its torque (or its power, T = P/ω);
3. else :data:`DEFAULT_INPUT_SPEED` and :data:`DEFAULT_INPUT_TORQUE`.

Whatever is used is stated in every output (:meth:`InputPoint.describe`).
Without loss models the point does not change any ratio or efficiency
(Brandenberger 1952, eq. 7: the loss follows the rolling power, a multiple of
the input power).

References
----------
Brandenberger 1952, eq. 7; ISO/TR 14179-2:2001 (load- and speed-dependent mesh losses).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..errors import ModelError
from ..results.solution import RPM_TO_RAD_S
from ..units import Units, to_core
from .default_point import DEFAULT_INPUT_SPEED, DEFAULT_INPUT_TORQUE  # one default point (docs: default_point)

__all__ = ["InputPoint", "input_point", "DEFAULT_INPUT_SPEED", "DEFAULT_INPUT_TORQUE"]



@dataclass(frozen=True)
class InputPoint:
    """Input speed and torque of a gear analysis, and where each came from.

    Parameters
    ----------
    speed : float
        Input speed, 1/min (finite, not 0).
    torque : float
        Input torque in drive, N·m (> 0; in coast the output is driven with torque × |ratio|).
    speed_source, torque_source : str
        Where each came from: ``"--speed"``, ``"[operating_point]"``, ``"default"``, ``"given"``.
    units : Units, optional
        Units :meth:`describe` shows them in (default 1/min and N·m).

    Examples
    --------
    >>> InputPoint(2000.0, 200.0, "[operating_point]", "[operating_point]").describe()
    'input 2000 1/min, 200 N*m (from [operating_point])'
    """

    speed: float
    torque: float
    speed_source: str = "given"
    torque_source: str = "given"
    units: Units | None = None

    def __post_init__(self) -> None:
        if not (isinstance(self.speed, (int, float)) and math.isfinite(self.speed) and self.speed != 0):
            raise ModelError(f"input point: the input speed must be a finite, non-zero 1/min value, "
                             f"got {self.speed!r}.")
        if not (isinstance(self.torque, (int, float)) and math.isfinite(self.torque) and self.torque > 0):
            raise ModelError(f"input point: the input torque must be a positive N·m value, got {self.torque!r}.")
        object.__setattr__(self, "speed", float(self.speed))
        object.__setattr__(self, "torque", float(self.torque))

    @property
    def is_default(self) -> bool:
        """True where neither value was given (the hidden point of old, now stated)."""
        return self.speed_source == "default" and self.torque_source == "default"

    def describe(self) -> str:
        """``"input 2000 1/min, 200 N*m (from [operating_point])"`` in :attr:`units`.

        Returns
        -------
        str
        """
        units = self.units or Units()
        speed = f"{units.convert(self.speed, 'speed'):.6g} {units.speed}"
        torque = f"{units.convert(self.torque, 'torque'):.6g} {units.torque}"
        if self.speed_source == self.torque_source:
            origin = f"from {self.speed_source}" if self.speed_source != "default" else \
                "the default point: give --speed/--torque or an [operating_point]"
            return f"input {speed}, {torque} ({origin})"
        return f"input {speed} (from {self.speed_source}), {torque} (from {self.torque_source})"

    def to_dict(self) -> dict[str, Any]:
        """``input_speed_rpm``, ``input_torque_Nm``, ``input_power_W`` and the sources (JSON-ready).

        Returns
        -------
        dict
        """
        return {"input_speed_rpm": self.speed, "input_torque_Nm": self.torque,
                "input_power_W": self.speed * RPM_TO_RAD_S * self.torque,
                "speed_source": self.speed_source, "torque_source": self.torque_source}


def input_point(input: str, operating_point: Any = None, *, speed: object = None, torque: object = None,
                units: Units | None = None) -> InputPoint:
    """The input point of a gear analysis: the given values, else the operating point's, else the defaults.

    Parameters
    ----------
    input : str
        The transmission's input shaft.
    operating_point : OperatingPoint, optional
        The file's ``[operating_point]``: its speed of ``input`` and its torque there (or its power
        there, T = P/ω).
    speed, torque : float, str or pint.Quantity, optional
        ``--speed`` / ``--torque``: plain numbers are in ``units`` (1/min and N·m without), strings
        may carry a unit (``"2000 U/min"``, ``"15 kp*m"``).
    units : Units, optional
        The file's ``[units]``.

    Returns
    -------
    InputPoint

    Raises
    ------
    UnitError
        A value whose unit is not a speed or torque.
    ModelError
        A zero or non-finite speed, a torque ≤ 0.

    Examples
    --------
    >>> from epicyclic import OperatingPoint
    >>> op = OperatingPoint(speeds={"in": 3000.0}, powers={"in": 31415.9265}, drives=["in"], loads=["out"])
    >>> p = input_point("in", op)
    >>> round(p.torque, 3), p.speed_source
    (100.0, '[operating_point]')
    >>> input_point("in", op, torque="50 N*m").describe()
    'input 3000 1/min (from [operating_point]), 50 N*m (from --torque)'

    References
    ----------
    Brandenberger 1952, eq. 7 (the losses follow the rolling power).
    """
    units = units or Units()
    n = t = None
    n_from = t_from = "default"
    if operating_point is not None:
        if input in operating_point.speeds:
            n, n_from = float(operating_point.speeds[input]), "[operating_point]"
        if input in operating_point.torques:
            t, t_from = abs(float(operating_point.torques[input])), "[operating_point]"
        elif input in operating_point.powers and n is not None:
            t, t_from = abs(float(operating_point.powers[input]) / (n * RPM_TO_RAD_S)), "[operating_point]"
    if speed is not None:
        n, n_from = to_core(speed, "speed", field="--speed", default_unit=units.speed), "--speed"
    if torque is not None:
        t, t_from = to_core(torque, "torque", field="--torque", default_unit=units.torque), "--torque"
    if n is None:
        n = DEFAULT_INPUT_SPEED
    if t is None:
        t = DEFAULT_INPUT_TORQUE
    if t_from == "--torque" and not t > 0:
        raise ModelError(f"--torque: the input torque must be > 0 (coast is analysed with it at the output), "
                         f"got {torque!r}.")
    if n_from == "--speed" and not (math.isfinite(n) and n != 0):
        raise ModelError(f"--speed: the input speed must be finite and not 0, got {speed!r}.")
    return InputPoint(n, t, n_from, t_from, units)
