"""Planet bodies that several planetary sets of a train share: one bearing load from all their meshes.

A train file describes a planet that meshes more gears than one set has as
several sets on one carrier.  A Wolfrom drive is a simple set (sun, planet,
ring 1) and a set with two rings (ring 1, stepped planet, ring 2); a Ravigneaux
set is a double-planet set and a simple set whose long planet meshes the same
ring.  Each set's :class:`~epicyclic.geometry.forces.PlanetaryForces` carries
its own share of the torques, so the bearing load of one set alone is not the
load of the planet.  :func:`share_planets` finds the bodies that are one and
sums the tooth forces on them.

Two sets share a planet gear when they have the same carrier shaft and a
central gear on the same shaft with the same tooth count and kind (internal or
external), meshed by a planet gear of the same tooth count at the same centre
distance, with the same number of planets.  Planet k of one set is then planet
k of the other (each set places its planets from the same carrier angle, so
the forces of the other set are turned onto the first set's pin).

At the shared mesh the sets' tangential forces add (superposition of the
torques on the one central gear); its radial and axial forces follow from the
sum, F_r = |F_t| tan α_wt and F_a = |F_t| tan β_w, pushing the planet away
from the pitch point.  The bearing load is the vector sum of the forces of all
meshes of the body, in the plane (see the module text of
:mod:`~epicyclic.geometry.forces` for what is not modelled: tilting of the pin
by wheels at different axial positions, the split between the bearings of one pin).

References
----------
Queitsch part I, eqs. (23)–(26), (30) and Bild 6 (forces on the planet; F_r = F_t tan α);
Müller 1998, ch. 2 (a compound train as coupled simple sets sharing members).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace

from .forces import MeshForce, PlanetaryForces, SharedPlanet, _cross
from .gear import MeshGeometry
from .set_geometry import SetGeometry

__all__ = ["share_planets"]

_TOLERANCE_MM = 1e-6


def _turn(v: tuple[float, float], angle: float) -> tuple[float, float]:
    c, s = math.cos(angle), math.sin(angle)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


def _contacts(forces: Mapping[str, PlanetaryForces], geometries: Mapping[str, SetGeometry]):
    """(set, slot, mesh, key) of every central mesh: slot is the body of the planet gear meshing it."""
    out = []
    for name, f in forces.items():
        g = geometries[name]
        names = g.planet_gear_names
        for port, mesh in (("sun", g.sun_mesh), ("ring", g.ring_mesh)):
            central, planet = g.gears[port], g.gears[names[0] if port == "sun" else names[-1]]
            slot = (0 if port == "sun" else 1) if g.kind == "double" else 0
            key = (f.members["carrier"][1], f.members[port][1], central.teeth, central.internal, planet.teeth,
                   f.planets)
            out.append((name, slot, mesh, key))
    return out


def _same(a, b) -> bool:
    (set_a, _, mesh_a, key_a), (set_b, _, mesh_b, key_b) = a, b
    return (set_a != set_b and key_a == key_b
            and abs(mesh_a.center_distance - mesh_b.center_distance) <= _TOLERANCE_MM
            and abs(mesh_a.rack.module - mesh_b.rack.module) <= 1e-12)


def share_planets(forces: Mapping[str, PlanetaryForces],
                  geometries: Mapping[str, SetGeometry]) -> dict[str, PlanetaryForces]:
    """The sets' forces with the bearing loads of planets that several sets share.

    Parameters
    ----------
    forces : mapping set name → PlanetaryForces
        From :func:`~epicyclic.geometry.forces.planetary_forces` of one solution.
    geometries : mapping set name → SetGeometry
        The geometry of each of these sets.

    Returns
    -------
    dict set name → PlanetaryForces
        Unchanged for a set that shares no planet.  For a set that does, the
        shared bodies' ``bearing_force``/``bearing_axial`` are those of the
        whole planet, ``shared_with`` names the other sets and ``shared`` holds
        the :class:`~epicyclic.geometry.forces.SharedPlanet` (all meshes).

    Examples
    --------
    A Wolfrom drive without losses (sun 27, planet 27/24, rings 81 and 78, m = 2 mm,
    3 planets, 5 N·m in, ratio 52): the carrier carries no torque, so the
    tangential forces on the planet cancel; the radial ones add (sun outward,
    both rings inward), tan 20° · 1000 · 5/3 · (51/81 + 52/78 − 1/27) = 763.9 N:

    >>> from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
    >>> from epicyclic.geometry import SetGeometry, planetary_forces
    >>> s = PlanetarySet.simple("S", sun="in", ring="r1", carrier="c", z_sun=27, z_planet=27, z_ring=81)
    >>> w = PlanetarySet.two_rings("W", first="r1", second="out", carrier="c", z_first=81,
    ...                            z_planet_first=27, z_planet_second=24, z_second=78)
    >>> sol = solve(GearTrain([s, w, Brake("B", "r1")]), OperatingPoint(
    ...     speeds={"in": 3000}, torques={"in": 5}, drives=["in"], loads=["out"]))
    >>> geo = {p.name: SetGeometry.create(p, module=2.0) for p in (s, w)}
    >>> shared = share_planets({n: planetary_forces(sol, n, g) for n, g in geo.items()}, geo)
    >>> round(shared["W"].bodies[0].bearing_load, 1), shared["W"].bodies[0].shared_with
    (763.9, ('S',))
    """
    contacts = _contacts(forces, geometries)
    parent = {(c[0], c[1]): (c[0], c[1]) for c in contacts}  # union-find over bodies (set, slot)
    mesh_group: dict[tuple[str, str], int] = {}  # (set, mesh name) -> shared mesh id

    def root(node):
        while parent[node] != node:
            node = parent[node]
        return node

    for i, a in enumerate(contacts):
        for b in contacts[i + 1:]:
            if _same(a, b):
                parent[root((b[0], b[1]))] = root((a[0], a[1]))
                group = mesh_group.get((a[0], a[2].name), mesh_group.get((b[0], b[2].name), i))
                mesh_group[(a[0], a[2].name)] = mesh_group[(b[0], b[2].name)] = group
    groups: dict[tuple[str, int], list[tuple[str, int]]] = {}
    for node in parent:
        groups.setdefault(root(node), []).append(node)
    out = dict(forces)
    for members in groups.values():
        if len({s for s, _ in members}) < 2:
            continue
        members.sort(key=lambda node: list(forces).index(node[0]))
        for index in range(forces[members[0][0]].planets):
            _share_body(out, forces, geometries, members, index, mesh_group)
    return out


def _body_position(forces: PlanetaryForces, geometry: SetGeometry, slot: int, index: int) -> int:
    return index * (2 if geometry.kind == "double" else 1) + slot


def _share_body(out, forces, geometries, members, index, mesh_group) -> None:
    """Sum the meshes of planet ``index`` of the bodies ``members`` and write the result into ``out``."""
    bodies = [(s, _body_position(forces[s], geometries[s], slot, index)) for s, slot in members]
    first = forces[bodies[0][0]].bodies[bodies[0][1]]
    phi0 = math.atan2(first.center[1], first.center[0])
    turns = {}
    merged: dict[object, list[tuple[str, MeshForce]]] = {}
    for s, pos in bodies:
        body = forces[s].bodies[pos]
        turns[(s, pos)] = delta = phi0 - math.atan2(body.center[1], body.center[0])
        for m in body.meshes:
            turned = replace(m, point=_turn(m.point, delta), force_on_planet=_turn(m.force_on_planet, delta))
            merged.setdefault(mesh_group.get((s, m.mesh), (s, m.mesh)), []).append((s, turned))
    meshes = [_merge(parts, first.center, geometries) for parts in merged.values()]
    force = (sum(m.force_on_planet[0] for m in meshes), sum(m.force_on_planet[1] for m in meshes))
    axial = 0.0
    for m in meshes:  # same helix hand on every wheel: the thrust follows the circumferential force
        arm = (m.point[0] - first.center[0], m.point[1] - first.center[1])
        axial += math.copysign(m.axial, _cross(arm, m.force_on_planet))
    sets = tuple(dict.fromkeys(s for s, _ in bodies))
    gears = ", ".join(f"{s} {forces[s].bodies[pos].gear}" for s, pos in bodies)
    planet = SharedPlanet(sets=sets, index=index, gears=gears, angle=first.angle, center=first.center,
                          meshes=tuple(meshes), bearing_force=force, bearing_axial=abs(axial))
    for s, pos in bodies:
        body = out[s].bodies[pos]
        shared_body = replace(body, bearing_force=_turn(force, -turns[(s, pos)]), bearing_axial=abs(axial),
                              shared_with=tuple(x for x in sets if x != s))
        new_bodies = tuple(shared_body if k == pos else b for k, b in enumerate(out[s].bodies))
        shared = out[s].shared + ((planet,) if planet not in out[s].shared else ())
        out[s] = replace(out[s], bodies=new_bodies, shared=shared)


def _merge(parts: list[tuple[str, MeshForce]], center, geometries) -> MeshForce:
    """One mesh from the sets' shares of it (a single share is kept as it is, named ``set: mesh``)."""
    name = " = ".join(f"{s}: {m.mesh}" for s, m in parts)
    s0, m0 = parts[0]
    if len(parts) == 1:
        return replace(m0, mesh=name)
    mesh: MeshGeometry = geometries[s0].mesh(m0.mesh)
    arm = (m0.point[0] - center[0], m0.point[1] - center[1])
    length = math.hypot(*arm)
    u = (arm[0] / length, arm[1] / length)
    t = (-u[1], u[0])
    total = (sum(m.force_on_planet[0] for _, m in parts), sum(m.force_on_planet[1] for _, m in parts))
    ft = total[0] * t[0] + total[1] * t[1]  # the tangential forces add; the separating force follows from them
    fr = abs(ft) * math.tan(mesh.alpha_wt)
    fa = abs(ft) * math.tan(math.radians(mesh.operating_helix_angle))
    force = (ft * t[0] - fr * u[0], ft * t[1] - fr * u[1])
    return MeshForce(name, abs(ft), fr, fa, m0.point, force)
