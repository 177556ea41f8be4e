"""Shift elements as they act in a shift: wet multi-plate clutches and brakes, and freewheels.

A wet clutch or brake presses its plates with the piston: the normal force is
F_n = max(0, p A − F_s) (piston area A, return-spring force F_s), and the torque it can carry is

    T_cap = μ(Δω) · z · r_m · F_n

with z friction faces, the mean friction radius r_m and the friction coefficient μ over the slip
speed from a table (static μ at zero slip).  While it slips it carries exactly T_cap against the
slip; while it sticks it carries whatever the train needs, up to T_cap(0) (stick–slip: it locks at
synchronism and breaks away where the need exceeds the static capacity).  While the pack is open
(F_n = 0) it carries the drag of the oil film (:class:`~epicyclic.losses.ClutchDrag`), if given.

The heat of slip, Q = ∫ T |Δω| dt, warms the plates: a lumped thermal mass (plates' m c) gives the
temperature rise ΔT = Q / (m c) (no heat flow to the oil during the shift: an upper bound).

A freewheel (one-way clutch) carries torque in one direction only: it locks when the slip
reaches zero in its blocking direction and overruns when the torque it carries would reverse.

References
----------
Naunheimer, H., Bertsche, B., Ryborz, J., Novak, W.: *Automotive Transmissions*, 2nd ed., Springer
2011, §10.2 (multi-plate clutch: T = μ z r_m F, the return spring, specific friction energy and
power per friction area); Budynas, R. G., Nisbett, J. K.: *Shigley's Mechanical Engineering
Design*, 9th ed., McGraw-Hill 2011, §16-5 (disk clutches, uniform wear, r_m = (r_o + r_i)/2) and
§16-10 (energy considerations, temperature rise ΔT = E/(C m)).
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass
from typing import Any

from .errors import DynamicsError

__all__ = ["FrictionCapacity", "WetElement", "Freewheel"]


def _number(value: object, name: str, owner: str, *, zero: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or not (value >= 0 if zero else value > 0):
        raise DynamicsError(f"{owner}: {name} must be a finite number {'≥ 0' if zero else '> 0'}, "
                            f"got {value!r:.40}.")
    return float(value)


def _table(points: Any, owner: str, key: str, x_name: str, y_name: str) -> tuple[tuple[float, float], ...]:
    """Rows (x, y) with x ≥ 0 strictly increasing and y > 0."""
    try:
        rows = tuple((float(x), float(y)) for x, y in points)
    except (TypeError, ValueError):
        raise DynamicsError(f"{owner}: {key} must be a list of [{x_name}, {y_name}] pairs, got {points!r:.60}.") \
            from None
    if not rows:
        raise DynamicsError(f"{owner}: {key} needs at least one [{x_name}, {y_name}] pair.")
    xs = [x for x, _ in rows]
    if not all(math.isfinite(x) and math.isfinite(y) and x >= 0 and y > 0 for x, y in rows):
        raise DynamicsError(f"{owner}: {key}: every {x_name} must be ≥ 0 and every {y_name} > 0 (finite), "
                            f"got {rows!r:.80}.")
    if any(b <= a for a, b in zip(xs, xs[1:])):
        raise DynamicsError(f"{owner}: {key}: the {x_name} values must increase strictly, got {xs!r:.80}.")
    return rows


@dataclass(frozen=True)
class FrictionCapacity:
    """Torque capacity of a wet multi-plate pack from the oil pressure.

    Parameters
    ----------
    piston_area : float
        A, m².
    faces : int
        z, number of friction faces (2 per lined plate).
    mean_radius : float
        r_m, m.
    friction : sequence of (slip, μ) or float
        μ over the slip speed (slip in 1/min, ≥ 0, increasing; linear between, constant beyond the
        ends); the value at the smallest slip is the static μ.  One number: constant μ.
    return_spring : float, default 0
        F_s, N: the pressure force below which the pack stays open.
    friction_area : float, optional
        Lined area of all faces, m² (for the specific energy and power); default z·π(r_o² − r_i²)
        is not known here, so it must be given for those figures (else they are not reported).
    heat_capacity : float, optional
        m c of the plates, J/K, for the lumped temperature rise (else not reported).

    References
    ----------
    Naunheimer et al. 2011, §10.2; Budynas & Nisbett 2011, §16-5.

    Examples
    --------
    >>> c = FrictionCapacity(piston_area=0.01, faces=8, mean_radius=0.07, friction=0.12, return_spring=500.0)
    >>> round(c.capacity(5e5, 0.0), 3)  # 0.12 · 8 · 0.07 · (5e5 · 0.01 − 500) N·m
    302.4
    """

    piston_area: float
    faces: int
    mean_radius: float
    friction: Any
    return_spring: float = 0.0
    friction_area: float | None = None
    heat_capacity: float | None = None

    def __post_init__(self) -> None:
        owner = "clutch capacity"
        object.__setattr__(self, "piston_area", _number(self.piston_area, "piston_area (m^2)", owner))
        if isinstance(self.faces, bool) or not isinstance(self.faces, int) or not 1 <= self.faces <= 64:
            raise DynamicsError(f"{owner}: faces must be a whole number of friction faces in 1 ... 64, "
                                f"got {self.faces!r:.40}.")
        object.__setattr__(self, "mean_radius", _number(self.mean_radius, "mean_radius (m)", owner))
        object.__setattr__(self, "return_spring", _number(self.return_spring, "return_spring (N)", owner, zero=True))
        friction = self.friction
        if isinstance(friction, (int, float)) and not isinstance(friction, bool):
            friction = ((0.0, _number(friction, "friction (mu)", owner)),)
        rows = _table(friction, owner, "friction", "slip (1/min)", "mu")
        if any(mu > 1.0 for _, mu in rows):
            raise DynamicsError(f"{owner}: friction: a wet friction coefficient above 1 is no lining "
                                f"(typical 0.08 ... 0.16), got {rows!r:.80}.")
        object.__setattr__(self, "friction", rows)
        for key, unit in (("friction_area", "m^2"), ("heat_capacity", "J/K")):
            value = getattr(self, key)
            if value is not None:
                object.__setattr__(self, key, _number(value, f"{key} ({unit})", owner))

    def mu(self, slip: float) -> float:
        """μ at the slip speed |slip| (rad/s), linear in the table over 1/min.

        Parameters
        ----------
        slip : float
            rad/s (its sign does not matter).

        Returns
        -------
        float
        """
        rows = self.friction
        if len(rows) == 1:
            return rows[0][1]
        x = abs(slip) * 30.0 / math.pi
        if x <= rows[0][0]:
            return rows[0][1]
        if x >= rows[-1][0]:
            return rows[-1][1]
        k = bisect.bisect_right([r[0] for r in rows], x)
        (x0, y0), (x1, y1) = rows[k - 1], rows[k]
        return y0 + (y1 - y0) * (x - x0) / (x1 - x0)

    @property
    def static_mu(self) -> float:
        """μ at the table's smallest slip (sticking)."""
        return self.friction[0][1]

    def normal_force(self, pressure: float) -> float:
        """F_n = max(0, p A − F_s), N, at the pressure p (Pa)."""
        return max(0.0, pressure * self.piston_area - self.return_spring)

    def capacity(self, pressure: float, slip: float) -> float:
        """T_cap = μ(slip) z r_m F_n, N·m.

        Parameters
        ----------
        pressure : float
            Pa.
        slip : float
            rad/s.

        References
        ----------
        Naunheimer et al. 2011, §10.2 (multi-plate clutch torque).
        """
        return self.mu(slip) * self.faces * self.mean_radius * self.normal_force(pressure)

    def pressure_for(self, torque: float) -> float:
        """The pressure (Pa) that gives the static capacity ``torque`` (N·m): the inverse of :meth:`capacity`."""
        return (max(torque, 0.0) / (self.static_mu * self.faces * self.mean_radius) + self.return_spring) \
            / self.piston_area


