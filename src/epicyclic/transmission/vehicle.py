"""The vehicle behind a transmission: wheel radius and axle ratio, and the road load of a speed trace.

A drive cycle gives the vehicle speed v(t); the transmission sees the output
speed and torque the vehicle asks for.  With the axle (final-drive) ratio i_A
and the dynamic wheel radius r:

* output speed n_out = i_A · v / r · 30/π (1/min);
* tractive force (driving resistances) F = m g (c_r cos α + sin α) + ½ ρ c_d A v² + λ m a,
  with the grade tan α, the rolling coefficient c_r (only while the vehicle moves), the drag area
  c_d A, the air density ρ, the rotating-mass factor λ ≥ 1 and the acceleration a = dv/dt;
* wheel torque T_w = F r, output torque T_out = T_w / (i_A η_A) while driving (T_w > 0) and
  T_w η_A / i_A while braking, with the axle efficiency η_A.

References
----------
Guzzella, Sciarretta, *Vehicle Propulsion Systems*, 3rd ed., Springer 2013, §2.1 (driving
resistances: rolling, aerodynamic, climbing and inertial forces); Naunheimer, Bertsche, Ryborz,
Novak, *Automotive Transmissions*, 2nd ed., Springer 2011, §3.1 (the same, with the rotating-mass
factor λ).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ModelError

__all__ = ["Vehicle", "STANDARD_GRAVITY", "AIR_DENSITY"]

#: g, m/s² (CGPM 1901).
STANDARD_GRAVITY = 9.80665
#: Density of dry air at 20 °C and 101.325 kPa, kg/m³ (ISO 2533 gives 1.225 at 15 °C).
AIR_DENSITY = 1.204


def _number(value: Any, name: str, low: float, high: float, *, low_open: bool = True) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or not (low < value if low_open else low <= value) or not value <= high:
        bound = "(" if low_open else "["
        raise ModelError(f"vehicle: {name} must be a number in {bound}{low:g}, {high:g}], got {value!r:.40}.")
    return float(value)


@dataclass(frozen=True)
class Vehicle:
    """Wheel, axle and driving-resistance data of a vehicle.

    Parameters
    ----------
    wheel_radius : float
        Dynamic rolling radius r, m (0.05 … 2).
    axle_ratio : float
        Final-drive ratio i_A = n_output / n_wheel (0.1 … 50).
    mass : float, optional
        Vehicle mass m, kg; needed for the road load (not for a cycle with output torques).
    rolling_coefficient : float, default 0.010
        c_r (a passenger-car tyre on asphalt: 0.008 … 0.015, Guzzella & Sciarretta 2013, §2.1).
    drag_area : float, default 0.0
        c_d A, m² (a mid-size car: about 0.65).
    air_density : float, default 1.204
        ρ, kg/m³.
    rotating_mass_factor : float, default 1.0
        λ ≥ 1: the inertia of wheels, shafts and engine as extra mass (1.0: none, stated).
    axle_efficiency : float, default 1.0
        η_A of the final drive (1.0: lossless, stated).

    Examples
    --------
    A 1500 kg car at 100 km/h on the level, c_r = 0.01, c_d A = 0.65 m², ρ = 1.2 kg/m³:
    F = 1500·9.80665·0.01 + ½·1.2·0.65·27.78² = 147.1 + 300.9 = 448.0 N.

    >>> car = Vehicle(0.31, 3.0, mass=1500.0, drag_area=0.65, air_density=1.2)
    >>> round(float(car.tractive_force(100 / 3.6, 0.0, 0.0)), 1)
    448.0
    """

    wheel_radius: float
    axle_ratio: float
    mass: float | None = None
    rolling_coefficient: float = 0.010
    drag_area: float = 0.0
    air_density: float = AIR_DENSITY
    rotating_mass_factor: float = 1.0
    axle_efficiency: float = 1.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "wheel_radius", _number(self.wheel_radius, "wheel_radius (m)", 0.05, 2.0,
                                                         low_open=False))
        object.__setattr__(self, "axle_ratio", _number(self.axle_ratio, "axle_ratio", 0.1, 50.0, low_open=False))
        if self.mass is not None:
            object.__setattr__(self, "mass", _number(self.mass, "mass (kg)", 0.0, 1e6))
        object.__setattr__(self, "rolling_coefficient",
                           _number(self.rolling_coefficient, "rolling_coefficient", 0.0, 0.5, low_open=False))
        object.__setattr__(self, "drag_area", _number(self.drag_area, "drag_area (m^2)", 0.0, 100.0, low_open=False))
        object.__setattr__(self, "air_density", _number(self.air_density, "air_density (kg/m^3)", 0.0, 10.0,
                                                        low_open=False))
        object.__setattr__(self, "rotating_mass_factor",
                           _number(self.rotating_mass_factor, "rotating_mass_factor", 1.0, 5.0, low_open=False))
        object.__setattr__(self, "axle_efficiency", _number(self.axle_efficiency, "axle_efficiency", 0.0, 1.0))

    def output_speed(self, vehicle_speed) -> np.ndarray:
        """n_out = i_A v / r · 30/π, 1/min, of vehicle speeds in m/s.

        Parameters
        ----------
        vehicle_speed : array_like
            m/s.

        Returns
        -------
        ndarray
        """
        return self.axle_ratio * np.asarray(vehicle_speed, dtype=float) / self.wheel_radius * 30.0 / math.pi

    def tractive_force(self, vehicle_speed, acceleration, grade) -> np.ndarray:
        """F = m g (c_r cos α + sin α) + ½ ρ c_d A v² + λ m a, N (arrays broadcast).

        Parameters
        ----------
        vehicle_speed : array_like
            v, m/s (≥ 0; rolling resistance only where v > 0).
        acceleration : array_like
            a, m/s².
        grade : array_like
            tan α (0.05 = 5 % uphill).

        Returns
        -------
        ndarray

        Raises
        ------
        ModelError
            No mass given.

        References
        ----------
        Guzzella & Sciarretta 2013, §2.1; Naunheimer et al. 2011, §3.1.
        """
        if self.mass is None:
            raise ModelError("vehicle: the road load needs the vehicle mass (--mass); or give output torques "
                             "in the cycle (column output_torque).")
        v = np.asarray(vehicle_speed, dtype=float)
        alpha = np.arctan(np.asarray(grade, dtype=float))
        weight = self.mass * STANDARD_GRAVITY
        rolling = np.where(v > 0, weight * self.rolling_coefficient * np.cos(alpha), 0.0)
        return (rolling + weight * np.sin(alpha) + 0.5 * self.air_density * self.drag_area * v * v
                + self.rotating_mass_factor * self.mass * np.asarray(acceleration, dtype=float))

    def output_torque(self, force) -> np.ndarray:
        """T_out of a tractive force, N·m: F r / (i_A η_A) while driving, F r η_A / i_A while braking.

        Parameters
        ----------
        force : array_like
            N.

        Returns
        -------
        ndarray
        """
        wheel = np.asarray(force, dtype=float) * self.wheel_radius
        return np.where(wheel > 0, wheel / (self.axle_ratio * self.axle_efficiency),
                        wheel * self.axle_efficiency / self.axle_ratio)

    def describe(self) -> str:
        """The vehicle in one line (for tables).

        Returns
        -------
        str
        """
        mass = f"m {self.mass:g} kg, " if self.mass is not None else ""
        return (f"{mass}r {self.wheel_radius:g} m, i_A {self.axle_ratio:g}, c_r {self.rolling_coefficient:g}, "
                f"c_d·A {self.drag_area:g} m², ρ {self.air_density:g} kg/m³, λ {self.rotating_mass_factor:g}, "
                f"η_A {self.axle_efficiency:g}")

    def to_dict(self) -> dict[str, Any]:
        """The parameters in SI units (JSON-ready)."""
        return {"wheel_radius_m": self.wheel_radius, "axle_ratio": self.axle_ratio, "mass_kg": self.mass,
                "rolling_coefficient": self.rolling_coefficient, "drag_area_m2": self.drag_area,
                "air_density_kg_m3": self.air_density, "rotating_mass_factor": self.rotating_mass_factor,
                "axle_efficiency": self.axle_efficiency}
