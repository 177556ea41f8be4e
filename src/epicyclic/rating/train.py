"""Rate every mesh of every planetary set and fixed-axis stage of a solved train.

:func:`mesh_inputs` builds, once per train, the :class:`~epicyclic.rating.mesh_rating.MeshInput`
of each mesh with geometry (the file's ``geometry`` tables: :class:`~epicyclic.geometry.SetGeometry`,
:class:`~epicyclic.geometry.StageGeometry`) and how its load follows from the element's port
torques and speeds; :func:`rate_solution` rates them at one operating point
(:class:`~epicyclic.results.Solution`) and :func:`rate_batch` over many at once (a
:class:`~epicyclic.solver.batch.BatchSolution`, one value per load case, vectorised).

Loads (the same as :mod:`epicyclic.geometry.forces`): a mesh of a central gear G carries
F_tw = 2000 |T_G| / (N d_wG) at its operating pitch circle (N planets, equal sharing; K_γ in the
rating), the planet–planet mesh of a double-planet set F_tw,ring r_w,ring / r_w,12 (planet 2 in
balance); a stage's mesh k is driven by |T_first| Π z2/z1 of the meshes before it.  The torque on
gear 1 is F_tw d_w1 / 2000.  Speeds are relative to the carrier: the sun's n_sun − n_carrier,
a planet's (n_G − n_carrier) z_G / z_planet.

References
----------
Queitsch part I, eqs. (23)–(26); ISO 6336-1:2019, 6.1 and 6.5.9 (planetary meshes);
Müller, *Die Umlaufgetriebe* (1998), ch. 4 (relative speeds of the planets).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace
from types import MappingProxyType

import numpy as np

from ..geometry.forces import _load_sharing  # K_γ of a set and where it comes from
from ..geometry.set_geometry import SetGeometry
from ..geometry.stage_geometry import StageGeometry
from .errors import RatingError
from .mesh_rating import MeshInput, rate_mesh
from .results import TrainRating
from .given_factors import GEAR_DEVIATIONS, MESH_FACTORS, unmatched_keys
from .spec import RatingSpec

__all__ = ["PlannedMesh", "mesh_inputs", "rate_batch", "rate_solution"]

Loads = Callable[[Mapping[str, np.ndarray], Mapping[str, np.ndarray]], tuple[np.ndarray, np.ndarray]]


@dataclass(frozen=True)
class PlannedMesh:
    """A mesh to rate and how its gear-1 torque and speed follow from its element's ports.

    Attributes
    ----------
    input : MeshInput
    loads : callable
        ``loads(torques, speeds)`` → (T1 per planet in N·m, n1 in 1/min) from the element's
        port torques (N·m) and speeds (1/min), scalars or arrays.
    """

    input: MeshInput
    loads: Loads


def _set_meshes(name: str, geometry: SetGeometry, spec: RatingSpec) -> list[PlannedMesh]:
    pset = geometry.planetary_set
    teeth = pset.teeth
    n = pset.planets
    k_gamma, k_source = _load_sharing(geometry.load_sharing, n)
    k_source = "given (geometry)" if k_source.startswith("given") else (
        "default" if k_source.startswith("ABS") else k_source)
    planets = geometry.planet_gear_names
    out = []
    for mesh in geometry.meshes:
        a, b = geometry.mesh_gears(mesh)
        first, second = (b, a) if geometry.gears[a].internal else (a, b)
        labels = (geometry.gear_label(first), geometry.gear_label(second))
        width = geometry.mesh_face_width(mesh)
        planet_index = 0 if first in planets else 1
        central = second if planet_index == 0 else first
        z = {g: geometry.gears[g].teeth for g in geometry.gears}
        if central in ("sun", "ring"):
            contacts = tuple(float(n) if g == central else 1.0 for g in (first, second))
        else:
            contacts = (1.0, 1.0)
        reversed_ = tuple(g in planets and teeth.kind != "stepped" for g in (first, second))
        d_w = mesh.operating_pitch_diameters
        d_w_central = d_w[0] if first == central else d_w[1]
        d_w1 = d_w[0]
        if central in ("sun", "ring"):
            def loads(torques, speeds, central=central, d_c=d_w_central, d_w1=d_w1, first=first, z=z):
                f_tw = 2000.0 * np.abs(torques[central]) / (n * d_c)
                relative = np.asarray(speeds[central]) - np.asarray(speeds["carrier"])
                n1 = relative if first == central else relative * z[central] / z[first]
                return f_tw * d_w1 / 2000.0, n1
        else:  # double planets: planet1-planet2
            ring_mesh = geometry.ring_mesh
            r_ring = ring_mesh.operating_pitch_diameters[0] / 2.0    # planet 2 in the ring mesh
            r_12 = d_w[1] / 2.0

            def loads(torques, speeds, r_ring=r_ring, r_12=r_12, d_w1=d_w1, ring_mesh=ring_mesh, z=z):
                f_ring = 2000.0 * np.abs(torques["ring"]) / (n * ring_mesh.operating_pitch_diameters[1])
                f_tw = f_ring * r_ring / r_12
                relative = np.asarray(speeds["sun"]) - np.asarray(speeds["carrier"])
                return f_tw * d_w1 / 2000.0, relative * z["sun"] / z[planets[0]]
        inp = MeshInput(name, mesh, width, labels, spec, contacts, reversed_, float(k_gamma),
                        n if central == "sun" else 0, planet_index if central == "sun" else -1, k_source)
        out.append(PlannedMesh(inp, loads))
    return out


def _stage_spec(spec: RatingSpec, element: str, mesh: str) -> RatingSpec:
    """``spec`` for a stage mesh: K_γ only where a table names the stage or the mesh (one load path else)."""
    given = spec.load_sharing
    if given is None:
        return spec
    named = isinstance(given, Mapping) and any(k in given for k in (f"{element}:{mesh}", mesh, element))
    if named:
        return spec
    rest = None if not isinstance(given, Mapping) else {k: v for k, v in given.items() if k != "all"} or None
    return replace(spec, load_sharing=rest)


def _stage_meshes(name: str, geometry: StageGeometry, spec: RatingSpec) -> list[PlannedMesh]:
    out = []
    torque_ratio, speed_ratio = 1.0, 1.0
    for k, ((z_drive, z_driven, _kind), mesh) in enumerate(zip(geometry.stage.meshes, geometry.meshes)):
        driving_first = geometry.driving_is_gear1(k)
        labels = ("driving", "driven") if driving_first else ("driven", "driving")
        d_w = mesh.operating_pitch_diameters
        d_drive = d_w[0] if driving_first else d_w[1]

        def loads(torques, speeds, tr=torque_ratio, sr=speed_ratio, d_drive=d_drive, d_w1=d_w[0],
                  driving_first=driving_first, z_drive=z_drive, z1=mesh.gear1.teeth):
            t_k = np.abs(torques["first"]) * tr
            f_tw = 2000.0 * t_k / d_drive
            n_k = np.asarray(speeds["first"]) * sr
            n1 = n_k if driving_first else n_k * z_drive / z1
            return f_tw * d_w1 / 2000.0, n1
        inp = MeshInput(name, mesh, geometry.mesh_face_width(k), labels,
                        _stage_spec(spec, name, mesh.name), load_sharing_source="one load path")
        out.append(PlannedMesh(inp, loads))
        torque_ratio *= z_driven / z_drive
        speed_ratio *= z_drive / z_driven
    return out


def mesh_inputs(geometry: Mapping[str, object], spec: RatingSpec) -> tuple[tuple[PlannedMesh, ...],
                                                                            Mapping[str, str]]:
    """Every mesh to rate of the elements in ``geometry``, and the elements skipped with the reason.

    Parameters
    ----------
    geometry : mapping element → SetGeometry or StageGeometry
        A train file's ``geometry``.
    spec : RatingSpec

    Returns
    -------
    tuple
        (planned meshes, {element: reason} of elements that could not be rated).

    Raises
    ------
    RatingError
        A required rating input is missing (material, roughness, viscosity).

    References
    ----------
    ISO 6336-1:2019, 6.5.9 (planetary gears).
    """
    planned: list[PlannedMesh] = []
    skipped: dict[str, str] = {}
    for name, shape in geometry.items():
        try:
            if isinstance(shape, SetGeometry):
                planned.extend(_set_meshes(name, shape, spec))
            elif isinstance(shape, StageGeometry):
                planned.extend(_stage_meshes(name, shape, spec))
            else:
                skipped[name] = f"no gear geometry ({type(shape).__name__})"
        except RatingError:
            raise
        except Exception as exc:  # a geometry error (no face width ...): reported, not hidden
            from ..errors import EpicyclicError

            if not isinstance(exc, EpicyclicError):
                raise
            raise RatingError(f"rating of {name!r}: {exc}") from None
    _check_keys(planned, spec)
    return tuple(planned), MappingProxyType(skipped)


def _check_keys(planned, spec: RatingSpec) -> None:
    """Every key of a per-mesh or per-gear table in ``[rating]`` names a mesh, a gear or an element."""
    meshes = {"all"} | {p.input.element for p in planned} | {p.input.name for p in planned} | {
        f"{p.input.element}:{p.input.name}" for p in planned}
    gears = {"all"} | {g for p in planned for g in p.input.gears} | {
        f"{p.input.element}:{g}" for p in planned for g in p.input.gears}
    for keys, names, what in ((tuple(MESH_FACTORS), meshes, "mesh"),
                              (GEAR_DEVIATIONS + ("accuracy_grade",), gears, "gear")):
        for key in keys:
            unknown = unmatched_keys(getattr(spec, key), names)
            if unknown:
                raise RatingError(f"rating.{key}: {unknown[0]!r} names no {what} of the rated train; accepted "
                                  f"keys are {', '.join(sorted(names))}.")


def _element_ports(solution_like, element: str):
    """(torques, speeds) by port of ``element`` from a Solution or a BatchSolution."""
    if hasattr(solution_like, "elements"):
        state = solution_like.elements[element]
        return dict(state.torques), dict(state.speeds)
    train = solution_like.train
    el = next(e for e in train.elements if e.name == element)
    ports = ("sun", "ring", "carrier") if len(el.shafts) == 3 else ("first", "second")
    torques = {p: solution_like.port_torques[(element, p)] for p in ports}
    speeds = {p: solution_like.speeds[s] for p, s in zip(ports, el.shafts)}
    return torques, speeds


def _rate(planned, source, gear, spec, skipped) -> TrainRating:
    ratings = []
    cache: dict[str, tuple] = {}
    for item in planned:
        element = item.input.element
        if element not in cache:
            try:
                cache[element] = _element_ports(source, element)
            except (KeyError, StopIteration):
                raise RatingError(f"rating: the solution has no element {element!r}.") from None
        torque, speed = item.loads(*cache[element])
        ratings.append(rate_mesh(item.input, torque, speed))
    return TrainRating(tuple(ratings), gear, f"ISO 6336:{spec.standard}", spec.life, skipped)


def rate_solution(solution, geometry: Mapping[str, object], spec: RatingSpec, *, gear: str | None = None,
                  planned=None) -> TrainRating:
    """Rate every mesh with geometry at one solved operating point.

    Parameters
    ----------
    solution : Solution
        From :func:`epicyclic.solve` (torques N·m, speeds 1/min).
    geometry : mapping element → SetGeometry or StageGeometry
    spec : RatingSpec
    gear : str, optional
        The transmission gear (for the report).
    planned : tuple, optional
        :func:`mesh_inputs` of ``geometry`` and ``spec`` already built (reuse across calls).

    Returns
    -------
    TrainRating

    Raises
    ------
    RatingError
        Missing rating inputs, an element of the geometry that the solution lacks.

    References
    ----------
    ISO 6336-1:2019; ISO 6336-2:2019; ISO 6336-3:2019.
    """
    plan, skipped = planned if planned is not None else mesh_inputs(geometry, spec)
    return _rate(plan, solution, gear, spec, skipped)


def rate_batch(batch, geometry: Mapping[str, object], spec: RatingSpec, *, gear: str | None = None,
               planned=None) -> TrainRating:
    """Rate every mesh over the points of a :class:`~epicyclic.solver.batch.BatchSolution` at once.

    Each factor of the result is an array with one value per point (load case).

    Parameters
    ----------
    batch : BatchSolution
        From :func:`epicyclic.solver.solve_batch`.
    geometry : mapping element → SetGeometry or StageGeometry
    spec : RatingSpec
    gear : str, optional
    planned : tuple, optional
        :func:`mesh_inputs` already built.

    Returns
    -------
    TrainRating

    References
    ----------
    ISO 6336-1:2019; ISO 6336-2:2019; ISO 6336-3:2019.
    """
    plan, skipped = planned if planned is not None else mesh_inputs(geometry, spec)
    return _rate(plan, batch, gear, spec, skipped)
