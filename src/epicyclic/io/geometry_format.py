"""The optional ``geometry`` and ``losses`` tables of a train file, and the top-level ``[lubricant]``.

Per ``[[planetary]]`` and ``[[gear]]`` element::

    [planetary.geometry]                 # mm, degrees
    module = 1.75                        # normal module m_n (required)
    pressure_angle = 20.0                # α_n (default 20)
    helix_angle = 0.0                    # β (default 0)
    addendum = 1.0                       # h_a* (default 1)
    dedendum = 1.25                      # h_f* (default 1.25)
    profile_shift = { sun = 0.438, planet = 0.0426, ring = 0.0 }   # by gear name (default 0)
    face_width = 38.0                    # mm, or one per gear name
    ring_module = 2.0                    # stepped sets: module of the second mesh
    planets = 3                          # number of planets (or the element's 'planets')
    load_sharing = 1.0                   # K_γ (default by number of planets)
    tip_shortening = true

    [planetary.losses]
    friction = "schlenk"                 # or a number: μ of every mesh
    roughness = 0.4                      # R_a in µm (Schlenk)
    bearing = { bore = 20.0, type = "needle roller" }   # or friction = 0.002 instead of type
    drag = [{ member = "carrier", coefficients = [0.0, 2e-5, 1e-9] }]   # N·m, N·m/(1/min), ...

    [lubricant]                          # top level, for friction = "schlenk"
    viscosity = 30.0                     # dynamic viscosity at operating temperature, mPa·s
    lubricant_factor = 1.0               # X_L (1 for mineral oil)

A ``[[gear]]`` stage built from ``meshes`` takes the same geometry keys with a
value per mesh where it differs (``module = [2.0, 2.5]``), ``profile_shift`` as
``[[x_driving, x_driven], ...]`` and ``face_width`` as one number or one per
mesh.  Every problem names the file, the element, the key, what was expected
and what was given (``docs/file-format.md``).
"""

from __future__ import annotations

import difflib
from collections.abc import Mapping
from dataclasses import replace
from typing import Any

from ..errors import EpicyclicError
from ..geometry import BasicRack, SetGeometry, StageGeometry
from ..geometry.set_geometry import TWO_CENTRAL_NAMES, planet_names
from ..limits import MODULE_RANGE
from ..losses import (
    ConstantFriction,
    DragTorque,
    ElementLosses,
    Lubricant,
    PlanetBearing,
    SchlenkFriction,
)
from ..model import GearStage, PlanetarySet
from ..text import short
from .reader import at_key

__all__ = ["GEOMETRY_KEYS", "LOSSES_KEYS", "LUBRICANT_KEYS", "module_ratio", "read_lubricant", "read_extras"]

GEOMETRY_KEYS = {"module", "pressure_angle", "helix_angle", "addendum", "dedendum", "profile_shift", "face_width",
                 "ring_module", "planets", "load_sharing", "tip_shortening"}
_STAGE_GEOMETRY_KEYS = GEOMETRY_KEYS - {"ring_module", "planets", "load_sharing"}
LOSSES_KEYS = {"friction", "roughness", "bearing", "drag"}
_STAGE_LOSSES_KEYS = LOSSES_KEYS - {"bearing"}
LUBRICANT_KEYS = {"viscosity", "lubricant_factor", "viscosity_40", "viscosity_100", "density", "temperature",
                  "expansion", "specific_heat"}
_BEARING_KEYS = {"bore", "type", "friction"}
_DRAG_KEYS = {"member", "coefficients", "relative_to"}


def _positive(reader, value: object, key: str, where: str, unit: str) -> float:
    number = reader.number(value, key, where)
    if not number > 0:
        raise reader.error(at_key(where, key), f"expected a positive number ({unit}), got {short(value)}.")
    return number


def module_ratio(reader, table: Mapping[str, Any], where: str) -> float:
    """m2/m1 of a stepped set from its geometry table (1.0 without one or without ``ring_module``)."""
    geometry = table.get("geometry")
    if not isinstance(geometry, dict) or "ring_module" not in geometry or "module" not in geometry:
        return 1.0
    g_where = f"{where}, table 'geometry'"
    return (_positive(reader, geometry["ring_module"], "geometry.ring_module", g_where, "mm")
            / _positive(reader, geometry["module"], "geometry.module", g_where, "mm"))


