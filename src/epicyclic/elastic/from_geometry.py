"""A lumped model of a simple or stepped planetary set from its gear geometry, with stated (refusable) defaults.

What the geometry decides:

* radii: base radii d_b/2 of sun, planet and ring; the carrier's u coordinate at the centre
  distance a_w; pressure angles: the working transverse α_wt of each mesh;
* mesh stiffness k = c_γα b (ISO 6336-1, 9.3: c' from the virtual tooth numbers and profile
  shifts, C_M = 0.8 solid blanks, C_R = 1, C_B from the basic rack, the line load taken ≥ 100 N/mm;
  c_γα = c' (0.75 ε_α + 0.25)), b the mesh's face width;
* masses and inertias of steel (7850 kg/m³) discs: sun and planet solid discs of the mean
  diameter (d_a + d_f)/2 and their face width (a stepped planet: both gears on one body); the ring an
  annulus from its root diameter out to a rim of 3 m_n; the carrier a solid disc of diameter 2 a_w
  and the (sun-side) planet face width.

What the defaults say (each default taken is listed in :attr:`ElasticSpec.defaults_taken`'s
result; ``refuse_defaults`` makes a missing value an error): planet bearing and pin 1e8 N/m,
translational supports of sun, ring and carrier 1e8 N/m, ring torsion (the held member) 1e9 N/m at
its base radius, sun and carrier torsion 0 (free: the rigid-body mode) — the magnitudes of
Lin & Parker 1999, Table 1.

References
----------
ISO 6336-1:2006, 9.3 (c', c_γα); J. Lin, R. G. Parker, J. Vib. Acoust. 121 (1999) 316–321, Table 1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..geometry.set_geometry import SetGeometry
from .errors import ElasticError, non_negative, positive
from .lumped import Body, PlanetaryLumpedModel, equally_spaced
from .stiffness import lumped_mesh_stiffness, mesh_stiffness, single_stiffness

__all__ = ["ElasticSpec", "lumped_model", "DEFAULTS"]

#: Default values (SI) and what they mean.
DEFAULTS = {
    "planet_bearing": (1e8, "planet bearing and pin 1e8 N/m (Lin & Parker 1999, Table 1)"),
    "sun_support": (1e8, "sun support 1e8 N/m"),
    "ring_support": (1e8, "ring support 1e8 N/m"),
    "carrier_support": (1e8, "carrier support 1e8 N/m"),
    "sun_torsion": (0.0, "sun torsion 0 (free)"),
    "carrier_torsion": (0.0, "carrier torsion 0 (free)"),
    "ring_torsion": (None, "ring torsion 1e9 N/m at its base radius (held; Lin & Parker 1999)"),
    "sun_mesh": (None, "sun mesh c_gamma_alpha b (ISO 6336-1, 9.3)"),
    "ring_mesh": (None, "ring mesh c_gamma_alpha b (ISO 6336-1, 9.3)"),
    "density": (7850.0, "steel 7850 kg/m3, gears and carrier as discs"),
}


@dataclass(frozen=True)
class ElasticSpec:
    """The ``[elastic]`` inputs of a set (SI units; None: the default of :data:`DEFAULTS`).

    Attributes
    ----------
    sun_mesh, ring_mesh, planet_bearing : float or None
        N/m.
    sun_support, ring_support, carrier_support : float or None
        Translational support stiffness, N/m (0 = floating).
    sun_torsion, ring_torsion, carrier_torsion : float or None
        N m/rad.
    density : float or None
        kg/m³.
    masses : dict
        Optional ``{"sun": (mass kg, inertia kg m²), ...}`` overriding the discs.
    planet_angles : tuple of float or None
        Degrees (default equally spaced).
    refuse_defaults : bool
        A value left to a default is an error.
    """

    sun_mesh: float | None = None
    ring_mesh: float | None = None
    planet_bearing: float | None = None
    sun_support: float | None = None
    ring_support: float | None = None
    carrier_support: float | None = None
    sun_torsion: float | None = None
    ring_torsion: float | None = None
    carrier_torsion: float | None = None
    density: float | None = None
    masses: dict = field(default_factory=dict)
    planet_angles: tuple[float, ...] | None = None
    refuse_defaults: bool = False

    def __post_init__(self) -> None:
        for key in DEFAULTS:
            value = getattr(self, key)
            if value is not None:
                check = positive if key in ("sun_mesh", "ring_mesh", "planet_bearing", "density") else non_negative
                object.__setattr__(self, key, check(value, f"elastic.{key}"))
        for name, pair in self.masses.items():
            if name not in ("sun", "planet", "ring", "carrier") or len(pair) != 2:
                raise ElasticError(f"elastic.masses: {name!r} must be sun, planet, ring or carrier with "
                                   "(mass kg, inertia kg m2).")

    def value(self, key: str, taken: list[str]):
        """The given value of ``key``, or its default (recorded in ``taken``; refused if so asked)."""
        given = getattr(self, key)
        if given is not None:
            return given
        default, meaning = DEFAULTS[key]
        if self.refuse_defaults:
            raise ElasticError(f"elastic.{key} is missing and the file refuses defaults (defaults = \"refuse\"); "
                               f"give it (the default would be: {meaning}).")
        taken.append(meaning)
        return default


def _iso_mesh(geometry: SetGeometry, mesh) -> float:
    g1, g2 = mesh.gear1, mesh.gear2
    rack = g1.rack
    beta = rack.beta
    beta_b = math.atan(math.tan(beta) * math.cos(rack.alpha_t))
    zn = [g.teeth / (math.cos(beta_b) ** 2 * math.cos(beta)) for g in (g1, g2)]
    order = (0, 1) if (mesh.internal or g1.teeth <= g2.teeth) else (1, 0)
    xs = [g1.profile_shift, g2.profile_shift]
    c_prime = single_stiffness(zn[order[0]], zn[order[1]], xs[order[0]], xs[order[1]], beta, dedendum=rack.dedendum,
                               pressure_angle_deg=rack.pressure_angle, internal=mesh.internal)
    _, c_ga, _ = mesh_stiffness(c_prime, mesh.contact_ratio, 100.0)
    return lumped_mesh_stiffness(float(c_ga), geometry.mesh_face_width(mesh))


def lumped_model(geometry: SetGeometry, spec: ElasticSpec | None = None) -> tuple[PlanetaryLumpedModel, list[str]]:
    """The :class:`PlanetaryLumpedModel` of a simple set and the defaults it took.

    Parameters
    ----------
    geometry : SetGeometry
        A simple set, or a stepped set with a sun and an internal ring, with a face width.
    spec : ElasticSpec, optional

    Returns
    -------
    tuple
        (model, defaults taken, each a sentence).

    Raises
    ------
    ElasticError
        Not a simple or stepped sun-ring set, no face width, a default refused.

    References
    ----------
    ISO 6336-1:2006, 9.3; Lin & Parker 1999, Table 1 (module docstring).

    Examples
    --------
    >>> from epicyclic import PlanetarySet
    >>> p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=21, z_planet=43, z_ring=108, planets=3)
    >>> g = SetGeometry.create(p, module=1.75, x_sun=0.438, x_planet=0.0426, face_width=38.0)
    >>> model, taken = lumped_model(g)
    >>> model.planets, round(model.sun_mesh / 1e6), len(taken)
    (3, 724, 10)
    """
    spec = spec or ElasticSpec()
    teeth = geometry.planetary_set.teeth if isinstance(geometry, SetGeometry) else None
    stepped = teeth is not None and teeth.kind == "stepped" and teeth.ring_internal and not teeth.sun_internal
    if isinstance(geometry, SetGeometry) and geometry.kind == "double":
        return _double(geometry, spec)
    if not isinstance(geometry, SetGeometry) or not (geometry.kind == "simple" or stepped):
        raise ElasticError("elastic models are built for simple, double-planet and stepped sets with a sun and an "
                           "internal ring, with a geometry table; sets with two suns or two rings are not modelled "
                           "yet.")
    if geometry.face_width is None:
        raise ElasticError(f"{geometry.planetary_set.name}: the geometry table needs face_width (mm) for the mesh "
                           "stiffness and the masses.")
    taken: list[str] = []
    rho = spec.value("density", taken) * 1e-9                        # kg/mm³
    gears = geometry.gears
    m_n = geometry.rack.module
    widths = geometry.face_width

    def disc(outer: float, inner: float, width: float) -> tuple[float, float]:
        mass = rho * math.pi / 4 * (outer ** 2 - inner ** 2) * width
        return mass, mass * (outer ** 2 + inner ** 2) / 8 * 1e-6      # kg, kg m²

    sun, ring = gears["sun"], gears["ring"]
    planet, planet_ring = (gears["planet_sun"], gears["planet_ring"]) if stepped else (gears["planet"], None)
    mean = lambda g: (g.tip_diameter + g.root_diameter) / 2  # noqa: E731
    a_w = geometry.carrier_radius
    planet_key = "planet_sun" if stepped else "planet"
    planet_disc = disc(mean(planet), 0.0, widths[planet_key])
    if stepped:  # both gears of the stepped planet on one body
        second = disc(mean(planet_ring), 0.0, widths["planet_ring"])
        planet_disc = (planet_disc[0] + second[0], planet_disc[1] + second[1])
    ring_m = geometry.ring_module or m_n
    inertial = {"sun": disc(mean(sun), 0.0, widths["sun"]), "planet": planet_disc,
                "ring": disc(ring.root_diameter + 6 * ring_m, ring.root_diameter, widths["ring"]),
                "carrier": disc(2 * a_w, 0.0, widths[planet_key])}
    inertial.update({k: (float(v[0]), float(v[1])) for k, v in spec.masses.items()})
    radius = {"sun": sun.base_diameter / 2e3, "planet": planet.base_diameter / 2e3, "ring": ring.base_diameter / 2e3,
              "carrier": a_w / 1e3}
    body = {k: Body(inertial[k][0], inertial[k][1], radius[k]) for k in radius}
    k_s = spec.sun_mesh if spec.sun_mesh is not None else None
    k_r = spec.ring_mesh if spec.ring_mesh is not None else None
    if k_s is None:
        spec.value("sun_mesh", taken)
        k_s = _iso_mesh(geometry, geometry.sun_mesh)
    if k_r is None:
        spec.value("ring_mesh", taken)
        k_r = _iso_mesh(geometry, geometry.ring_mesh)
    ring_torsion = spec.value("ring_torsion", taken)
    if ring_torsion is None:
        ring_torsion = 1e9 * radius["ring"] ** 2
    planets = geometry.planetary_set.planets
    angles = equally_spaced(planets) if spec.planet_angles is None else tuple(math.radians(a) for a in
                                                                              spec.planet_angles)
    if len(angles) != planets:
        raise ElasticError(f"elastic.planet_angles: give one angle per planet ({planets}), got {len(angles)}.")
    model = PlanetaryLumpedModel(
        body["carrier"], body["ring"], body["sun"], body["planet"], angles, k_s, k_r,
        spec.value("planet_bearing", taken),
        supports={"sun": (spec.value("sun_support", taken), spec.value("sun_torsion", taken)),
                  "ring": (spec.value("ring_support", taken), ring_torsion),
                  "carrier": (spec.value("carrier_support", taken), spec.value("carrier_torsion", taken))},
        sun_pressure_angle=math.radians(geometry.sun_mesh.operating_pressure_angle),
        ring_pressure_angle=math.radians(geometry.ring_mesh.operating_pressure_angle),
        ring_planet_radius=planet_ring.base_diameter / 2e3 if stepped else None)
    return model, taken


def _double(geometry: SetGeometry, spec: ElasticSpec) -> tuple[PlanetaryLumpedModel, list[str]]:
    """A double-planet set: planet 1 (sun side) at the sun mesh's centre distance, planet 2 at the ring's,
    φ between them from the triangle of the three centre distances."""
    from .double import DoublePlanetModel

    taken: list[str] = []
    rho = spec.value("density", taken) * 1e-9
    widths, gears = geometry.face_width, geometry.gears
    if widths is None:
        raise ElasticError(f"{geometry.planetary_set.name}: the geometry table needs face_width (mm).")

    def disc(g, width: float) -> tuple[float, float]:
        d = (g.tip_diameter + g.root_diameter) / 2
        mass = rho * math.pi / 4 * d * d * width
        return mass, mass * d * d / 8 * 1e-6

    sun_mesh, middle, ring_mesh = geometry.meshes
    r_a, r_b, a_ab = sun_mesh.center_distance, ring_mesh.center_distance, middle.center_distance
    cos_phi = (r_a ** 2 + r_b ** 2 - a_ab ** 2) / (2 * r_a * r_b)
    if not -1.0 < cos_phi < 1.0:
        raise ElasticError(f"{geometry.planetary_set.name}: the centre distances {r_a:.4g}, {r_b:.4g}, {a_ab:.4g} mm "
                           "close no triangle; check the double-planet geometry (epicyclic fit).")
    ring = gears["ring"]
    m_n = geometry.rack.module
    inertial = {"sun": disc(gears["sun"], widths["sun"]), "planet": disc(gears["planet1"], widths["planet1"]),
                "outer": disc(gears["planet2"], widths["planet2"]),
                "ring": (rho * math.pi / 4 * ((ring.root_diameter + 6 * m_n) ** 2 - ring.root_diameter ** 2)
                         * widths["ring"], 0.0),
                "carrier": (rho * math.pi / 4 * (2 * r_b) ** 2 * widths["planet2"], 0.0)}
    ring_mass = inertial["ring"][0]
    inertial["ring"] = (ring_mass, ring_mass * ((ring.root_diameter + 6 * m_n) ** 2 + ring.root_diameter ** 2) / 8e6)
    carrier_mass = inertial["carrier"][0]
    inertial["carrier"] = (carrier_mass, carrier_mass * (2 * r_b) ** 2 / 8e6)
    inertial.update({k: (float(v[0]), float(v[1])) for k, v in spec.masses.items()})
    body = lambda key, radius: Body(inertial[key][0], inertial[key][1], radius)  # noqa: E731
    k = []
    for mesh, key in ((sun_mesh, "sun_mesh"), (ring_mesh, "ring_mesh")):
        given = getattr(spec, key)
        if given is None:
            spec.value(key, taken)
        k.append(given if given is not None else _iso_mesh(geometry, mesh))
    k_ab = _iso_mesh(geometry, middle)
    taken.append("planet-planet mesh c_gamma_alpha b (ISO 6336-1, 9.3)")
    ring_torsion = spec.value("ring_torsion", taken)
    if ring_torsion is None:
        ring_torsion = 1e9 * (ring.base_diameter / 2e3) ** 2
    planets = geometry.planetary_set.planets
    angles = equally_spaced(planets) if spec.planet_angles is None else tuple(math.radians(a) for a in
                                                                              spec.planet_angles)
    if len(angles) != planets:
        raise ElasticError(f"elastic.planet_angles: give one angle per planet pair ({planets}), got {len(angles)}.")
    model = DoublePlanetModel(
        body("carrier", r_a / 1e3), body("ring", ring.base_diameter / 2e3), body("sun", gears["sun"].base_diameter / 2e3),
        body("planet", gears["planet1"].base_diameter / 2e3), angles, k[0], k[1],
        spec.value("planet_bearing", taken),
        supports={"sun": (spec.value("sun_support", taken), spec.value("sun_torsion", taken)),
                  "ring": (spec.value("ring_support", taken), ring_torsion),
                  "carrier": (spec.value("carrier_support", taken), spec.value("carrier_torsion", taken))},
        sun_pressure_angle=math.radians(sun_mesh.operating_pressure_angle),
        ring_pressure_angle=math.radians(ring_mesh.operating_pressure_angle),
        outer_planet=body("outer", gears["planet2"].base_diameter / 2e3), planet_mesh=k_ab,
        planet_pressure_angle=math.radians(middle.operating_pressure_angle), outer_planet_radius=r_b / 1e3,
        outer_planet_angle=math.acos(cos_phi))
    return model, taken
