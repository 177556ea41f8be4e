"""Mass moments of inertia of a train: shafts, gear blanks and the planets with their carrier-relative spin.

The kinetic energy of a train is a quadratic form in the speeds of its moving shafts,
E = ½ ωᵀ J ω.  A shaft carries its own inertia (given, or summed from gear blanks on it) on the
diagonal of J.  A planet of a set turns about its own axis at
ω_p = ω_c + ρ (ω_s − ω_c), ρ = −z_s / z_p for a simple set (the mesh with the sun, seen from the
carrier), and its centre orbits at ω_c on the radius a; its energy
½ J_p ω_p² + ½ m_p a² ω_c² couples the sun and carrier speeds, so J is symmetric but not diagonal.

Blanks (each a body of revolution of density ρ):

* solid blank (disc with a bore): J = ½ m (r_o² + r_i²), m = ρ π (r_o² − r_i²) b;
* rimmed blank: the rim (r_rim … r_o, face width b) plus a web (r_i … r_rim, web thickness t),
  each a hollow cylinder as above.

References
----------
Meriam, J. L., Kraige, L. G.: *Engineering Mechanics: Dynamics*, 7th ed., Wiley 2012, Appendix D,
Table D/4 (moment of inertia of a circular cylinder and of a thick-walled tube, ½ m (r_o² + r_i²));
Müller, H. W.: *Epicyclic Drive Trains*, Wayne State University Press 1982, ch. 2 (the planet's
absolute speed ω_c + (ω_s − ω_c)·(−z_s/z_p)).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from .errors import DynamicsError

__all__ = ["solid_blank_inertia", "rimmed_blank_inertia", "PlanetInertia", "Inertias", "STEEL_DENSITY"]

#: Density of steel, kg/m³ (the blank default, stated).
STEEL_DENSITY = 7850.0


def _positive(value: object, name: str, owner: str, *, zero: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or not (value >= 0 if zero else value > 0):
        rule = "≥ 0" if zero else "> 0"
        raise DynamicsError(f"{owner}: {name} must be a finite number {rule}, got {value!r:.40}.")
    return float(value)


def _tube(outer: float, inner: float, width: float, density: float) -> float:
    """½ m (r_o² + r_i²) of a hollow cylinder, diameters and width in m."""
    r_o, r_i = outer / 2.0, inner / 2.0
    mass = density * math.pi * (r_o * r_o - r_i * r_i) * width
    return 0.5 * mass * (r_o * r_o + r_i * r_i)


def solid_blank_inertia(diameter: float, face_width: float, *, bore: float = 0.0,
                        density: float = STEEL_DENSITY) -> float:
    """J of a solid gear blank (a disc with a bore) about its axis, kg·m².

    Parameters
    ----------
    diameter : float
        Outside (or reference) diameter, m.
    face_width : float
        m.
    bore : float, default 0
        Bore diameter, m (< diameter).
    density : float, default 7850
        kg/m³ (steel).

    Returns
    -------
    float
        ½ m (r_o² + r_i²) with m = ρ π (r_o² − r_i²) b.

    References
    ----------
    Meriam & Kraige 2012, Appendix D, Table D/4 (thick-walled circular tube).

    Examples
    --------
    >>> round(solid_blank_inertia(0.1, 0.02), 7)  # ½ (7850 π 0.05² 0.02) 0.05²
    0.0015413
    """
    owner = "solid blank"
    d = _positive(diameter, "diameter (m)", owner)
    b = _positive(face_width, "face_width (m)", owner)
    d_i = _positive(bore, "bore (m)", owner, zero=True)
    rho = _positive(density, "density (kg/m^3)", owner)
    if d_i >= d:
        raise DynamicsError(f"{owner}: bore {d_i!r} m must be smaller than the diameter {d!r} m.")
    return _tube(d, d_i, b, rho)


def rimmed_blank_inertia(diameter: float, face_width: float, rim_diameter: float, web_width: float, *,
                         bore: float = 0.0, density: float = STEEL_DENSITY) -> float:
    """J of a rimmed gear blank: a rim of the face width on a thinner web, kg·m².

    Parameters
    ----------
    diameter : float
        Outside diameter, m.
    face_width : float
        Width of the rim, m.
    rim_diameter : float
        Inner diameter of the rim (where the web starts), m: bore < rim_diameter < diameter.
    web_width : float
        Thickness of the web, m (≤ face_width).
    bore : float, default 0
        Bore diameter, m.
    density : float, default 7850
        kg/m³.

    Returns
    -------
    float
        J_rim + J_web, each ½ m (r_o² + r_i²).

    References
    ----------
    Meriam & Kraige 2012, Appendix D, Table D/4 (composite bodies: the sum of the parts).

    Examples
    --------
    >>> full = solid_blank_inertia(0.2, 0.03)
    >>> round(rimmed_blank_inertia(0.2, 0.03, 0.15, 0.03) / full, 12)  # a web as wide as the rim: the solid blank
    1.0
    """
    owner = "rimmed blank"
    d = _positive(diameter, "diameter (m)", owner)
    b = _positive(face_width, "face_width (m)", owner)
    d_r = _positive(rim_diameter, "rim_diameter (m)", owner)
    t = _positive(web_width, "web_width (m)", owner)
    d_i = _positive(bore, "bore (m)", owner, zero=True)
    rho = _positive(density, "density (kg/m^3)", owner)
    if not d_i < d_r < d:
        raise DynamicsError(f"{owner}: need bore < rim_diameter < diameter, got {d_i!r}, {d_r!r}, {d!r} m.")
    if t > b:
        raise DynamicsError(f"{owner}: web_width {t!r} m is wider than the face width {b!r} m.")
    return _tube(d, d_r, b, rho) + _tube(d_r, d_i, t, rho)


@dataclass(frozen=True)
class PlanetInertia:
    """The planets of one set: their own spin inertia, their mass on the orbit and the spin ratio.

    Parameters
    ----------
    set_name : str
        The planetary set.
    count : int
        Number of planets.
    inertia : float
        J_p of one planet about its own axis, kg·m².
    mass : float, default 0
        m_p of one planet (with its bearing), kg: carried round the orbit.
    orbit_radius : float, default 0
        a, m (the centre distance).
    spin_ratio : float, optional
        ρ = (ω_p − ω_c)/(ω_s − ω_c); default −z_s/z_p from the set's tooth counts (simple sets),
        else required.
    """

    set_name: str
    count: int
    inertia: float
    mass: float = 0.0
    orbit_radius: float = 0.0
    spin_ratio: float | None = None

    def __post_init__(self) -> None:
        owner = f"planets of {self.set_name!r}"
        if isinstance(self.count, bool) or not isinstance(self.count, int) or not 1 <= self.count <= 64:
            raise DynamicsError(f"{owner}: count must be a whole number of planets in 1 ... 64, got {self.count!r}.")
        object.__setattr__(self, "inertia", _positive(self.inertia, "inertia (kg m^2)", owner, zero=True))
        object.__setattr__(self, "mass", _positive(self.mass, "mass (kg)", owner, zero=True))
        object.__setattr__(self, "orbit_radius", _positive(self.orbit_radius, "orbit_radius (m)", owner, zero=True))
        if self.spin_ratio is not None:
            r = self.spin_ratio
            if isinstance(r, bool) or not isinstance(r, (int, float)) or not math.isfinite(r) or r == 0:
                raise DynamicsError(f"{owner}: spin_ratio must be a finite non-zero number, got {r!r:.40}.")
            object.__setattr__(self, "spin_ratio", float(r))


def _spin_ratio(planet: PlanetInertia, planetary) -> float:
    if planet.spin_ratio is not None:
        return planet.spin_ratio
    teeth = getattr(planetary, "teeth", None)
    if getattr(teeth, "kind", None) == "simple":
        return -teeth.sun / teeth.planet[0]
    raise DynamicsError(f"planets of {planet.set_name!r}: the set has no simple tooth counts, so give spin_ratio "
                        "= (ω_planet − ω_carrier)/(ω_sun − ω_carrier), e.g. -z_sun/z_planet.")


@dataclass(frozen=True)
class Inertias:
    """Inertias of a train's shafts and planets: the mass matrix of its kinetic energy.

    Parameters
    ----------
    shafts : mapping shaft → float
        kg·m² per moving shaft (missing shafts: 0; the housing does not move).
    planets : tuple of PlanetInertia, default ()

    Examples
    --------
    >>> from epicyclic import GearTrain, Clutch
    >>> train = GearTrain([Clutch("C", "a", "b")])
    >>> Inertias({"a": 0.2, "b": 0.3}).matrix(train).tolist()
    [[0.2, 0.0], [0.0, 0.3]]
    """

    shafts: Mapping[str, float] = field(default_factory=dict)
    planets: tuple[PlanetInertia, ...] = ()

    def __post_init__(self) -> None:
        if not isinstance(self.shafts, Mapping):
            raise DynamicsError(f"inertias: shafts must be a mapping shaft -> kg m^2, got {self.shafts!r:.40}.")
        values = {str(k): _positive(v, f"inertia of shaft {k!r} (kg m^2)", "inertias", zero=True)
                  for k, v in self.shafts.items()}
        object.__setattr__(self, "shafts", MappingProxyType(values))
        planets = tuple(self.planets)
        if not all(isinstance(p, PlanetInertia) for p in planets):
            raise DynamicsError("inertias: planets must be PlanetInertia objects.")
        object.__setattr__(self, "planets", planets)

    def matrix(self, train) -> np.ndarray:
        """J (moving shafts × moving shafts, train order), kg·m²: E = ½ ωᵀ J ω.

        Parameters
        ----------
        train : GearTrain

        Returns
        -------
        ndarray

        Raises
        ------
        DynamicsError
            A shaft or set the train does not have, or a singular J over the train's motions.

        References
        ----------
        Müller 1982, ch. 2 (planet speed); Meriam & Kraige 2012, §6/8 (kinetic energy of rotation).
        """
        moving = train.moving_shafts
        index = {s: k for k, s in enumerate(moving)}
        j = np.zeros((len(moving), len(moving)))
        for shaft, value in self.shafts.items():
            if shaft not in index:
                raise DynamicsError(f"inertias: {shaft!r} is not a moving shaft of the train; shafts are "
                                    f"{', '.join(repr(s) for s in moving)}.")
            j[index[shaft], index[shaft]] += value
        sets = {s.name: s for s in train.planetary_sets}
        for planet in self.planets:
            if planet.set_name not in sets:
                raise DynamicsError(f"inertias: planets of {planet.set_name!r}: no such planetary set; sets are "
                                    f"{', '.join(repr(s) for s in sets) or 'none'}.")
            p = sets[planet.set_name]
            rho = _spin_ratio(planet, p)
            v = np.zeros(len(moving))  # ω_p = v · ω
            for shaft, coef in ((p.sun, rho), (p.carrier, 1.0 - rho)):
                if shaft in index:
                    v[index[shaft]] += coef
            j += planet.count * planet.inertia * np.outer(v, v)
            if p.carrier in index:
                j[index[p.carrier], index[p.carrier]] += planet.count * planet.mass * planet.orbit_radius ** 2
        return j