@dataclass(frozen=True)
class WetElement:
    """A clutch or brake of the train with its friction pack, pressure and drag.

    Parameters
    ----------
    name : str
        The clutch or brake of the train.
    capacity : FrictionCapacity
    drag : callable, optional
        Slip speed (rad/s) → drag torque magnitude (N·m) while the pack is open, e.g. a
        :class:`~epicyclic.losses.ClutchDrag` at the oil's viscosity and density
        (:meth:`from_drag_model`).
    """

    name: str
    capacity: FrictionCapacity
    drag: Any = None

    def __post_init__(self) -> None:
        if not isinstance(self.capacity, FrictionCapacity):
            raise DynamicsError(f"element {self.name!r}: capacity must be a FrictionCapacity, got "
                                f"{type(self.capacity).__name__}.")
        if self.drag is not None and not callable(self.drag):
            raise DynamicsError(f"element {self.name!r}: drag must be a function of the slip speed (rad/s).")

    def torque(self, pressure: float, slip: float) -> float:
        """Magnitude of the torque the element carries while slipping, N·m: friction, or drag while open.

        Parameters
        ----------
        pressure : float
            Pa.
        slip : float
            rad/s.

        Returns
        -------
        float
        """
        force = self.capacity.normal_force(pressure)
        if force > 0.0:
            return self.capacity.capacity(pressure, slip)
        return float(self.drag(abs(slip))) if self.drag is not None else 0.0

    def static_capacity(self, pressure: float) -> float:
        """The most torque it holds while sticking, N·m."""
        return self.capacity.capacity(pressure, 0.0)

    @staticmethod
    def drag_function(model, viscosity: float, density: float):
        """Slip (rad/s) → drag (N·m) of a :class:`~epicyclic.losses.ClutchDrag` at η (mPa·s) and ρ (kg/m³).

        Parameters
        ----------
        model : ClutchDrag
        viscosity : float
            mPa·s.
        density : float
            kg/m³.

        Returns
        -------
        callable

        References
        ----------
        Yuan et al. 2007, eqs. (5)–(9) (via :class:`~epicyclic.losses.ClutchDrag`).
        """
        return _Drag(model, float(viscosity), float(density))


@dataclass(frozen=True)
class _Drag:
    model: Any
    viscosity: float
    density: float

    def __call__(self, slip: float) -> float:
        return float(self.model.torque(slip * 30.0 / math.pi, self.viscosity, self.density))


@dataclass(frozen=True)
class Freewheel:
    """A one-way clutch: it locks where ω_first − ω_second would turn negative and overruns where positive.

    Parameters
    ----------
    name : str
        The clutch or brake of the train that acts as a freewheel.
    reverse : bool, default False
        True: it blocks the other direction (locks where ω_first − ω_second would turn positive).
    """

    name: str
    reverse: bool = False

    def __post_init__(self) -> None:
        if not isinstance(self.reverse, bool):
            raise DynamicsError(f"freewheel {self.name!r}: reverse must be true or false, got {self.reverse!r}.")

    @property
    def blocking(self) -> float:
        """+1: it blocks negative slip (first slower than second); −1: positive slip."""
        return -1.0 if self.reverse else 1.0
