"""The optional ``geometry`` and ``losses`` tables of a train file, and the top-level ``[lubricant]``.

Per ``[[planetary]]`` and ``[[gear]]`` element::

    [planetary.geometry]                 # mm, degrees
    module = 1.75                        # normal module m_n (required)
    pressure_angle = 20.0                # α_n (default 20)
    helix_angle = 0.0                    # β (default 0)
    addendum = 1.0                       # h_a* (default 1)
    dedendum = 1.25                      # h_f* (default 1.25)
    profile_shift = { sun = 0.438, planet = 0.0426, ring = 0.0 }   # by gear name (default 0)
    internal_shift_convention = "iso"    # sign of an internal gear's x: "iso" (ISO 21771, default) or "khk"
    center_distance_tolerance = "js7"    # coaxiality: ± mm or an ISO 286 js field (DIN 3964)
    center_distance = 56.8               # the carrier's centre distance as built, mm (backlash from it)
    thickness_allowance = -0.05          # A_sn ≤ 0, mm: one number or one per gear name
    face_width = 38.0                    # mm, or one per gear name
    ring_module = 2.0                    # stepped sets: module of the second mesh
    planets = 3                          # number of planets (or the element's 'planets')
    load_sharing = 1.0                   # K_γ, or "floating_sun" / "flexible_pins" / "abs" for the tables
    tip_shortening = true                # or the coefficient k per gear: { sun = 0.05, planet = 0.02 }

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
``[[x_driving, x_driven], ...]``, ``face_width`` and ``center_distance`` as one
number or one per mesh, ``idlers = [1]`` for an idler gear (mesh 1's driven
gear drives mesh 2: one gear, one geometry), ``tip_shortening`` as true/false or
``[[k_driving, k_driven], ...]`` and ``tip_diameter = [[d_a driving, d_a driven], ...]`` (mm,
``"none"`` keeps a gear's own) for the tips as built.  Every problem names the file, the element, the key, what was expected
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
from ..losses import Lubricant
from ..model import GearStage, PlanetarySet
from ..text import short
from .losses_format import LOSSES_KEYS, read_losses
from .reader import at_key

__all__ = ["GEOMETRY_KEYS", "LOSSES_KEYS", "LUBRICANT_KEYS", "module_ratio", "read_lubricant", "read_extras"]

GEOMETRY_KEYS = {"module", "pressure_angle", "helix_angle", "addendum", "dedendum", "profile_shift", "face_width",
                 "ring_module", "planets", "load_sharing", "tip_shortening", "internal_shift_convention",
                 "center_distance_tolerance", "center_distance", "thickness_allowance"}
_STAGE_GEOMETRY_KEYS = (GEOMETRY_KEYS - {"ring_module", "planets", "load_sharing", "center_distance_tolerance",
                                         "thickness_allowance"}) | {"idlers", "tip_diameter"}
LUBRICANT_KEYS = {"viscosity", "lubricant_factor", "viscosity_40", "viscosity_100", "density", "temperature",
                  "expansion", "specific_heat"}  # _40/_100: mm²/s (spin losses and rating)


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
            losses = read_losses(reader, kind, l_table, element, geometry, table, lubricant, l_where)
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


def _convention(reader, table, where: str) -> str:
    """``internal_shift_convention``: "iso" (default) or "khk"."""
    value = table.get("internal_shift_convention", "iso")
    if not isinstance(value, str) or value.strip().lower() not in ("iso", "khk"):
        raise reader.error(at_key(where, "geometry.internal_shift_convention"),
                           f"expected \"iso\" (ISO 21771, DIN 3960, KISSsoft, REXS: an internal gear's x < 0 "
                           f"enlarges its tip circle) or \"khk\" (KHK / SDP-SI handbooks, the opposite sign), "
                           f"got {short(value)}.")
    return value.strip().lower()


def _cd_tolerance(reader, table, where: str):
    """``center_distance_tolerance``: ± mm or an ISO 286 js field, or None."""
    if "center_distance_tolerance" not in table:
        return None
    from ..geometry.tolerances import parse_center_distance_tolerance

    value = table["center_distance_tolerance"]
    try:
        return parse_center_distance_tolerance(value)
    except EpicyclicError:
        raise reader.error(at_key(where, "geometry.center_distance_tolerance"),
                           f"expected a positive number of mm or an ISO 286 js field \"js5\" … \"js11\" "
                           f"(DIN 3964), got {short(value)}.") from None


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
    if isinstance(table.get("load_sharing"), str):
        from ..geometry.load_sharing import MOUNTINGS

        load_sharing = table["load_sharing"]
        if load_sharing not in MOUNTINGS:
            raise reader.error(at_key(where, "geometry.load_sharing"),
                               f"expected K_gamma >= 1 or a mounting for the tabulated value "
                               f"({', '.join(repr(m) for m in MOUNTINGS)}), got {short(load_sharing)}.")
    elif "load_sharing" in table:
        load_sharing = reader.number(table["load_sharing"], "geometry.load_sharing", where)
        if load_sharing < 1.0:
            raise reader.error(at_key(where, "geometry.load_sharing"),
                               f"expected K_gamma >= 1 (1 = equal sharing), "
                               f"got {short(table['load_sharing'])}.")
    if isinstance(table.get("tip_shortening"), dict):
        tip = _gear_values(reader, table["tip_shortening"], user, "tip_shortening", where, 0.0)
        tip = {back[k]: v for k, v in tip.items()}
        for name, k in tip.items():
            if k < 0:
                raise reader.error(at_key(where, "geometry.tip_shortening"),
                                   f"expected a tip-shortening coefficient k >= 0 for {name}, got {short(k)}.")
    else:
        tip = reader.boolean(table, "tip_shortening", where, True)
    center = None
    if "center_distance" in table:
        center = _positive(reader, table["center_distance"], "geometry.center_distance", where, "mm")
    allowance = None
    if "thickness_allowance" in table:
        allowance = _gear_values(reader, table["thickness_allowance"], user, "thickness_allowance", where, 0.0)
        allowance = {back[k]: v for k, v in allowance.items()}
        for name, a in allowance.items():
            if not -rack.module <= a <= 0:
                raise reader.error(at_key(where, "geometry.thickness_allowance"),
                                   f"expected a tooth-thickness allowance A_sn in [-m_n, 0] mm for {name} "
                                   f"(negative: thinner teeth, backlash), got {short(a)}.")
    planet_shifts = tuple(shifts[n] for n in names[1:-1])
    geometry = SetGeometry(pset, rack, shifts["sun"], shifts["ring"],
                           planet_shifts if len(planet_shifts) > 1 else planet_shifts[0], ring_module, tip,
                           widths, load_sharing, _convention(reader, table, where),
                           _cd_tolerance(reader, table, where), center, allowance)
    return pset, geometry


def _stage_geometry(reader, table, stage: GearStage, where: str) -> StageGeometry:
    reader.check_keys(table, _STAGE_GEOMETRY_KEYS, where)
    if not stage.meshes:
        raise reader.error(where, "a geometry table needs tooth counts: give 'meshes' instead of 'ratio'.")
    count = len(stage.meshes)
    per_mesh = any(isinstance(table.get(k), list) for k in ("module", "pressure_angle", "helix_angle", "addendum",
                                                             "dedendum"))
    for key in ("module", "pressure_angle", "helix_angle", "addendum", "dedendum"):
        value = table.get(key)
        if isinstance(value, list) and len(value) != count:
            raise reader.error(at_key(where, f"geometry.{key}"),
                               f"expected one value per mesh ({count}), got {len(value)}: "
                               f"{'remove the extra ones' if len(value) > count else 'add the missing ones'}.")
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
    tip = (_stage_pairs(reader, table, "tip_shortening", count, where) if isinstance(table.get("tip_shortening"), list)
           else reader.boolean(table, "tip_shortening", where, True))
    tip_diameter = _stage_pairs(reader, table, "tip_diameter", count, where) if "tip_diameter" in table else None
    idlers = table.get("idlers", [])
    if not isinstance(idlers, list) or not all(isinstance(k, int) and not isinstance(k, bool) and 1 <= k < count
                                               for k in idlers):
        raise reader.error(at_key(where, "geometry.idlers"),
                           f"expected a list of mesh numbers 1 … {count - 1} whose driven gear drives the next mesh "
                           f"(one idler gear), got {short(idlers)}.")
    center = None
    if "center_distance" in table:
        value = table["center_distance"]
        center = ([_positive(reader, v, f"geometry.center_distance[{k}]", where, "mm") for k, v in enumerate(value)]
                  if isinstance(value, list) else _positive(reader, value, "geometry.center_distance", where, "mm"))
        if isinstance(center, list) and len(center) != count:
            raise reader.error(at_key(where, "geometry.center_distance"),
                               f"expected one centre distance per mesh ({count}), got {len(center)}.")
    try:
        return StageGeometry(stage, racks if per_mesh else racks[0], pairs, widths, tip,
                             _convention(reader, table, where), tuple(idlers), center, tip_diameter)
    except EpicyclicError as exc:
        raise reader.wrap(where, exc) from None


def _stage_pairs(reader, table, key: str, count: int, where: str) -> list[tuple]:
    """One pair (driving, driven) per mesh of ``key``: numbers, or "none" to keep a gear's own."""
    values = table[key]
    k_where = at_key(where, f"geometry.{key}")
    if not isinstance(values, list) or len(values) != count or not all(
            isinstance(x, list) and len(x) == 2 for x in values):
        raise reader.error(k_where, f"expected one pair [driving, driven] per mesh ({count}), e.g. "
                                    f"{[[0.0, 0.0]] * count}, got {short(values)}.")
    return [tuple(None if v == "none" else reader.number(v, f"{key}[{k}]", where) for v in pair)
            for k, pair in enumerate(values)]
