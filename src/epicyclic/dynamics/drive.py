"""What drives a transmission in a shift and what loads it.

Drives (at the input shaft):

* :class:`Engine`: the full-load torque over speed from a table, scaled by the throttle,
  T = θ · T_full(n) + (1 − θ) · T_motoring(n) (the motoring (drag) table defaults to 0: no engine
  braking, stated), and the engine's inertia on the input shaft;
* :class:`TorqueTrace`: the input torque over time from a table (a test bench's drive motor).

Loads (at the output shaft):

* :class:`OutputTorque`: a torque against the output over time (table; constant if one row);
* :class:`HeldSpeed`: a dynamometer that holds the output at its speed (the torque it takes is
  whatever the train delivers: a test bench at constant output speed);
* :class:`VehicleLoad`: the vehicle of :class:`~epicyclic.transmission.Vehicle` on a grade: the
  road load F = m g (c_r cos α + sin α) + ½ ρ c_d A v² at the wheel (the rolling part building up over the
  first :data:`ROLLING_ONSET` m/s from standstill, against the motion), and the vehicle's translating
  mass λ m r²/i_A² as inertia on the output; the axle efficiency acts on the road load only
  (stated).

References
----------
Guzzella, L., Sciarretta, A.: *Vehicle Propulsion Systems*, 3rd ed., Springer 2013, §2.1 (driving
resistances, the vehicle's mass reduced to a rotating shaft) and §3.1 (engine maps: torque over
speed and throttle).
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .errors import DynamicsError

#: Vehicle speed (m/s) over which the rolling resistance builds up from standstill (it opposes the motion and
#: is no driving force at rest): 0.1 m/s, stated; the vehicle's own inertia keeps this far from stiff.
ROLLING_ONSET = 0.1

__all__ = ["ROLLING_ONSET", "Engine", "TorqueTrace", "OutputTorque", "HeldSpeed", "VehicleLoad", "Table"]

RPM = math.pi / 30.0


@dataclass(frozen=True)
class Table:
    """y(x) through the rows (x, y), linear between, held beyond the ends; x strictly increasing.

    Examples
    --------
    >>> Table(((0.0, 1.0), (2.0, 3.0)), "t")(1.0)
    2.0
    """

    rows: tuple[tuple[float, float], ...]
    name: str = "table"

    def __post_init__(self) -> None:
        try:
            rows = tuple((float(x), float(y)) for x, y in self.rows)
        except (TypeError, ValueError):
            raise DynamicsError(f"{self.name}: expected a list of [x, y] pairs, got {self.rows!r:.60}.") from None
        if not 1 <= len(rows) <= 10_000:
            raise DynamicsError(f"{self.name}: give 1 ... 10000 rows, got {len(rows)}.")
        if not all(math.isfinite(x) and math.isfinite(y) for x, y in rows):
            raise DynamicsError(f"{self.name}: every value must be a finite number, got {rows!r:.80}.")
        if any(b[0] <= a[0] for a, b in zip(rows, rows[1:])):
            raise DynamicsError(f"{self.name}: the first column must increase strictly, got "
                                f"{[x for x, _ in rows]!r:.80}.")
        object.__setattr__(self, "rows", rows)
        object.__setattr__(self, "_xs", [x for x, _ in rows])

    def __call__(self, x: float) -> float:
        rows = self.rows
        if x <= rows[0][0]:
            return rows[0][1]
        if x >= rows[-1][0]:
            return rows[-1][1]
        k = bisect.bisect_right(self._xs, x)
        (x0, y0), (x1, y1) = rows[k - 1], rows[k]
        return y0 + (y1 - y0) * (x - x0) / (x1 - x0)

    @property
    def span(self) -> tuple[float, float]:
        return self.rows[0][0], self.rows[-1][0]


@dataclass(frozen=True)
class Engine:
    """An engine (or motor) at the input: torque over speed, scaled by the throttle.

    Parameters
    ----------
    full_load : sequence of (speed 1/min, torque N·m)
        The full-load curve.
    inertia : float, default 0.15
        kg·m² of the crankshaft, flywheel and turbine on the input shaft (a mid-size petrol
        engine: about 0.1 ... 0.2, stated default).
    motoring : sequence of (speed, torque), optional
        The torque at closed throttle (negative: engine braking); default 0.
    throttle : float, default 1
        θ in [0, 1].

    Examples
    --------
    >>> e = Engine(((1000, 200.0), (3000, 300.0)), throttle=0.5)
    >>> e.torque(2000 * math.pi / 30, 0.0)
    125.0
    """

    full_load: Any
    inertia: float = 0.15
    motoring: Any = ((0.0, 0.0),)
    throttle: float = 1.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "full_load", Table(self.full_load, "engine full_load").rows)
        object.__setattr__(self, "motoring", Table(self.motoring, "engine motoring").rows)
        object.__setattr__(self, "_full", Table(self.full_load, "engine full_load"))
        object.__setattr__(self, "_motoring", Table(self.motoring, "engine motoring"))
        for key, low, high in (("inertia", 0.0, 100.0), ("throttle", 0.0, 1.0)):
            value = getattr(self, key)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not low <= value <= high:
                raise DynamicsError(f"engine: {key} must be a number in [{low:g}, {high:g}], got {value!r:.40}.")
            object.__setattr__(self, key, float(value))

    def torque(self, omega: float, t: float) -> float:
        """T(n) = θ T_full(n) + (1 − θ) T_motoring(n), N·m, at ω (rad/s).

        Parameters
        ----------
        omega : float
            Speed of the shaft it acts on, rad/s.
        t : float
            Time, s.

        Returns
        -------
        float
            N·m.
        """
        n = omega / RPM
        return self.throttle * self._full(n) + (1.0 - self.throttle) * self._motoring(n)

    def with_throttle(self, throttle: float) -> Engine:
        """The same engine at another throttle θ ∈ [0, 1]."""
        return Engine(self.full_load, self.inertia, self.motoring, throttle)


@dataclass(frozen=True)
class _TorqueOverTime:
    """A torque over time from a table (s → N·m) and an inertia (kg·m²) on its shaft."""

    rows: Any
    inertia: float = 0.0
    _what = "torque over time"

    def __post_init__(self) -> None:
        table = Table(self.rows, self._what)
        object.__setattr__(self, "rows", table.rows)
        object.__setattr__(self, "_table", table)
        if isinstance(self.inertia, bool) or not isinstance(self.inertia, (int, float)) or not self.inertia >= 0:
            raise DynamicsError(f"{self._what}: inertia must be ≥ 0 kg m^2, got {self.inertia!r:.40}.")

    def torque(self, omega: float, t: float) -> float:
        """The table's torque at time t, N·m (ω unused).

        Parameters
        ----------
        omega : float
            Speed of the shaft it acts on, rad/s.
        t : float
            Time, s.

        Returns
        -------
        float
            N·m.
        """
        return self._table(t)


@dataclass(frozen=True)
class TorqueTrace(_TorqueOverTime):
    """The input torque over time (s → N·m), a test bench's drive motor; ``inertia`` kg·m² on the input."""

    _what = "input torque trace"