def read_lubricant(reader, data: Mapping[str, Any]) -> Lubricant | None:
    """The top-level ``[lubricant]`` table as Schlenk's lubricant, or None (see :mod:`.spin_format`)."""
    from .spin_format import read_lubricant as read

    return read(reader, data)[0]


def read_extras(reader, kind: str, table: Mapping[str, Any], element, where: str,
                lubricant: Lubricant | None) -> tuple[Any, Any, Any]:
    """(element, geometry, losses) of one ``[[planetary]]`` or ``[[gear]]`` table.

    The element comes back changed when the geometry table gives its number of planets.
    """
    geometry = None
    if "geometry" in table:
        g_where = f"{where}, table 'geometry'"
        g_table = reader.table(table["geometry"], g_where)
        try:
            if kind == "planetary":
                element, geometry = _set_geometry(reader, g_table, element, table, g_where)
            else:
                geometry = _stage_geometry(reader, g_table, element, g_where)
        except EpicyclicError as exc:
            if _located(exc):
                raise
            raise reader.wrap(g_where, exc) from None
    losses = None
    if "losses" in table:
        l_where = f"{where}, table 'losses'"
        l_table = reader.table(table["losses"], l_where)
        try:
            losses = _losses(reader, kind, l_table, element, geometry, table, lubricant, l_where)
        except EpicyclicError as exc:
            if _located(exc):
                raise
            raise reader.wrap(l_where, exc) from None
    return element, geometry, losses


def _located(exc: Exception) -> bool:
    """Whether the error already names the file and key (an input-file error of the reader)."""
    return hasattr(exc, "source") and hasattr(exc, "where")


# ---------------------------------------------------------------------- geometry
def _rack(reader, table, where: str, index: int | None = None) -> BasicRack:
    def pick(key, default):
        value = table.get(key, default)
        if isinstance(value, list):
            if index is None:
                raise reader.error(at_key(where, f"geometry.{key}"),
                                   f"expected a number, got the array {short(value)}.")
            if index >= len(value):
                raise reader.error(at_key(where, f"geometry.{key}"), f"expected one value per mesh, got {len(value)}.")
            value = value[index]
        return reader.number(value, f"geometry.{key}", where)

    module = pick("module", reader.require(table, "module", where))
    if not MODULE_RANGE[0] <= module <= MODULE_RANGE[1]:
        raise reader.error(at_key(where, "geometry.module"),
                           f"expected a positive normal module in mm within {MODULE_RANGE[0]:g} … "
                           f"{MODULE_RANGE[1]:g} "
                           f"(see docs/limits.md), got {short(module)}.")
    return BasicRack(module, pick("pressure_angle", 20.0), pick("helix_angle", 0.0), pick("addendum", 1.0),
                     pick("dedendum", 1.25))


def _gear_values(reader, value, names: tuple[str, ...], key: str, where: str, default: float | None):
    """A number for every gear, or a table gear name → number (missing gears take ``default``)."""
    if isinstance(value, dict):
        unknown = [k for k in value if k not in names]
        if unknown:
            close = next(iter(difflib.get_close_matches(unknown[0], names, n=1, cutoff=0.6)), None)
            raise reader.error(at_key(where, f"geometry.{key}"),
                               f"unknown gear {unknown[0]!r}; the gears of this set "
                               f"are {', '.join(names)}" + (f" (did you mean {close!r}?)" if close else "")
                                      + ".")
        out = {}
        for name in names:
            if name not in value and default is None:
                raise reader.error(at_key(where, f"geometry.{key}"),
                                   f"missing gear {name!r}; give one value per gear "
                                   f"({', '.join(names)}) or one number for all.")
            out[name] = reader.number(value.get(name, default), f"geometry.{key}.{name}", where)
        return out
    number = reader.number(value, f"geometry.{key}", where)
    return {name: number for name in names}


