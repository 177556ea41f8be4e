"""One gear of a transmission at arrays of output speed × output torque, and whether it can carry them.

The shift map and the drive cycle ask the same question of every gear: at this
output speed and output torque, what does the input turn at, what does it
take, what is lost (by source and by element), and can the gear carry the point
at all?  :func:`solve_gear_points` answers it for arrays of points with one
batch solve with the transmission's loss models
(:func:`~epicyclic.losses.solve_batch_with_losses`, never a loop over points):
the output shaft is given its speed and loaded with the torque, the input
drives.  :class:`CarryLimits` says which points a gear can carry: the input
speed within the engine's range, the input torque at most the engine's, the
torque of every engaged shift element within its capacity, and no
self-locking.

References
----------
Brandenberger 1952, eqs. 7–10 (efficiency by the direction of power flow); ISO/TR 14179-2:2001
(the gearbox loss as the sum of the load-dependent and no-load losses); Naunheimer et al.,
*Automotive Transmissions* (2011), §7.4 (the engine's speed range limits the gears of a point).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from ..errors import ModelError
from ..model.elements import Clutch
from ..units import to_core

__all__ = ["GearPoints", "CarryLimits", "solve_gear_points", "DEFAULT_INPUT_SPEED_RANGE"]

#: Input (engine) speeds, 1/min, a gear may run at when none are given: idle to a petrol engine's
#: rated speed (Naunheimer et al. 2011, §3.2: about 800 … 6000 1/min).
DEFAULT_INPUT_SPEED_RANGE = (800.0, 6000.0)


def _frozen(value) -> np.ndarray:
    view = np.asarray(value, dtype=float if np.asarray(value).dtype != bool else bool).view()
    view.flags.writeable = False
    return view


@dataclass(frozen=True, eq=False)
class GearPoints:
    """One gear at arrays of output speed and torque (all arrays of one shape).

    Attributes
    ----------
    gear : str
    ratio : float
        n_input / n_output.
    output_speed, output_torque : ndarray
        1/min, N·m (magnitudes, as given).
    input_speed, input_torque : ndarray
        1/min, N·m at the input (driving).
    input_power, output_power, loss : ndarray
        W; ``loss = input_power − output_power``.
    efficiency : ndarray
        NaN where no power flows out or the gear self-locks.
    self_locking : ndarray of bool
    losses_by_source : mapping source → ndarray
        ``mesh``, ``bearing``, ``drag`` and the spin-loss sources, summed over the elements, W.
    losses_by_element : mapping element → ndarray
        W (``housing``: the losses that belong to no element, e.g. the pump).
    element_torques : mapping element → ndarray
        Torque on each engaged clutch or brake, N·m (signed).
    """

    gear: str
    ratio: float
    output_speed: np.ndarray
    output_torque: np.ndarray
    input_speed: np.ndarray
    input_torque: np.ndarray
    input_power: np.ndarray
    output_power: np.ndarray
    loss: np.ndarray
    efficiency: np.ndarray
    self_locking: np.ndarray
    losses_by_source: Mapping[str, np.ndarray]
    losses_by_element: Mapping[str, np.ndarray]
    element_torques: Mapping[str, np.ndarray]

    def __post_init__(self) -> None:
        for name in ("output_speed", "output_torque", "input_speed", "input_torque", "input_power",
                     "output_power", "loss", "efficiency", "self_locking"):
            object.__setattr__(self, name, _frozen(getattr(self, name)))
        for name in ("losses_by_source", "losses_by_element", "element_torques"):
            object.__setattr__(self, name, MappingProxyType({k: _frozen(v) for k, v in getattr(self, name).items()}))

    @property
    def shape(self) -> tuple[int, ...]:
        return self.loss.shape

    def __repr__(self) -> str:
        return f"<GearPoints gear {self.gear!r} (ratio {self.ratio:.4g}): {self.loss.size} points>"


@dataclass(frozen=True)
class CarryLimits:
    """What a gear must keep to carry a point: engine speed range, engine torque, shift-element capacities.

    Parameters
    ----------
    input_speed : (float, float), default (800, 6000)
        Lowest and highest input (engine) speed, 1/min (values may carry units: ``"1000 rpm"``).
    max_input_torque : float, optional
        Most input torque, N·m (the engine's peak torque); None: no limit.
    capacities : mapping element → float, optional
        Torque capacity of shift elements, N·m: an engaged clutch or brake whose torque exceeds it
        slips, so the gear cannot carry the point.

    Examples
    --------
    >>> CarryLimits((1000.0, 5000.0), 400.0, {"B": 2000.0}).describe()
    'input speed 1000..5000 1/min, input torque <= 400 N*m, capacity B 2000 N*m'

    References
    ----------
    Naunheimer et al. 2011, §7.4.
    """

    input_speed: tuple[float, float] = DEFAULT_INPUT_SPEED_RANGE
    max_input_torque: float | None = None
    capacities: Mapping[str, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        try:
            low, high = self.input_speed
        except (TypeError, ValueError):
            raise ModelError(f"carry limits: input_speed must be a pair (lowest, highest) in 1/min, "
                             f"got {self.input_speed!r:.80}.") from None
        low = to_core(low, "speed", field="input speed range (lowest)")
        high = to_core(high, "speed", field="input speed range (highest)")
        if not 0 <= low < high:
            raise ModelError(f"carry limits: the input speed range must be 0 <= lowest < highest, got "
                             f"{low:g}..{high:g} 1/min.")
        object.__setattr__(self, "input_speed", (low, high))
        if self.max_input_torque is not None:
            value = to_core(self.max_input_torque, "torque", field="max input torque")
            if not value > 0:
                raise ModelError(f"carry limits: max_input_torque must be > 0 N*m, got {value!r}.")
            object.__setattr__(self, "max_input_torque", value)
        capacities = {}
        for name, value in dict(self.capacities).items():
            number = to_core(value, "torque", field=f"capacity of {name!r}")
            if not (math.isfinite(number) and number > 0):
                raise ModelError(f"carry limits: the capacity of {name!r} must be > 0 N*m, got {value!r}.")
            capacities[str(name)] = number
        object.__setattr__(self, "capacities", MappingProxyType(capacities))

    def check_elements(self, known) -> None:
        """Refuse a capacity for an element the transmission does not have (a typo is no limit)."""
        from ..errors import closest

        known = list(known)
        for name in self.capacities:
            if name not in known:
                close = closest(name, known)
                raise ModelError(f"capacity: the transmission has no shift element {name!r}"
                                 + (f" (did you mean {close!r}?)" if close else "")
                                 + f"; its shift elements are {', '.join(repr(k) for k in known)}.")

    def carries(self, points: GearPoints) -> np.ndarray:
        """Where the gear can carry each point (bool array of the points' shape).

        Parameters
        ----------
        points : GearPoints

        Returns
        -------
        ndarray of bool
            Input speed within :attr:`input_speed`, input torque within :attr:`max_input_torque`,
            every engaged element within its capacity, no self-locking.
        """
        n = np.abs(points.input_speed)
        ok = (n >= self.input_speed[0]) & (n <= self.input_speed[1]) & ~points.self_locking
        if self.max_input_torque is not None:
            ok &= np.abs(points.input_torque) <= self.max_input_torque
        for name, capacity in self.capacities.items():
            if name in points.element_torques:
                ok &= np.abs(points.element_torques[name]) <= capacity
        return ok

    def describe(self) -> str:
        """The limits in words, for tables and figure captions.

        Returns
        -------
        str
        """
        parts = [f"input speed {self.input_speed[0]:g}..{self.input_speed[1]:g} 1/min"]
        if self.max_input_torque is not None:
            parts.append(f"input torque <= {self.max_input_torque:g} N*m")
        parts += [f"capacity {k} {v:g} N*m" for k, v in self.capacities.items()]
        return ", ".join(parts)

    def to_dict(self) -> dict[str, Any]:
        """``input_speed_rpm`` [lowest, highest], ``max_input_torque_Nm`` (or None), ``capacities_Nm``."""
        return {"input_speed_rpm": list(self.input_speed), "max_input_torque_Nm": self.max_input_torque,
                "capacities_Nm": dict(self.capacities)}


def _solve(transmission, gear: str, speed: np.ndarray, torque: np.ndarray):
    """One batch solve of ``gear``: the output turns at ``speed`` and is loaded with ``torque``."""
    from ..losses import solve_batch_with_losses

    t = transmission
    extra: dict[str, Any] = {}
    spin = getattr(t, "spin", None)
    if spin is not None:  # the transmission's spin losses (clutch drag, pump, ...) at its oil temperature
        extra = {"spin": spin, "gear": gear, "input": t.input}
    return solve_batch_with_losses(t.gear_train(gear), dict(getattr(t, "losses", None) or {}),
                                   speeds={t.output: speed}, torques={t.output: torque},
                                   drives=[t.input], loads=[t.output], **extra)


def solve_gear_points(transmission, gear: str, output_speed, output_torque) -> GearPoints:
    """``gear`` of ``transmission`` at arrays of output speed (1/min) and output torque (N·m), one batch solve.

    Parameters
    ----------
    transmission : Transmission
        With its loss models (``Transmission.from_file`` brings the file's).
    gear : str
        A gear of its schedule.
    output_speed, output_torque : array_like
        Broadcast to one shape; magnitudes (the output is driven forward and loaded).  A torque of 0
        gives the spin losses alone (no power out, efficiency NaN).

    Returns
    -------
    GearPoints

    Raises
    ------
    ModelError
        A speed or torque that is negative or not finite.
    UnknownGearError
        A gear that is not in the schedule.

    References
    ----------
    Brandenberger 1952, eqs. 7–10; ISO/TR 14179-2:2001.
    """
    speed, torque = np.broadcast_arrays(np.asarray(output_speed, dtype=float), np.asarray(output_torque, dtype=float))
    for name, value in (("output speed", speed), ("output torque", torque)):
        if not np.all(np.isfinite(value)) or np.any(value < 0):
            raise ModelError(f"gear {gear!r}: every {name} must be a finite number >= 0.")
    t = transmission
    ratio = float(t.ratio(gear))
    sol = _solve(t, gear, speed, torque)
    shape = speed.shape
    by_source: dict[str, np.ndarray] = {}
    for parts in sol.loss_sources.values():
        for source, value in parts.items():
            by_source[source] = by_source.get(source, 0.0) + np.broadcast_to(value, shape)
    by_element = {name: np.broadcast_to(value, shape) for name, value in sol.losses.items()}
    engaged = {}
    train = t.gear_train(gear)
    for element in train.shift_elements:
        key = (element.name, "first" if isinstance(element, Clutch) else "shaft")
        if element.name in t.schedule[gear] and key in sol.port_torques:
            engaged[element.name] = sol.port_torques[key]
    no_power = ~(sol.output_power > 0)
    efficiency = np.where(no_power, np.nan, sol.efficiency)
    return GearPoints(gear, ratio, speed, torque, sol.speeds[t.input], sol.torques[t.input], sol.input_power,
                      sol.output_power, sol.loss, efficiency, sol.self_locking & ~no_power,
                      by_source, by_element, engaged)