@dataclass(frozen=True)
class OutputTorque(_TorqueOverTime):
    """A torque against the output over time (s → N·m, positive: it brakes the output); ``inertia`` on it."""

    _what = "output torque"


@dataclass(frozen=True)
class HeldSpeed:
    """A dynamometer holding the output at the speed it has at the start (a constant-speed test bench)."""

    inertia: float = 0.0


@dataclass(frozen=True)
class VehicleLoad:
    """The vehicle's road load on a grade and its mass as inertia on the output.

    Parameters
    ----------
    vehicle : Vehicle
        With a mass.
    grade : float, default 0
        tan α.
    """

    vehicle: Any
    grade: float = 0.0
    inertia: float = field(init=False, default=0.0)

    def __post_init__(self) -> None:
        v = self.vehicle
        if getattr(v, "mass", None) is None:
            raise DynamicsError("vehicle load: the vehicle needs a mass (kg); give [vehicle] mass.")
        if isinstance(self.grade, bool) or not isinstance(self.grade, (int, float)) or not abs(self.grade) <= 1.0:
            raise DynamicsError(f"vehicle load: grade must be tan(alpha) in [-1, 1], got {self.grade!r:.40}.")
        object.__setattr__(self, "inertia",
                           v.rotating_mass_factor * v.mass * v.wheel_radius ** 2 / v.axle_ratio ** 2)

    def torque(self, omega: float, t: float) -> float:
        """Road load at the output, N·m, at the output speed ω (rad/s), against the motion.

        Parameters
        ----------
        omega : float
            Speed of the shaft it acts on, rad/s.
        t : float
            Time, s.

        Returns
        -------
        float
            N·m.
        """
        v = self.vehicle
        speed = omega * v.wheel_radius / v.axle_ratio
        alpha = math.atan(self.grade)
        weight = v.mass * 9.80665
        rolling = weight * v.rolling_coefficient * math.cos(alpha) * max(-1.0, min(1.0, speed / ROLLING_ONSET))
        force = rolling + weight * math.sin(alpha) + 0.5 * v.air_density * v.drag_area * speed * abs(speed)
        wheel = force * v.wheel_radius  # Vehicle.output_torque, for one number
        return wheel / (v.axle_ratio * v.axle_efficiency) if wheel > 0 else wheel * v.axle_efficiency / v.axle_ratio

    def vehicle_speed(self, omega):
        """v = ω r / i_A, m/s."""
        return np.asarray(omega) * self.vehicle.wheel_radius / self.vehicle.axle_ratio