def _set_geometry(reader, table, pset: PlanetarySet, element_table, where: str):
    reader.check_keys(table, GEOMETRY_KEYS, where)
    if pset.teeth is None:
        raise reader.error(where, "a geometry table needs tooth counts: give 'teeth' instead of 'stationary_ratio'.")
    rack = _rack(reader, table, where)
    names = ("sun", *planet_names(pset.teeth), "ring")
    # a set with two suns or two rings names its gears as its teeth table does: first, planet_first, ...
    said = {n: TWO_CENTRAL_NAMES[n] for n in names} if pset.teeth.arrangement in ("two rings", "two suns") \
        else {n: n for n in names}
    back = {v: k for k, v in said.items()}
    user = tuple(said.values())
    shifts = _gear_values(reader, table.get("profile_shift", 0.0), user, "profile_shift", where, 0.0)
    shifts = {back[k]: v for k, v in shifts.items()}
    widths = None
    if "face_width" in table:
        widths = _gear_values(reader, table["face_width"], user, "face_width", where, None)
        widths = {back[k]: v for k, v in widths.items()}
        for name, b in widths.items():
            if b <= 0:
                raise reader.error(at_key(where, "geometry.face_width"),
                                   f"expected a positive width in mm for {name}, "
                                   f"got {short(b)}.")
    ring_module = None
    if "ring_module" in table:
        if pset.teeth.kind != "stepped":
            raise reader.error(at_key(where, "geometry.ring_module"),
                               f"only stepped sets have a second module; this "
                               f"is a {pset.teeth.kind} set. Remove it.")
        ring_module = _positive(reader, table["ring_module"], "geometry.ring_module", where, "mm")
    if "planets" in table:
        planets = reader.integer(table["planets"], "geometry.planets", where)
        if "planets" in element_table and planets != pset.planets:
            raise reader.error(at_key(where, "geometry.planets"),
                               f"{planets} planets, but the element's 'planets' "
                               f"says {pset.planets}; give the number once.")
        pset = replace(pset, planets=planets)
    load_sharing = None
    if "load_sharing" in table:
        load_sharing = reader.number(table["load_sharing"], "geometry.load_sharing", where)
        if load_sharing < 1.0:
            raise reader.error(at_key(where, "geometry.load_sharing"),
                               f"expected K_gamma >= 1 (1 = equal sharing), "
                               f"got {short(table['load_sharing'])}.")
    tip = reader.boolean(table, "tip_shortening", where, True)
    planet_shifts = tuple(shifts[n] for n in names[1:-1])
    geometry = SetGeometry(pset, rack, shifts["sun"], shifts["ring"],
                           planet_shifts if len(planet_shifts) > 1 else planet_shifts[0], ring_module, tip,
                           widths, load_sharing)
    return pset, geometry


def _stage_geometry(reader, table, stage: GearStage, where: str) -> StageGeometry:
    reader.check_keys(table, _STAGE_GEOMETRY_KEYS, where)
    if not stage.meshes:
        raise reader.error(where, "a geometry table needs tooth counts: give 'meshes' instead of 'ratio'.")
    count = len(stage.meshes)
    per_mesh = any(isinstance(table.get(k), list) for k in ("module", "pressure_angle", "helix_angle", "addendum",
                                                             "dedendum"))
    racks = [_rack(reader, table, where, k if per_mesh else None) for k in range(count)]
    shifts = table.get("profile_shift", [[0.0, 0.0]] * count)
    if not isinstance(shifts, list) or len(shifts) != count or not all(
            isinstance(x, list) and len(x) == 2 for x in shifts):
        raise reader.error(at_key(where, "geometry.profile_shift"),
                           f"expected one pair [x_driving, x_driven] per mesh "
                           f"({count}), e.g. {[[0.0, 0.0]] * count}, got {short(shifts)}.")
    pairs = [tuple(reader.number(v, f"geometry.profile_shift[{k}]", where) for v in pair)
             for k, pair in enumerate(shifts)]
    widths = None
    if "face_width" in table:
        value = table["face_width"]
        widths = ([_positive(reader, v, f"geometry.face_width[{k}]", where, "mm") for k, v in enumerate(value)]
                  if isinstance(value, list) else _positive(reader, value, "geometry.face_width", where, "mm"))
    tip = reader.boolean(table, "tip_shortening", where, True)
    return StageGeometry(stage, racks if per_mesh else racks[0], pairs, widths, tip)


