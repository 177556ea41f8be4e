"""Lumped-parameter model of a simple planetary set: rotational and translational DOF (Lin & Parker 1999).

Every member — carrier, ring, sun and each planet — is a rigid body in the plane of the set with
two translations and one rotation, written in a frame that turns with the carrier:

* central members c, r, s: x, y and u = r θ (r the base radius of sun and ring, the centre
  distance for the carrier);
* planet n at the angle ψ_n: ξ_n (radial), η_n (tangential) and u_n = r_p θ_n.

Springs, each a stiffness k along a direction vector v of the coordinates (K = Σ k v vᵀ):

* sun–planet mesh: δ_sn = −x_s sin ψ_sn + y_s cos ψ_sn − ξ_n sin α_s − η_n cos α_s + u_s + u_n,
  ψ_sn = ψ_n − α_s;
* ring–planet mesh: δ_rn = −x_r sin ψ_rn + y_r cos ψ_rn + ξ_n sin α_r − η_n cos α_r + u_r − ρ u_n,
  ψ_rn = ψ_n + α_r (ρ = 1; a stepped planet: ρ = r_p,ring/r_p,sun, its two gears on one body);
* planet bearing (isotropic k_p, between planet and its pin on the carrier):
  ξ_n − (x_c cos ψ_n + y_c sin ψ_n) and η_n − (−x_c sin ψ_n + y_c cos ψ_n + u_c);
* supports of c, r, s: k_j on x and y, k_ju on u (torsional k_θ/r² in the u coordinate).

At a carrier speed Ω the equations in the rotating frame are
M q̈ + Ω G q̇ + (K − Ω² K_Ω) q = 0 with G = blocks [[0, −2m, 0], [2m, 0, 0], [0, 0, 0]] and
K_Ω = blocks diag(m, m, 0) (Lin & Parker 1999, eq. (8); Cooley & Parker 2012, eq. (1)).

References
----------
J. Lin, R. G. Parker, "Analytical characterization of the unique properties of planetary gear free
vibration", J. Vib. Acoust. 121 (1999) 316–321, eqs. (1)–(8).
C. G. Cooley, R. G. Parker, "Vibration properties of high-speed planetary gears with gyroscopic
effects", J. Vib. Acoust. 134 (2012) 061014, eq. (1).
D. R. Kiracofe, R. G. Parker, "Structured vibration modes of general compound planetary gear
systems", J. Vib. Acoust. 129 (2007) 1–16 (stepped planets keep the three mode types).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .errors import ElasticError, finite, non_negative, positive

__all__ = ["Body", "PlanetaryLumpedModel", "SpringSet", "CENTRAL", "equally_spaced"]

#: The central members in the order of their coordinates.
CENTRAL = ("carrier", "ring", "sun")


def equally_spaced(planets: int) -> tuple[float, ...]:
    """Planet angles ψ_n = 2π (n − 1)/N, rad.

    Parameters
    ----------
    planets : int
        N ≥ 1.

    Returns
    -------
    tuple of float

    References
    ----------
    Lin & Parker 1999, section 2 (ψ_n measured from the first planet).

    Examples
    --------
    >>> [round(a, 4) for a in equally_spaced(4)]
    [0.0, 1.5708, 3.1416, 4.7124]
    """
    if isinstance(planets, bool) or not isinstance(planets, int) or planets < 1:
        raise ElasticError(f"planets must be a whole number >= 1, got {planets!r}.")
    return tuple(2.0 * math.pi * n / planets for n in range(planets))


@dataclass(frozen=True)
class Body:
    """A rigid member of the set: mass, polar moment of inertia and the radius of its u coordinate.

    Attributes
    ----------
    mass : float
        kg.
    inertia : float
        Polar moment of inertia about its axis, kg m².
    radius : float
        Base radius (sun, ring, planet) or centre distance (carrier), m.
    """

    mass: float
    inertia: float
    radius: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "mass", positive(self.mass, "mass"))
        object.__setattr__(self, "inertia", positive(self.inertia, "inertia"))
        object.__setattr__(self, "radius", positive(self.radius, "radius"))

    @property
    def inertia_over_r2(self) -> float:
        """I/r², kg: the mass of the u coordinate."""
        return self.inertia / self.radius ** 2


class SpringSet:
    """Springs being listed: names, stiffnesses and direction rows over ``size`` coordinates."""

    def __init__(self, size: int):
        self.size, self.names, self.ks, self.rows = size, [], [], []

    def add(self, name: str, k: float, entries: dict[int, float]) -> None:
        """A spring ``k`` (left out where 0) along the direction with ``entries`` (coordinate → coefficient)."""
        if k <= 0.0:
            return
        v = np.zeros(self.size)
        for index, value in entries.items():
            v[index] += value
        self.names.append(name)
        self.ks.append(k)
        self.rows.append(v)

    def result(self) -> tuple[tuple[str, ...], np.ndarray, np.ndarray]:
        """(names, stiffnesses, directions)."""
        return tuple(self.names), np.asarray(self.ks), np.asarray(self.rows).reshape(len(self.rows), self.size)


@dataclass(frozen=True)
class PlanetaryLumpedModel:
    """A simple planetary set as masses and springs (see the module docstring for the coordinates).

    Attributes
    ----------
    carrier, ring, sun, planet : Body
        The members (every planet alike).
    planet_angles : tuple of float
        ψ_n, rad, in the sense of the carrier's rotation.
    sun_mesh, ring_mesh : float
        Mean mesh stiffnesses k_sp, k_rp, N/m (e.g. c_γα b, :func:`~epicyclic.elastic.stiffness.lumped_mesh_stiffness`).
    planet_bearing : float
        k_p, N/m (radial and tangential alike).
    supports : mapping
        ``{"carrier"|"ring"|"sun": (k_translational N/m, k_torsional N m/rad)}``; 0 means free.
    sun_pressure_angle, ring_pressure_angle : float
        Working transverse pressure angles α_s, α_r, rad.
    ring_planet_radius : float or None
        A stepped planet: base radius of its gear that meshes the ring, m (``planet.radius`` is that
        of the gear meshing the sun); the ring mesh sees the planet's rotation u_n times
        ρ = r_p,ring/r_p,sun.  None: one planet gear (a simple set).
    """

    carrier: Body
    ring: Body
    sun: Body
    planet: Body
    planet_angles: tuple[float, ...]
    sun_mesh: float
    ring_mesh: float
    planet_bearing: float
    supports: dict[str, tuple[float, float]] = field(default_factory=dict)
    sun_pressure_angle: float = math.radians(20.0)
    ring_pressure_angle: float = math.radians(20.0)
    ring_planet_radius: float | None = None

    def __post_init__(self) -> None:
        for name in (*CENTRAL, "planet"):
            if not isinstance(getattr(self, name), Body):
                raise ElasticError(f"{name} must be a Body(mass, inertia, radius), got {getattr(self, name)!r}.")
        angles = tuple(finite(a, "planet_angles") for a in self.planet_angles)
        if not angles:
            raise ElasticError("planet_angles: give at least one planet angle.")
        object.__setattr__(self, "planet_angles", angles)
        for key in ("sun_mesh", "ring_mesh", "planet_bearing"):
            object.__setattr__(self, key, positive(getattr(self, key), key))
        supports = {}
        for name, pair in dict(self.supports).items():
            if name not in CENTRAL:
                raise ElasticError(f"supports: unknown member {name!r}; use carrier, ring or sun.")
            if not isinstance(pair, (tuple, list)) or len(pair) != 2:
                raise ElasticError(f"supports[{name!r}] must be (translational N/m, torsional N m/rad), got {pair!r}.")
            supports[name] = (non_negative(pair[0], f"supports.{name} translational"),
                              non_negative(pair[1], f"supports.{name} torsional"))
        object.__setattr__(self, "supports", {name: supports.get(name, (0.0, 0.0)) for name in CENTRAL})
        if self.ring_planet_radius is not None:
            object.__setattr__(self, "ring_planet_radius", positive(self.ring_planet_radius, "ring_planet_radius"))
        for key in ("sun_pressure_angle", "ring_pressure_angle"):
            value = finite(getattr(self, key), key)
            if not 0.0 < value < math.pi / 2:
                raise ElasticError(f"{key} must lie between 0 and pi/2 rad, got {value!r}.")
            object.__setattr__(self, key, value)

    # ------------------------------------------------------------------ coordinates
    @property
    def planets(self) -> int:
        """N."""
        return len(self.planet_angles)

    @property
    def size(self) -> int:
        """Number of coordinates, 9 + 3N."""
        return 9 + 3 * self.planets

    def labels(self) -> tuple[str, ...]:
        """Names of the coordinates (``sun.x``, ``planet 2.u`` …) in matrix order."""
        out = [f"{m}.{c}" for m in CENTRAL for c in ("x", "y", "u")]
        out += [f"planet {n + 1}.{c}" for n in range(self.planets) for c in ("xi", "eta", "u")]
        return tuple(out)

    def _body_masses(self) -> tuple[np.ndarray, np.ndarray]:
        bodies = [self.carrier, self.ring, self.sun] + [self.planet] * self.planets
        translational = np.repeat([b.mass for b in bodies], 3)
        translational[2::3] = 0.0
        full = translational.copy()
        full[2::3] = [b.inertia_over_r2 for b in bodies]
        return full, translational

    def mass_matrix(self) -> np.ndarray:
        """M = diag(m, m, I/r²) per member, kg."""
        return np.diag(self._body_masses()[0])

    def gyroscopic_matrix(self) -> np.ndarray:
        """G (skew): blocks [[0, −2m, 0], [2m, 0, 0], [0, 0, 0]], kg."""
        translational = self._body_masses()[1]
        g = np.zeros((self.size, self.size))
        for start in range(0, self.size, 3):
            m = translational[start]
            g[start, start + 1], g[start + 1, start] = -2.0 * m, 2.0 * m
        return g

    def centripetal_matrix(self) -> np.ndarray:
        """K_Ω = diag(m, m, 0) per member, kg."""
        return np.diag(self._body_masses()[1])

    @property
    def step_ratio(self) -> float:
        """ρ = r_p,ring / r_p,sun of a stepped planet (1 for a simple set)."""
        return 1.0 if self.ring_planet_radius is None else self.ring_planet_radius / self.planet.radius

    # ------------------------------------------------------------------ springs
    def springs(self) -> tuple[tuple[str, ...], np.ndarray, np.ndarray]:
        """(names, stiffnesses k (N/m), directions V (one row per spring)) with K = Vᵀ diag(k) V.

        A spring's name is the element it belongs to: ``sun-planet 1``, ``ring-planet 1``,
        ``bearing planet 1`` (radial and tangential rows), ``support sun`` (x, y rows),
        ``torsion ring``.  Springs of zero stiffness (free members) are left out.
        """
        springs = SpringSet(self.size)
        add = springs.add
        a_s, a_r, rho = self.sun_pressure_angle, self.ring_pressure_angle, self.step_ratio
        for i, psi in enumerate(self.planet_angles):
            p = 9 + 3 * i
            ps, pr = psi - a_s, psi + a_r
            add(f"sun-planet {i + 1}", self.sun_mesh,
                {6: -math.sin(ps), 7: math.cos(ps), 8: 1.0, p: -math.sin(a_s), p + 1: -math.cos(a_s), p + 2: 1.0})
            add(f"ring-planet {i + 1}", self.ring_mesh,
                {3: -math.sin(pr), 4: math.cos(pr), 5: 1.0, p: math.sin(a_r), p + 1: -math.cos(a_r), p + 2: -rho})
            add(f"bearing planet {i + 1}", self.planet_bearing, {p: 1.0, 0: -math.cos(psi), 1: -math.sin(psi)})
            add(f"bearing planet {i + 1}", self.planet_bearing,
                {p + 1: 1.0, 0: math.sin(psi), 1: -math.cos(psi), 2: -1.0})
        self._supports(springs)
        return springs.result()

    def _supports(self, springs: SpringSet) -> None:
        """The translational and torsional supports of carrier, ring and sun."""
        for j, name in enumerate(CENTRAL):
            k_t, k_theta = self.supports[name]
            body = getattr(self, name)
            springs.add(f"support {name}", k_t, {3 * j: 1.0})
            springs.add(f"support {name}", k_t, {3 * j + 1: 1.0})
            springs.add(f"torsion {name}", k_theta / body.radius ** 2, {3 * j + 2: 1.0})

    def stiffness_matrix(self) -> np.ndarray:
        """K = Σ k v vᵀ over meshes, planet bearings and supports, N/m."""
        _, k, v = self.springs()
        return (v.T * k) @ v

    def elements(self) -> tuple[str, ...]:
        """The spring elements by name, each once, in order."""
        return tuple(dict.fromkeys(self.springs()[0]))

    def to_dict(self) -> dict[str, Any]:
        """JSON data of the inputs (SI units)."""
        body = lambda b: {"mass_kg": b.mass, "inertia_kg_m2": b.inertia, "radius_m": b.radius}  # noqa: E731
        return {"carrier": body(self.carrier), "ring": body(self.ring), "sun": body(self.sun),
                "planet": body(self.planet), "planet_angles_deg": [math.degrees(a) for a in self.planet_angles],
                "sun_mesh_N_per_m": self.sun_mesh, "ring_mesh_N_per_m": self.ring_mesh,
                "planet_bearing_N_per_m": self.planet_bearing,
                "supports": {k: {"translational_N_per_m": v[0], "torsional_Nm_per_rad": v[1]}
                             for k, v in self.supports.items()},
                "sun_pressure_angle_deg": math.degrees(self.sun_pressure_angle),
                "ring_pressure_angle_deg": math.degrees(self.ring_pressure_angle),
                "ring_planet_radius_m": self.ring_planet_radius}

    def equally_spaced(self, tolerance: float = 1e-9) -> bool:
        """Whether the planets stand at 2π/N apart (within ``tolerance`` rad)."""
        ideal = np.asarray(equally_spaced(self.planets)) + self.planet_angles[0]
        diff = np.angle(np.exp(1j * (np.asarray(self.planet_angles) - ideal)))
        return bool(np.all(np.abs(diff) <= tolerance))

