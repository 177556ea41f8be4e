"""Lumped model of a double-planet set: sun – inner planet – outer planet – ring, every planet with 3 DOF.

Planet pair n: the inner planet a at (ψ_n, R_a = carrier radius) meshes the sun, the outer planet b at
(ψ_n + φ, R_b) meshes the ring and planet a.  Coordinates as in :mod:`~epicyclic.elastic.lumped`
(ξ, η, u of each planet in its own radial/tangential axes), in the order a, b of each pair.
The meshes, on the flanks loaded when the sun drives counter-clockwise (the sense ψ grows):

* sun–a: the form of Lin & Parker 1999, δ = −x_s sin ψ_s + y_s cos ψ_s − ξ_a sin α_s − η_a cos α_s + u_s + u_a;
* a–b (external, a driven clockwise drives b): line of action d = e(β + α_ab − 90°), β the angle of the
  centre line a → b; δ = d·(X_a − X_b) − u_a − u_b;
* b–ring (internal, b driven counter-clockwise): d′ = e(ψ_b − α_r − 90°); δ = d′·(X_r − X_b) − u_r + u_b
  (the mirror of the simple set's ring mesh, whose planet turns the other way);
* the planet bearings at radius R tie the pin to the carrier: η − (−x_c sin ψ + y_c cos ψ + (R/r_c) u_c).

Checks built into the tests: a rigid rotation of the whole set strains no spring (the mesh signs and
lines of action are consistent); equally spaced pairs give 9 rotational, 9 double translational and 6
planet-mode frequencies of multiplicity N − 3 (Kiracofe & Parker 2007).

References
----------
J. Lin, R. G. Parker, J. Vib. Acoust. 121 (1999) 316–321 (the model); D. R. Kiracofe, R. G. Parker,
"Structured vibration modes of general compound planetary gear systems", J. Vib. Acoust. 129 (2007)
1–16 (double-planet sets, the mode structure).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import ElasticError, finite, positive
from .lumped import CENTRAL, Body, PlanetaryLumpedModel, SpringSet

__all__ = ["DoublePlanetModel"]


def _e(angle: float) -> np.ndarray:
    return np.array([math.cos(angle), math.sin(angle)])


@dataclass(frozen=True)
class DoublePlanetModel(PlanetaryLumpedModel):
    """A double-planet set as masses and springs (module docstring).

    Attributes
    ----------
    outer_planet : Body
        Planet b (meshing the ring); ``planet`` is planet a (meshing the sun).
    planet_mesh : float
        Mesh stiffness of the a–b mesh, N/m.
    planet_pressure_angle : float
        Its working transverse pressure angle, rad.
    outer_planet_radius : float
        R_b, m (R_a is ``carrier.radius``).
    outer_planet_angle : float
        φ: planet b stands at ψ_n + φ, rad.
    """

    outer_planet: Body | None = None
    planet_mesh: float = 0.0
    planet_pressure_angle: float = math.radians(20.0)
    outer_planet_radius: float = 0.0
    outer_planet_angle: float = 0.0

    def __post_init__(self) -> None:
        super().__post_init__()
        if not isinstance(self.outer_planet, Body):
            raise ElasticError(f"outer_planet must be a Body(mass, inertia, radius), got {self.outer_planet!r}.")
        object.__setattr__(self, "planet_mesh", positive(self.planet_mesh, "planet_mesh"))
        object.__setattr__(self, "outer_planet_radius", positive(self.outer_planet_radius, "outer_planet_radius"))
        object.__setattr__(self, "outer_planet_angle", finite(self.outer_planet_angle, "outer_planet_angle"))
        alpha = finite(self.planet_pressure_angle, "planet_pressure_angle")
        if not 0.0 < alpha < math.pi / 2:
            raise ElasticError(f"planet_pressure_angle must lie between 0 and pi/2 rad, got {alpha!r}.")
        if self.ring_planet_radius is not None:
            raise ElasticError("a double-planet set has no stepped planet: leave ring_planet_radius out.")

    @property
    def size(self) -> int:
        """Number of coordinates, 9 + 6N."""
        return 9 + 6 * self.planets

    def labels(self) -> tuple[str, ...]:
        """Names of the coordinates in matrix order (``planet 1a.xi`` … ``planet 1b.u``)."""
        out = [f"{m}.{c}" for m in CENTRAL for c in ("x", "y", "u")]
        out += [f"planet {n + 1}{w}.{c}" for n in range(self.planets) for w in "ab" for c in ("xi", "eta", "u")]
        return tuple(out)

    def _body_masses(self) -> tuple[np.ndarray, np.ndarray]:
        bodies = [self.carrier, self.ring, self.sun] + [self.planet, self.outer_planet] * self.planets
        translational = np.repeat([b.mass for b in bodies], 3)
        translational[2::3] = 0.0
        full = translational.copy()
        full[2::3] = [b.inertia_over_r2 for b in bodies]
        return full, translational

    def springs(self) -> tuple[tuple[str, ...], np.ndarray, np.ndarray]:
        """(names, stiffnesses N/m, directions) as :meth:`PlanetaryLumpedModel.springs`; meshes ``sun-planet n``,
        ``planet-planet n``, ``ring-planet n``, bearings ``bearing planet na`` / ``nb``."""
        springs = SpringSet(self.size)
        add = springs.add

        def local(p: int, psi: float, d: np.ndarray, sign: float) -> dict[int, float]:
            """A planet's translation term sign·d·X in its (ξ, η) axes."""
            return {p: sign * float(d @ _e(psi)), p + 1: sign * float(d @ _e(psi + math.pi / 2))}

        a_s, a_r, a_p = self.sun_pressure_angle, self.ring_pressure_angle, self.planet_pressure_angle
        r_a, r_b, r_c = self.carrier.radius, self.outer_planet_radius, self.carrier.radius
        for i, psi in enumerate(self.planet_angles):
            pa, pb = 9 + 6 * i, 9 + 6 * i + 3
            psi_b = psi + self.outer_planet_angle
            ps = psi - a_s
            add(f"sun-planet {i + 1}", self.sun_mesh, {6: -math.sin(ps), 7: math.cos(ps), 8: 1.0, pa: -math.sin(a_s),
                                                      pa + 1: -math.cos(a_s), pa + 2: 1.0})
            centre = r_b * _e(psi_b) - r_a * _e(psi)
            beta = math.atan2(centre[1], centre[0])
            d = _e(beta + a_p - math.pi / 2)
            add(f"planet-planet {i + 1}", self.planet_mesh,
                {**local(pa, psi, d, 1.0), pa + 2: -1.0, **local(pb, psi_b, d, -1.0), pb + 2: -1.0})
            d_r = _e(psi_b - a_r - math.pi / 2)
            add(f"ring-planet {i + 1}", self.ring_mesh,
                {3: float(d_r[0]), 4: float(d_r[1]), 5: -1.0, **local(pb, psi_b, d_r, -1.0), pb + 2: 1.0})
            for p, phi, radius, tag in ((pa, psi, r_a, "a"), (pb, psi_b, r_b, "b")):
                add(f"bearing planet {i + 1}{tag}", self.planet_bearing, {p: 1.0, 0: -math.cos(phi), 1: -math.sin(phi)})
                add(f"bearing planet {i + 1}{tag}", self.planet_bearing,
                    {p + 1: 1.0, 0: math.sin(phi), 1: -math.cos(phi), 2: -radius / r_c})
        self._supports(springs)
        return springs.result()

    def to_dict(self):
        """JSON data of the inputs (SI units), with the outer planet and the planet–planet mesh."""
        out = super().to_dict()
        b = self.outer_planet
        out.update({"outer_planet": {"mass_kg": b.mass, "inertia_kg_m2": b.inertia, "radius_m": b.radius},
                    "planet_mesh_N_per_m": self.planet_mesh,
                    "planet_pressure_angle_deg": math.degrees(self.planet_pressure_angle),
                    "outer_planet_radius_m": self.outer_planet_radius,
                    "outer_planet_angle_deg": math.degrees(self.outer_planet_angle)})
        return out