# ---------------------------------------------------------------------- losses
def _friction(reader, table, lubricant: Lubricant | None, where: str):
    if "friction" not in table:
        if "roughness" in table:
            raise reader.error(where, "key 'roughness' is for friction = \"schlenk\"; give 'friction' too.")
        return None
    value = table["friction"]
    if isinstance(value, str):
        if value.strip().lower() != "schlenk":
            raise reader.error(at_key(where, "losses.friction"),
                               f"expected a coefficient such as 0.05 or \"schlenk\" "
                               f"(ISO/TR 14179-2), got {short(value)}.")
        if lubricant is None:
            raise reader.error(where, "friction = \"schlenk\" needs the oil: add a top-level [lubricant] table with "
                                      "'viscosity' (mPa*s at the operating temperature).")
        if "roughness" not in table:
            raise reader.error(where, "friction = \"schlenk\" needs the flank roughness: add 'roughness' (R_a, um, "
                                      "mean of both flanks), e.g. roughness = 0.4.")
        return SchlenkFriction(lubricant, _positive(reader, table["roughness"], "losses.roughness", where, "um"))
    if "roughness" in table:
        raise reader.error(where, "key 'roughness' is for friction = \"schlenk\"; a given coefficient needs none.")
    mu = reader.number(value, "losses.friction", where)
    if not 0.0 <= mu < 1.0:
        raise reader.error(at_key(where, "losses.friction"),
                           f"expected a coefficient of friction in [0, 1) "
                           f"(typically 0.03-0.08), got {short(value)}.")
    return ConstantFriction(mu)


def _bearing(reader, value, where: str) -> PlanetBearing:
    b_where = f"{where}, key 'bearing'"
    table = reader.table(value, b_where)
    reader.check_keys(table, _BEARING_KEYS, b_where)
    bore = _positive(reader, reader.require(table, "bore", b_where), "losses.bearing.bore", where, "mm")
    if "type" in table and "friction" in table:
        raise reader.error(b_where, "give the bearing 'type' or its 'friction' coefficient, not both.")
    if "friction" in table:
        return PlanetBearing(bore, reader.number(table["friction"], "losses.bearing.friction", where))
    kind = table.get("type", "needle roller")
    if not isinstance(kind, str):
        raise reader.error(at_key(b_where, "type"),
                           f"expected a bearing type such as \"needle roller\", got {short(kind)}.")
    return PlanetBearing(bore, kind)


def _drag(reader, value, where: str) -> tuple[DragTorque, ...]:
    if isinstance(value, dict):
        value = [value]
    if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
        raise reader.error(at_key(where, "losses.drag"),
                           f"expected a table or array of tables such as "
                           f"[{{ member = \"carrier\", coefficients = [0.0, 2e-5] }}], got {short(value)}.")
    out = []
    for k, term in enumerate(value):
        d_where = f"{where}, drag[{k}]"
        reader.check_keys(term, _DRAG_KEYS, d_where)
        member = reader.string(term, "member", d_where)
        coefficients = reader.require(term, "coefficients", d_where)
        if not isinstance(coefficients, list) or not coefficients:
            raise reader.error(at_key(d_where, "coefficients"),
                               f"expected a list [c0, c1, c2, ...] (N*m, N*m per "
                               f"1/min, ...), got {short(coefficients)}.")
        numbers = [reader.number(c, f"drag[{k}].coefficients[{j}]", d_where) for j, c in enumerate(coefficients)]
        out.append(DragTorque(member, numbers, term.get("relative_to", "housing")))
    return tuple(out)


def _losses(reader, kind, table, element, geometry, element_table, lubricant, where: str) -> ElementLosses:
    reader.check_keys(table, LOSSES_KEYS if kind == "planetary" else _STAGE_LOSSES_KEYS, where)
    friction = _friction(reader, table, lubricant, where)
    own = ("stationary_efficiency", "mesh_efficiencies") if kind == "planetary" else ("efficiency",)
    given = [k for k in own if k in element_table]
    if friction is not None:
        if given:
            raise reader.error(where, f"key 'losses.friction' computes the mesh efficiency from the geometry; remove "
                                      f"the element's {given[0]!r} (or the friction).")
        if geometry is None:
            raise reader.error(where, "key 'losses.friction' needs the gear geometry: add a 'geometry' table with "
                                      "module and face_width.")
        if geometry.face_width is None:
            raise reader.error(where, "key 'losses.friction' needs the load per face width: add 'face_width' (mm) to "
                                      "the 'geometry' table.")
    bearing = _bearing(reader, table["bearing"], where) if "bearing" in table else None
    if bearing is not None and geometry is None:
        raise reader.error(where, "key 'losses.bearing' takes the bearing loads from the tooth forces: add a "
                                  "'geometry' table.")
    drag = _drag(reader, table["drag"], where) if "drag" in table else ()
    if geometry is None:
        return ElementLosses(element, (), None, 1.0, drag)
    if kind == "planetary":
        return ElementLosses.for_set(geometry, friction=friction, bearing=bearing, drag=drag)
    return ElementLosses.for_stage(geometry, friction=friction, drag=drag)
