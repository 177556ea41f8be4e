"""Planet-bearing and central loads of a set over arrays of load cases, from four force evaluations.

The force model of :func:`~epicyclic.geometry.planetary_forces` puts on each planet
body a part that depends on the sun torque alone and a part that depends on the
ring torque alone.  Each part is a mesh force ``F_t e_t + F_r e_r`` with
``F_t = 1000 |T| / (N r_w)`` (its sense from the sign of T) and ``F_r = F_t tan α_wt``
(always pushing the gears apart); the force of planet 1 on planet 2 of a
double-planet set follows from the ring part alone.  So each part is |T| times a
vector that depends only on the sign of T:

.. math:: \\vec F_{body}(T_s, T_r) = |T_s|\\,\\vec H_{\\operatorname{sgn} T_s} + |T_r|\\,\\vec G_{\\operatorname{sgn} T_r}

and the same holds for the net forces on the central members.  The four vectors
H₊, H₋, G₊, G₋ of every body are the forces of
:func:`~epicyclic.geometry.planetary_forces` itself at the unit torques
(±1, 0) and (0, ±1) N·m, so the loads of any number of cases follow with numpy,
identical to a call per case up to round-off (the benchmark and the tests check
it).  The net axial force of a body, ``|F_a,first − F_a,last|``, follows as
``| |T_s| A_s − |T_r| A_r |`` from the unit evaluations the same way.

Planets that several sets share (:func:`~epicyclic.geometry.share_planets`) add the
tangential forces of two sets at one mesh before taking the radial force of the
sum; that is not of this form, and those sets are evaluated case by case.

References
----------
Queitsch part I, eqs. (23)–(26), (30) (mesh forces on the planet: F_t = 2000 M/(N d), F_r = F_t tan α);
ISO 21771:2007 (α_wt, β_w).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

import numpy as np

from ..geometry.forces import planetary_forces
from ..geometry.set_geometry import SetGeometry
from ..model.train import GearTrain

__all__ = ["SetLoads", "set_loads", "solution_view", "unit_forces"]


@dataclass(frozen=True)
class _Element:
    kind: str
    torques: Any


@dataclass(frozen=True)
class _Unit:
    """What :func:`~epicyclic.geometry.planetary_forces` reads of a solution: one set at given port torques."""

    train: Any
    elements: Any


@dataclass(frozen=True, eq=False)
class SetLoads:
    """Loads of one set's planet bodies and central members over an array of cases.

    Attributes
    ----------
    gears : tuple of str
        The planet gear(s) on each body (as :class:`~epicyclic.geometry.forces.PlanetLoad.gear`).
    indices : tuple of int
        The planet number of each body.
    bearing : ndarray, shape (bodies, cases, 2)
        Σ of the mesh forces on each body (its bearing force), N.
    axial : ndarray, shape (bodies, cases)
        Net axial force of each body, N.
    central : mapping {"sun", "ring", "carrier"} → ndarray, shape (cases, 2)
        Net force of the planets on each member, N.
    """

    gears: tuple[str, ...]
    indices: tuple[int, ...]
    bearing: np.ndarray
    axial: np.ndarray
    central: Any


def solution_view(train: GearTrain, torques: Mapping[str, Mapping[str, float]]) -> Any:
    """What :func:`~epicyclic.geometry.planetary_forces` reads of a Solution: sets at given port torques.

    Parameters
    ----------
    train : GearTrain
        The train the sets belong to.
    torques : mapping set → mapping port → float
        Port torques (``sun``, ``ring``, ``carrier``) of each set, N·m.

    Returns
    -------
    object
        With ``train`` and ``elements[set].torques`` / ``.kind``.
    """
    return _Unit(train, {name: _Element("planetary set", dict(t)) for name, t in torques.items()})


def _unit(train: GearTrain, name: str, geometry: SetGeometry, t_sun: float, t_ring: float):
    view = solution_view(train, {name: {"sun": t_sun, "ring": t_ring, "carrier": 0.0}})
    return planetary_forces(view, name, geometry)


def unit_forces(train: GearTrain, name: str, geometry: SetGeometry) -> dict[tuple[str, float], Any]:
    """The set's forces at the unit torques (±1, 0) and (0, ±1) N·m: the four evaluations of the module text.

    Parameters
    ----------
    train : GearTrain
        The train the set belongs to.
    name : str
        The set.
    geometry : SetGeometry
        Its geometry.

    Returns
    -------
    dict (part, sign) → PlanetaryForces
        ``part`` is ``"sun"`` or ``"ring"``, ``sign`` ±1.0.
    """
    return {(part, sign): _unit(train, name, geometry, sign if part == "sun" else 0.0, sign if part == "ring" else 0.0)
            for part in ("sun", "ring") for sign in (1.0, -1.0)}


def set_loads(train: GearTrain, name: str, geometry: SetGeometry, sun_torque: np.ndarray,
              ring_torque: np.ndarray, *, units: dict | None = None) -> SetLoads:
    """Bearing and central forces of set ``name`` at arrays of port torques (see the module text).

    Parameters
    ----------
    train : GearTrain
        The train the set belongs to.
    name : str
        The set.
    geometry : SetGeometry
        Its geometry.
    sun_torque, ring_torque : ndarray
        Port torques T_sun and T_ring per case, N·m (the solver's ``port_torques``).
    units : dict, optional
        :func:`unit_forces` of the set, when already evaluated (they depend on the geometry only).

    Returns
    -------
    SetLoads

    Examples
    --------
    A simple set, 3 planets, sun 30 teeth of module 2: each bearing carries 2 F_t = 2·2000 T/(3·60) N
    (Queitsch eq. 26):

    >>> from epicyclic import PlanetarySet
    >>> p = PlanetarySet.simple("P", sun="in", ring="r", carrier="out", z_sun=30, z_planet=24, z_ring=78)
    >>> from epicyclic import Brake, GearTrain
    >>> loads = set_loads(GearTrain([p, Brake("B", "r")]), "P", SetGeometry.create(p, module=2.0),
    ...                   np.array([100.0, -50.0]), np.array([260.0, -130.0]))
    >>> np.round(np.hypot(*loads.bearing[0].T), 3).tolist(), round(2 * 2000 * 100 / 180, 3)
    ([2222.222, 1111.111], 2222.222)

    References
    ----------
    Queitsch part I, eqs. (23)–(26), (30).
    """
    t_s = np.asarray(sun_torque, dtype=float)
    t_r = np.asarray(ring_torque, dtype=float)
    if units is None:
        units = unit_forces(train, name, geometry)
    first = units[("sun", 1.0)]
    magnitude = {"sun": np.abs(t_s), "ring": np.abs(t_r)}
    positive = {"sun": t_s >= 0, "ring": t_r >= 0}

    def combine(pick) -> np.ndarray:
        total = 0.0
        for part in ("sun", "ring"):
            plus, minus = np.asarray(pick(units[(part, 1.0)]), float), np.asarray(pick(units[(part, -1.0)]), float)
            shape = (-1,) + (1,) * plus.ndim
            total = total + magnitude[part].reshape(shape) * np.where(positive[part].reshape(shape), plus, minus)
        return np.asarray(total)

    bodies = range(len(first.bodies))
    bearing = np.stack([combine(lambda f, b=b: f.bodies[b].bearing_force) for b in bodies]) if first.bodies else \
        np.zeros((0, t_s.size, 2))
    # net axial |F_a,first − F_a,last|: the sun part's thrust against the ring part's (see the module text)
    axial = np.stack([np.abs(magnitude["sun"] * np.where(positive["sun"], units[("sun", 1.0)].bodies[b].bearing_axial,
                                                         units[("sun", -1.0)].bodies[b].bearing_axial)
                             - magnitude["ring"] * np.where(positive["ring"],
                                                            units[("ring", 1.0)].bodies[b].bearing_axial,
                                                            units[("ring", -1.0)].bodies[b].bearing_axial))
                      for b in bodies]) if first.bodies else np.zeros((0, t_s.size))
    central = {role: combine(lambda f, r=role: f.central_forces[r]) for role in ("sun", "ring", "carrier")}
    return SetLoads(tuple(b.gear for b in first.bodies), tuple(b.index for b in first.bodies), bearing, axial,
                    MappingProxyType(central))
