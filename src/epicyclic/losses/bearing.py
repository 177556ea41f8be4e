"""Friction of the planet bearings from the bearing loads of the tooth forces.

A rolling bearing's frictional moment, estimated with a constant coefficient of
friction (SKF):

.. math:: M = 0.5\\,\\mu\\,P\\,d

(M in N·mm, P the bearing load in N, d the bore diameter in mm; μ = 0.0020 for
needle roller bearings with a cage, 0.0011 for cylindrical roller bearings with
a cage).  A planet bearing turns at the planet's speed relative to the carrier,
so it loses P_b = Σ M |ω_p − ω_c| over all planets.  Its load is the vector sum
of the planet's mesh forces (:func:`~epicyclic.geometry.planetary_forces`), which
is proportional to the set's torque, and the planet's relative speed is
proportional to the set's relative speed: the ratio of the bearing loss to the
rolling power P_w = T_sun (ω_sun − ω_carrier) is therefore a constant of the set,

.. math:: \\eta_{bearing} = 1 - \\frac{P_b}{|P_w|}
          = 1 - \\sum_{planets} 0.5\\,\\mu\\,d\\,\\frac{F_b}{1000\\,|T_{sun}|}\\,|k|

and the bearing friction acts, like the mesh friction, as a factor on the torque
ratio in the direction of the rolling power (Brandenberger's rule) — exactly
where its torque acts, through the meshes on the central gears.

References
----------
SKF, *Rolling bearings* (General Catalogue), "Friction — Estimating the frictional moment",
M = 0.5 μ P d and Table 1 (constant coefficient of friction μ for open bearings);
Queitsch part I, eq. (26) and Bild 6 (the bearing load F_u5 = −2 F_u2 of a simple set).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from ..geometry.forces import planetary_forces
from ..geometry.set_geometry import SetGeometry
from ..model import Brake, GearTrain, OperatingPoint
from ..solver import solve
from .errors import LossModelError

__all__ = ["PlanetBearing", "BEARING_FRICTION"]

#: Constant coefficients of friction of open bearings (SKF, Rolling bearings, "Friction", Table 1).
BEARING_FRICTION = {
    "needle roller": 0.0020,
    "cylindrical roller": 0.0011,
    "cylindrical roller full complement": 0.0020,
    "deep groove ball": 0.0015,
    "tapered roller": 0.0018,
    "spherical roller": 0.0018,
}


@dataclass(frozen=True)
class PlanetBearing:
    """The planet bearings of a set: type (or μ) and bore diameter.

    Parameters
    ----------
    bore : float
        Bore diameter d of each planet bearing, mm.
    friction : float or str, default "needle roller"
        The constant coefficient of friction μ, or a bearing type of
        :data:`BEARING_FRICTION`.

    Examples
    --------
    >>> PlanetBearing(20.0).coefficient
    0.002
    """

    bore: float
    friction: float | str = "needle roller"

    def __post_init__(self) -> None:
        d = self.bore
        if isinstance(d, bool) or not isinstance(d, (int, float)) or not math.isfinite(d) or d <= 0:
            raise LossModelError(f"PlanetBearing: bore must be a positive diameter in mm, got {d!r}.")
        f = self.friction
        if isinstance(f, str):
            if f not in BEARING_FRICTION:
                raise LossModelError(
                    f"PlanetBearing: unknown bearing type {f!r}; expected one of "
                    f"{', '.join(repr(k) for k in BEARING_FRICTION)} or a coefficient such as 0.002."
                )
        elif isinstance(f, bool) or not isinstance(f, (int, float)) or not math.isfinite(f) or not 0 <= f < 0.1:
            raise LossModelError(
                f"PlanetBearing: friction must be a bearing type or a coefficient in [0, 0.1) "
                f"(SKF: 0.0011-0.0050), got {f!r}."
            )

    @property
    def coefficient(self) -> float:
        """μ of the SKF estimate."""
        return BEARING_FRICTION[self.friction] if isinstance(self.friction, str) else float(self.friction)

    def efficiency(self, geometry: SetGeometry) -> float:
        """η_bearing of the set (see the module text): 1 − (bearing loss)/(rolling power).

        Examples
        --------
        Simple set 30/24/78, m = 2, 3 planets, needle bearings d = 16 mm: each planet bearing
        carries 2 F_t = 2·2000 T/(3·60) per N·m of sun torque (Queitsch eq. 26) and turns at
        |k| = 30/24 times the sun's relative speed:

        >>> from epicyclic import PlanetarySet
        >>> p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78)
        >>> eta = PlanetBearing(16.0).efficiency(SetGeometry.create(p, module=2.0))
        >>> round(eta, 6), round(1 - 3 * 0.5 * 0.002 * 16 * (2 * 2000 / (3 * 60)) / 1000 * 30 / 24, 6)
        (0.998667, 0.998667)
        """
        pset = geometry.planetary_set
        unit = replace(geometry, planetary_set=replace(pset, sun="s", ring="r", carrier="c",
                                                       stationary_efficiency=1.0))
        train = GearTrain([unit.planetary_set, Brake("B", "r")])
        solution = solve(train, OperatingPoint(speeds={"s": 1000.0}, torques={"s": 1.0}, drives=["s"],
                                               loads=["c"]), lossless=True)
        forces = planetary_forces(solution, pset.name, unit, load_sharing=1.0)
        k = pset.teeth.planet_factors  # type: ignore[union-attr]
        names = geometry.planet_gear_names
        loss_ratio = 0.0
        for body in forces.bodies:
            factor = k[names.index(body.gear)] if pset.teeth.kind == "double" else k[0]  # type: ignore[union-attr]
            loss_ratio += 0.5 * self.coefficient * self.bore * body.bearing_load / 1000.0 * abs(factor)
        if loss_ratio >= 1.0:
            raise LossModelError(
                f"PlanetBearing of {pset.name!r}: the bearing friction would take {loss_ratio:.3g} of the rolling "
                "power; check the bore (mm) and the coefficient."
            )
        return 1.0 - loss_ratio
