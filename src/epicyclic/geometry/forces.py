"""Tooth forces, planet-bearing loads and carrier-pin forces of a solved planetary set.

From a :class:`~epicyclic.results.Solution` of the engine the port torques of
a set (``solution.elements[name].torques``: the torque each shaft exerts on
the set, N·m) are turned into forces on the planets, in the carrier frame
(x, y in mm, forces in N, planet k at carrier angle θ_k):

* tangential force at a mesh of a central gear G with operating pitch radius
  r_wG: ``F_t = 1000 |T_G| / (N r_wG)`` (Queitsch eqs. 23–25);
* radial (separating) force with the OPERATING transverse pressure angle:
  ``F_r = F_t tan α_wt`` (Queitsch eq. 30 with α_b for α_0);
* axial force of helical meshes ``F_a = F_t tan β_w`` (β_w helix angle at the
  operating pitch cylinder, ISO 21771);
* the planet bearing carries the vector sum of the mesh forces on its planet
  (tangential and radial components at each mesh's position); the carrier pin
  takes the opposite force.  A planet that several sets of a train share (a
  Wolfrom drive's stepped planet, a Ravigneaux set's long planet) is one body:
  :func:`~epicyclic.geometry.shared_planets.share_planets` adds the forces of
  all its meshes (:class:`SharedPlanet`).  With losses (η0 < 1) the mesh
  forces' moments on a planet do not cancel: the remainder is the friction
  moment that the pin (bearing) passes to the carrier, so the carrier torque
  from the pin forces plus these moments equals the solver's carrier torque.

Nominal forces assume equal load sharing (each planet 1/N).  The design
values multiply them by the load-sharing factor K_γ (user-given, or the
default by number of planets of :func:`default_load_sharing`).

What is modelled: the in-plane forces at the operating pitch points and
their resultant on the pin, the *bearing load*.  The gear wheels of a stepped
planet sit at different axial positions; their forces also tilt the pin, and
how the resultant divides between the bearings of one pin depends on where the
wheels and bearings sit along it: neither is computed (size each bearing from
the resultant and the planet's layout).  The net axial force assumes the same
helix hand on every wheel of a planet (the usual choice, so that the thrusts
oppose): F_a = |Σ ± F_a,i|, the sign of each mesh from the sense of its
circumferential force on the planet.

References
----------
Queitsch part I, eqs. (23)–(26), (30) and Bild 6 (forces on planet and carrier);
ISO 21771:2007 (α_wt, β_w); Drivetrain Hub, *Strength / Force Analysis*
(F_t = 2T/d_w, F_r = F_t tan α_wt, F_a = F_t tan β).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from ._render import html_table, text_table
from .errors import GeometryError, expect_type
from .gear import MeshGeometry
from .load_sharing import default_load_sharing, tabulated_load_sharing
from .set_geometry import SetGeometry

__all__ = ["MeshForce", "PlanetLoad", "PlanetaryForces", "planetary_forces", "default_load_sharing",
           "mesh_forces"]

Vec = tuple[float, float]


def _load_sharing(given, planets: int) -> tuple[object, str]:
    """(K_γ, where it comes from): a given number beside the IEC 61400-4 table value, a table row, or ABS."""
    if isinstance(given, str):
        table = tabulated_load_sharing(planets, given)
        return table.value, table.source
    try:
        table_note = f"; {tabulated_load_sharing(planets).source}: {tabulated_load_sharing(planets).value:g}"
    except GeometryError:
        table_note = ""
    if given is None:
        return default_load_sharing(planets), "ABS rules default" + table_note
    return given, "given" + table_note


def mesh_forces(torque: float, pitch_diameter: float, mesh: MeshGeometry) -> tuple[float, float, float]:
    """(F_t, F_r, F_a) in N of a gear with ``torque`` (N·m) on operating pitch diameter ``pitch_diameter`` (mm).

    F_t = 2000 |T| / d_w, F_r = F_t tan α_wt, F_a = F_t tan β_w (all ≥ 0; the
    directions follow from the gear's side of the mesh).

    Parameters
    ----------
    torque : float
        Torque on the gear, N·m (its sign is ignored); per planet where a set
        shares it among planets.
    pitch_diameter : float
        The gear's operating pitch diameter d_w, mm (> 0).
    mesh : MeshGeometry
        The mesh (gives α_wt and β_w).

    Returns
    -------
    tuple of float
        (F_t, F_r, F_a), N.

    Raises
    ------
    GeometryError
        ``pitch_diameter`` ≤ 0.

    References
    ----------
    Queitsch part I, eqs. (23)–(25) and (30); ISO 21771:2007 (d_w, α_wt, β_w at the
    operating pitch cylinder).

    Examples
    --------
    Drivetrain Hub force example (z = 15/45, m_n = 2.5, β = 20°, a = 80 mm, T = 100 N·m):
    F_t = 5000 N, F_r = 1971.1 N (α_wt = 21.515°); the source takes F_a = F_t tan β = 1819.9 N,
    here F_a = F_t tan β_w with β_w = 20.04° at the operating pitch cylinder:

    >>> from epicyclic.geometry.gear import BasicRack, MeshGeometry
    >>> mesh = MeshGeometry.at_center_distance(15, 45, BasicRack(2.5, helix_angle=20), 80.0)
    >>> [round(f, 1) for f in mesh_forces(100.0, mesh.operating_pitch_diameters[0], mesh)]
    [5000.0, 1971.1, 1824.1]
    """
    if pitch_diameter <= 0:
        raise GeometryError(f"mesh_forces: pitch_diameter must be > 0 mm, got {pitch_diameter!r}.")
    ft = 2000.0 * abs(torque) / pitch_diameter
    return ft, ft * math.tan(mesh.alpha_wt), ft * math.tan(math.radians(mesh.operating_helix_angle))


@dataclass(frozen=True)
class MeshForce:
    """Force at one mesh on one planet gear (nominal, equal load sharing).

    Attributes
    ----------
    mesh : str
        Mesh name (``sun-planet``, ``planet-ring``, ``first-planet_first`` for two rings, ...).
    tangential, radial, axial, normal : float
        Magnitudes, N.
    point : (float, float)
        Pitch point in the carrier frame, mm.
    force_on_planet : (float, float)
        In-plane force vector on the planet gear, N (the central gear or the
        other planet gets the opposite).
    """

    mesh: str
    tangential: float
    radial: float
    axial: float
    point: Vec
    force_on_planet: Vec

    @property
    def normal(self) -> float:
        """|F_n| = sqrt(F_t² + F_r² + F_a²), N."""
        return math.hypot(self.tangential, self.radial, self.axial)


@dataclass(frozen=True)
class PlanetLoad:
    """Loads of one planet body (one pin): its meshes, bearing and pin force.

    Attributes
    ----------
    index : int
        Planet (cluster) number, 0-based.
    gear : str
        Planet gear name(s) on this pin.
    angle : float
        Carrier angle of the pin, degrees.
    center : (float, float)
        Pin position, mm.
    meshes : tuple of MeshForce
    bearing_force : (float, float)
        Force the planet exerts on its pin = Σ mesh forces on the planet, N.
        The pin exerts the opposite on the planet (equilibrium).
    friction_moment : float
        Moment the pin passes to the planet to balance the mesh forces, N·m
        (0 without losses; the lumped mesh loss otherwise).
    bearing_axial : float
        Net axial force on the bearing, N, with the mesh thrusts opposing
        (one planet gear meshing sun and ring; 0 for spur gears).
    shared_with : tuple of str
        Other sets of the train that share this planet body (empty unless
        :func:`~epicyclic.geometry.shared_planets.share_planets` found some).
        Then ``bearing_force`` and ``bearing_axial`` are those of the whole body,
        the vector sum over the meshes of all these sets (:class:`SharedPlanet`);
        ``meshes`` stay this set's.
    """

    index: int
    gear: str
    angle: float
    center: Vec
    meshes: tuple[MeshForce, ...]
    bearing_force: Vec
    friction_moment: float
    bearing_axial: float
    shared_with: tuple[str, ...] = ()

    @property
    def bearing_load(self) -> float:
        """Radial bearing load |F_bearing|, N."""
        return math.hypot(*self.bearing_force)

    @property
    def pin_force(self) -> Vec:
        """Force of the carrier pin on the planet, N (= −bearing_force)."""
        return (-self.bearing_force[0], -self.bearing_force[1])


@dataclass(frozen=True)
class SharedPlanet:
    """One planet body that several sets of a train share, with the forces of all its meshes.

    A train describes a Wolfrom drive as a simple set (sun, planet, ring 1) and
    a set with two rings (ring 1, stepped planet, ring 2) on one carrier: the
    planet gear meshing ring 1 is the same gear in both.  Each set's forces
    carry its share of the torques; the body carries them all.

    Attributes
    ----------
    sets : tuple of str
        The sets sharing the body; the first set's frame is used.
    index : int
        Planet number (0-based) in each set.
    gears : str
        The body's gears, per set (``S: planet = W: planet_first; W: planet_second``).
    angle : float
        Carrier angle of the pin in the first set's frame, degrees.
    center : (float, float)
        Pin position, mm.
    meshes : tuple of MeshForce
        Every mesh of the body once, named ``set: mesh``.  A mesh that two sets
        share (the planet gear with ring 1) appears once with the sum of the
        sets' tangential forces and the radial and axial forces of that sum
        (F_r = |F_t| tan α_wt, F_a = |F_t| tan β_w).
    bearing_force : (float, float)
        Σ of the mesh forces on the body, N (the force on its pin).
    bearing_axial : float
        Net axial force (same helix hand on every wheel), N.
    """

    sets: tuple[str, ...]
    index: int
    gears: str
    angle: float
    center: Vec
    meshes: tuple[MeshForce, ...]
    bearing_force: Vec
    bearing_axial: float

    @property
    def bearing_load(self) -> float:
        """Radial bearing load |F_bearing|, N."""
        return math.hypot(*self.bearing_force)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data of the planet body that several sets share (N, mm, degrees).

        Returns
        -------
        dict
            ``sets``, ``index``, ``gears``, ``angle`` (deg), ``center`` (mm),
            ``bearing_force`` (N, x and y), ``bearing_load`` (N), ``bearing_axial`` (N) and
            ``meshes`` (each mesh's forces in N).
        """
        return {"sets": list(self.sets), "index": self.index, "gears": self.gears, "angle": self.angle,
                "center": list(self.center), "bearing_force": list(self.bearing_force),
                "bearing_load": self.bearing_load, "bearing_axial": self.bearing_axial,
                "meshes": [_mesh_dict(m) for m in self.meshes]}

    def rows(self, factor: float = 1.0) -> list[list[object]]:
        """Table rows (forces × ``factor``): planet, angle, mesh, F_t, F_r, F_a, bearing."""
        return [[self.index + 1, f"{self.angle:.2f}", m.mesh, m.tangential * factor, m.radial * factor,
                 m.axial * factor, self.bearing_load * factor] for m in self.meshes]


def _mesh_dict(m: MeshForce) -> dict[str, Any]:
    return {"mesh": m.mesh, "tangential": m.tangential, "radial": m.radial, "axial": m.axial,
            "normal": m.normal, "point": list(m.point), "force_on_planet": list(m.force_on_planet)}


@dataclass(frozen=True)
class PlanetaryForces:
    """Forces of a planetary set at a solved operating point.

    Attributes
    ----------
    set_name : str
    planets : int
    load_sharing_factor : float
        K_γ applied to the design values.
    torques : mapping port → N·m
        The solver's port torques (sun, ring, carrier).
    bodies : tuple of PlanetLoad
        One per pin (two per cluster for a double-planet set).
    central_forces : mapping {"sun", "ring", "carrier"} → (Fx, Fy)
        Net in-plane force of the planets on each central member and on the
        carrier, N (zero for equally spaced planets).
    carrier_torque_from_forces : float
        Carrier torque rebuilt from pin forces × radii plus friction moments, N·m.
    members : mapping port → (gear, shaft)
        What each port is in this set: its gear's name (``first``/``second``
        for two rings or two suns, :func:`~epicyclic.geometry.set_geometry.gear_label`)
        and the train's shaft.
    shared : tuple of SharedPlanet
        The planet bodies this set shares with other sets (see :attr:`PlanetLoad.shared_with`).
    """

    set_name: str
    planets: int
    load_sharing_factor: float
    torques: Mapping[str, float]
    bodies: tuple[PlanetLoad, ...]
    central_forces: Mapping[str, Vec]
    carrier_torque_from_forces: float
    members: Mapping[str, tuple[str, str]] = field(default_factory=lambda: MappingProxyType({}))
    shared: tuple[SharedPlanet, ...] = ()
    load_sharing_source: str = ""

    @property
    def housing_torque(self) -> float:
        """T_sun + T_ring + T_carrier, N·m: zero, so no reaction reaches the housing in three-shaft operation."""
        return sum(self.torques.values())

    @property
    def design_tangential(self) -> dict[str, float]:
        """Largest tangential force per mesh × K_γ, N."""
        out: dict[str, float] = {}
        for body in self.bodies:
            for m in body.meshes:
                out[m.mesh] = max(out.get(m.mesh, 0.0), m.tangential * self.load_sharing_factor)
        return out

    @property
    def design_bearing_load(self) -> float:
        """Largest planet bearing load × K_γ, N (of the whole body where planets are shared)."""
        return max(b.bearing_load for b in self.bodies) * self.load_sharing_factor

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: torques, every planet body's mesh and bearing forces, design loads.

        Forces in N, lengths in mm, torques in N·m, angles in degrees (stated under
        ``units``).

        Returns
        -------
        dict
            ``set``, ``planets``, ``load_sharing_factor``, ``units``, ``torques`` (port → N·m),
            ``members`` (port → ``{gear, shaft}``: ``first``/``second`` for two rings or two
            suns), ``carrier_torque_from_forces``, ``housing_torque``, ``central_forces``,
            ``design_tangential``, ``design_bearing_load``, ``bodies`` (one per planet: angle,
            centre, bearing force/load/axial, friction moment, meshes) and
            ``shared_planets`` (:meth:`SharedPlanet.to_dict`).
        """
        return {
            "set": self.set_name,
            "planets": self.planets,
            "load_sharing_factor": self.load_sharing_factor,
            "load_sharing_source": self.load_sharing_source,
            "units": {"force": "N", "length": "mm", "torque": "N*m", "angle": "deg"},
            "torques": dict(self.torques),
            "members": {port: {"gear": gear, "shaft": shaft} for port, (gear, shaft) in self.members.items()},
            "carrier_torque_from_forces": self.carrier_torque_from_forces,
            "housing_torque": self.housing_torque,
            "central_forces": {k: list(v) for k, v in self.central_forces.items()},
            "design_tangential": self.design_tangential,
            "design_bearing_load": self.design_bearing_load,
            "bodies": [
                {
                    "index": b.index, "gear": b.gear, "angle": b.angle, "center": list(b.center),
                    "bearing_force": list(b.bearing_force), "bearing_load": b.bearing_load,
                    "bearing_axial": b.bearing_axial, "friction_moment": b.friction_moment,
                    "shared_with": list(b.shared_with),
                    "meshes": [_mesh_dict(m) for m in b.meshes],
                }
                for b in self.bodies
            ],
            "shared_planets": [p.to_dict() for p in self.shared],
        }

    def _rows(self) -> list[list[object]]:
        k = self.load_sharing_factor
        return [
            [b.index + 1, b.gear, f"{b.angle:.2f}", m.mesh, m.tangential * k, m.radial * k, m.axial * k,
             b.bearing_load * k]
            for b in self.bodies for m in b.meshes
        ]

    _HEAD = ["planet", "gear", "angle [deg]", "mesh", "F_t [N]", "F_r [N]", "F_a [N]", "bearing [N]"]

    def _port(self, port: str) -> str:
        gear, shaft = self.members.get(port, (port, ""))
        return f"{gear} ({shaft})" if shaft and shaft != gear else gear

    _SHARED_HEAD = ["planet", "angle [deg]", "mesh", "F_t [N]", "F_r [N]", "F_a [N]", "bearing [N]"]

    def _shared_title(self) -> str:
        others = sorted({name for p in self.shared for name in p.sets if name != self.set_name})
        return (f"planets shared with set {', '.join(map(repr, others))} ({self.shared[0].gears}): every mesh of "
                f"each planet; its bearing carries their vector sum (x K_gamma)")

    def _shared_rows(self) -> list[list[object]]:
        return [row for p in self.shared for row in p.rows(self.load_sharing_factor)]

    def table(self) -> str:
        """Design forces (× K_γ) per planet and mesh, N; every mesh of planets shared with other sets."""
        source = f" ({self.load_sharing_source})" if self.load_sharing_source else ""
        title = (f"forces of {self.set_name!r}: {self.planets} planets, K_gamma = {self.load_sharing_factor:g}{source} "
                 f"(torques {', '.join(f'{self._port(p)} {t:.5g} N*m' for p, t in self.torques.items())})")
        text = text_table(self._HEAD, self._rows(), title=title)
        if self.shared:
            text += "\n\n" + text_table(self._SHARED_HEAD, self._shared_rows(), title=self._shared_title())
        return text

    def _repr_html_(self) -> str:
        out = html_table(self._HEAD, self._rows(), title=f"forces of {self.set_name} (N, K_gamma applied)")
        if self.shared:
            out += html_table(self._SHARED_HEAD, self._shared_rows(), title=self._shared_title())
        return out

    def __repr__(self) -> str:
        dt = ", ".join(f"{m} {f:.1f} N" for m, f in self.design_tangential.items())
        return (f"PlanetaryForces({self.set_name!r}, N={self.planets}, K_gamma={self.load_sharing_factor:g}, "
                f"F_t design: {dt}, bearing {self.design_bearing_load:.1f} N)")


def _rot(theta: float) -> tuple[Vec, Vec]:
    c, s = math.cos(theta), math.sin(theta)
    return (c, s), (-s, c)


def _cross(a: Vec, b: Vec) -> float:
    return a[0] * b[1] - a[1] * b[0]


def _central_mesh(torque: float, n: int, mesh: MeshGeometry, planet_first: bool, theta: float,
                  outward: bool) -> tuple[MeshForce, float]:
    """Mesh of a central gear (centre at origin) with a planet gear whose pitch point lies at angle theta.

    Returns the force on the planet and the signed tangential component f on the
    central gear along e_t (f·r_w = −T/N).
    """
    d_w = mesh.operating_pitch_diameters
    r_central = (d_w[1] if planet_first else d_w[0]) / 2.0
    e_r, e_t = _rot(theta)
    f = -1000.0 * torque / (n * r_central)
    ft, fr, fa = abs(f), abs(f) * math.tan(mesh.alpha_wt), abs(f) * math.tan(math.radians(mesh.operating_helix_angle))
    sign = 1.0 if outward else -1.0
    force = (-f * e_t[0] + sign * fr * e_r[0], -f * e_t[1] + sign * fr * e_r[1])
    point = (r_central * e_r[0], r_central * e_r[1])
    return MeshForce(mesh.name, ft, fr, fa, point, force), f


def planetary_forces(
    solution,
    set_name: str,
    geometry: SetGeometry,
    *,
    load_sharing: float | None = None,
    angles: Sequence[float] | None = None,
) -> PlanetaryForces:
    """Tooth, bearing and pin forces of planetary set ``set_name`` in ``solution``.

    Parameters
    ----------
    solution : Solution
        From :func:`epicyclic.solve`; ``solution.elements[set_name].torques``
        are the port torques in N·m.
    set_name : str
    geometry : SetGeometry
        Geometry of that set (same tooth counts).
    load_sharing : float or str, optional
        K_γ ≥ 1, or a mounting of :func:`~epicyclic.geometry.load_sharing.tabulated_load_sharing`
        (``"floating_sun"``, ``"flexible_pins"``, ``"abs"``) for the tabulated value; default
        ``geometry.load_sharing``, else :func:`default_load_sharing` of the number of planets.
        The result's ``load_sharing_source`` says where it came from, beside the IEC 61400-4 value.
    angles : sequence of float, optional
        Carrier angles of the planets, degrees (default equally spaced; give the
        angles of :func:`~epicyclic.geometry.fitting.check_assembly` for unequal spacing).

    Raises
    ------
    GeometryError
        Unknown set, a set that is not planetary, geometry of another set, K_γ < 1.

    References
    ----------
    Queitsch part I, eqs. (23)–(26), (30) (F_t = 2000 M/d per planet).
    """
    if not (hasattr(solution, "elements") and hasattr(solution, "train")):
        raise GeometryError(f"planetary_forces: solution must be a Solution, got a {type(solution).__name__}; "
                            "give solve(train, operating_point) first.")
    expect_type(set_name, str, "planetary_forces", "set_name", "give the name of the set in the train, e.g. 'P'")
    expect_type(geometry, SetGeometry, "planetary_forces", "geometry", "make one with SetGeometry.create(set, module=...)")
    try:
        state = solution.elements[set_name]
    except KeyError:
        known = ", ".join(repr(k) for k in solution.elements)
        raise GeometryError(f"planetary_forces: the solution has no element {set_name!r}; it has {known}.") from None
    if state.kind != "planetary set":
        raise GeometryError(f"planetary_forces: element {set_name!r} is a {state.kind}, not a planetary set.")
    pset = geometry.planetary_set
    element = next((e for e in solution.train.elements if getattr(e, "name", None) == set_name), None)
    if element is not None and (element.teeth != pset.teeth):
        raise GeometryError(
            f"planetary_forces: geometry is for teeth {pset.teeth}, but set {set_name!r} in the train has "
            f"{element.teeth}; build SetGeometry from the same PlanetarySet."
        )
    n = pset.planets if angles is None else len(angles)
    if n < 1:
        raise GeometryError("planetary_forces: at least one planet angle is needed.")
    if angles is None:
        angles = [360.0 * i / n for i in range(n)]
    if load_sharing is None:
        load_sharing = geometry.load_sharing
    k, source = _load_sharing(load_sharing, n)
    if isinstance(k, bool) or not isinstance(k, (int, float)) or not math.isfinite(k) or k < 1.0:
        raise GeometryError(f"planetary_forces: load_sharing (K_gamma) must be a number >= 1, got {load_sharing!r}.")

    t_sun, t_ring, t_carrier = (state.torques[p] for p in ("sun", "ring", "carrier"))
    names = tuple(geometry.gear_label(g) for g in geometry.planet_gear_names)
    sun_mesh, ring_mesh = geometry.sun_mesh, geometry.ring_mesh
    ring_internal = ring_mesh.internal
    sun_internal = geometry.gears["sun"].internal  # the first ring of a Wolfrom set
    bodies: list[PlanetLoad] = []
    sums = {"sun": [0.0, 0.0], "ring": [0.0, 0.0], "carrier": [0.0, 0.0]}
    carrier_torque = 0.0

    def add_body(index, gear, theta, centre, meshes, arms):
        nonlocal carrier_torque
        fx = sum(m.force_on_planet[0] for m in meshes)
        fy = sum(m.force_on_planet[1] for m in meshes)
        moment = sum(_cross(arm, m.force_on_planet) for arm, m in zip(arms, meshes))  # N·mm
        friction = -moment / 1000.0
        axial = abs(meshes[0].axial - meshes[-1].axial) if len(meshes) > 1 else meshes[0].axial
        bodies.append(PlanetLoad(index, gear, math.degrees(theta), centre, tuple(meshes), (fx, fy), friction, axial))
        sums["carrier"][0] += fx
        sums["carrier"][1] += fy
        carrier_torque += friction - _cross(centre, (fx, fy)) / 1000.0

    for j, angle in enumerate(angles):
        theta = math.radians(angle)
        sun_force, _ = _central_mesh(t_sun, n, sun_mesh, sun_internal, theta, outward=not sun_internal)
        sums["sun"][0] -= sun_force.force_on_planet[0]
        sums["sun"][1] -= sun_force.force_on_planet[1]
        if geometry.kind != "double":
            a = geometry.carrier_radius
            e_r, _ = _rot(theta)
            centre = (a * e_r[0], a * e_r[1])
            ring_force, _ = _central_mesh(t_ring, n, ring_mesh, True, theta, outward=not ring_internal)
            sums["ring"][0] -= ring_force.force_on_planet[0]
            sums["ring"][1] -= ring_force.force_on_planet[1]
            arms = [(m.point[0] - centre[0], m.point[1] - centre[1]) for m in (sun_force, ring_force)]
            add_body(j, "+".join(names), theta, centre, [sun_force, ring_force], arms)
            continue
        # double planets: planet1 at (a1, θ), planet2 at (a2, θ + γ)
        m1, m12, m2 = geometry.meshes
        a1, a12, a2 = m1.center_distance, m12.center_distance, m2.center_distance
        gamma = math.acos(max(-1.0, min(1.0, (a1 * a1 + a2 * a2 - a12 * a12) / (2 * a1 * a2))))
        c1 = (a1 * math.cos(theta), a1 * math.sin(theta))
        c2 = (a2 * math.cos(theta + gamma), a2 * math.sin(theta + gamma))
        ring_force, _ = _central_mesh(t_ring, n, m2, True, theta + gamma, outward=False)
        sums["ring"][0] -= ring_force.force_on_planet[0]
        sums["ring"][1] -= ring_force.force_on_planet[1]
        u = ((c2[0] - c1[0]) / a12, (c2[1] - c1[1]) / a12)
        t = (-u[1], u[0])
        r1, r2 = (d / 2.0 for d in m12.operating_pitch_diameters)
        point = (c1[0] + r1 * u[0], c1[1] + r1 * u[1])
        arm_ring = (ring_force.point[0] - c2[0], ring_force.point[1] - c2[1])
        # planet 2 balanced: tangential force of planet 1 on planet 2 cancels the ring's moment
        f12 = _cross(arm_ring, ring_force.force_on_planet) / r2
        ft, fr = abs(f12), abs(f12) * math.tan(m12.alpha_wt)
        fa = ft * math.tan(math.radians(m12.operating_helix_angle))
        on2 = (f12 * t[0] + fr * u[0], f12 * t[1] + fr * u[1])
        mesh_on2 = MeshForce(m12.name, ft, fr, fa, point, on2)
        mesh_on1 = MeshForce(m12.name, ft, fr, fa, point, (-on2[0], -on2[1]))
        arm_sun = (sun_force.point[0] - c1[0], sun_force.point[1] - c1[1])
        arm12_1 = (point[0] - c1[0], point[1] - c1[1])
        arm12_2 = (point[0] - c2[0], point[1] - c2[1])
        add_body(j, names[0], theta, c1, [sun_force, mesh_on1], [arm_sun, arm12_1])
        add_body(j, names[1], theta + gamma, c2, [mesh_on2, ring_force], [arm12_2, arm_ring])

    members = {port: (geometry.gear_label(port), shaft) for port, shaft in zip(("sun", "ring", "carrier"),
                                                                                 pset.shafts)}
    if element is not None:  # the train's shafts (geometry may be built from a set with other shaft names)
        members = {port: (gear, shaft) for (port, (gear, _)), shaft in zip(members.items(), element.shafts)}
    return PlanetaryForces(
        set_name, n, float(k), MappingProxyType(dict(state.torques)), tuple(bodies),
        MappingProxyType({key: (v[0], v[1]) for key, v in sums.items()}), carrier_torque,
        MappingProxyType(members), load_sharing_source=source,
    )
