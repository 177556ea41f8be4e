"""The ``losses`` table of a ``[[planetary]]`` or ``[[gear]]`` element: mesh friction, planet bearings, drag.

::

    [planetary.losses]
    friction = "schlenk"                 # or a number: μ of every mesh; or one per mesh:
                                         # { "sun-planet" = 0.05, "planet-ring" = "schlenk" } or [0.05, "schlenk"]
    roughness = 0.4                      # R_a in µm (Schlenk), one number or one per mesh as friction
    bearing = { bore = 20.0, type = "needle roller" }   # or friction = 0.002 instead of type
    drag = [{ member = "carrier", coefficients = [0.0, 2e-5, 1e-9] }]   # N·m, N·m/(1/min), ...

Mesh names are those of the geometry (``sun-planet``, ``planet-ring``, ``mesh 1 (20/31)``).
Every problem names the file, the element, the key, what was expected and what was given.
"""

from __future__ import annotations

from ..losses import ConstantFriction, DragTorque, ElementLosses, Lubricant, PlanetBearing, SchlenkFriction
from ..text import short
from .reader import at_key

__all__ = ["LOSSES_KEYS", "read_losses"]

LOSSES_KEYS = {"friction", "roughness", "bearing", "drag"}
_STAGE_LOSSES_KEYS = LOSSES_KEYS - {"bearing"}
_BEARING_KEYS = {"bore", "type", "friction"}
_DRAG_KEYS = {"member", "coefficients", "relative_to"}


def _positive(reader, value: object, key: str, where: str, unit: str) -> float:
    number = reader.number(value, key, where)
    if not number > 0:
        raise reader.error(at_key(where, key), f"expected a positive number ({unit}), got {short(value)}.")
    return number


def _one_friction(reader, value, roughness, lubricant: Lubricant | None, where: str, key: str):
    """One friction model: a coefficient, or "schlenk" with the flanks' roughness (R_a, µm)."""
    if isinstance(value, str):
        if value.strip().lower() != "schlenk":
            raise reader.error(at_key(where, key),
                               f"expected a coefficient such as 0.05 or \"schlenk\" "
                               f"(ISO/TR 14179-2), got {short(value)}.")
        if lubricant is None:
            raise reader.error(where, "friction = \"schlenk\" needs the oil: add a top-level [lubricant] table with "
                                      "'viscosity' (mPa*s at the operating temperature).")
        if roughness is None:
            raise reader.error(where, "friction = \"schlenk\" needs the flank roughness: add 'roughness' (R_a, um, "
                                      "mean of both flanks), e.g. roughness = 0.4.")
        return SchlenkFriction(lubricant, _positive(reader, roughness, key.replace("friction", "roughness"), where,
                                                    "um"))
    if roughness is not None:
        raise reader.error(where, "key 'roughness' is for friction = \"schlenk\"; a given coefficient needs none.")
    mu = reader.number(value, key, where)
    if not 0.0 <= mu < 1.0:
        raise reader.error(at_key(where, key),
                           f"expected a coefficient of friction in [0, 1) "
                           f"(typically 0.03-0.08), got {short(value)}.")
    return ConstantFriction(mu)


def _per_mesh(reader, value, names: list[str], key: str, where: str) -> dict[str, object] | None:
    """A table mesh name → value or a list with one value per mesh, as a dict; None for a single value."""
    if isinstance(value, dict):
        unknown = [k for k in value if k not in names]
        if unknown:
            raise reader.error(at_key(where, key), f"unknown mesh {unknown[0]!r}; the meshes are "
                                                   f"{', '.join(map(repr, names))}.")
        return dict(value)
    if isinstance(value, list):
        if len(value) != len(names):
            raise reader.error(at_key(where, key), f"expected one value per mesh ({len(names)}: "
                                                   f"{', '.join(map(repr, names))}), got {len(value)}.")
        return dict(zip(names, value))
    return None


def _friction(reader, table, lubricant: Lubricant | None, where: str, geometry=None):
    """(friction of the element, per-mesh friction by mesh name): ``friction`` and ``roughness`` are one value,
    a table by mesh name or a list in mesh order."""
    if "friction" not in table:
        if "roughness" in table:
            raise reader.error(where, "key 'roughness' is for friction = \"schlenk\"; give 'friction' too.")
        return None, None
    value, roughness = table["friction"], table.get("roughness")
    per_mesh = isinstance(value, (dict, list)) or isinstance(roughness, (dict, list))
    if not per_mesh:
        return _one_friction(reader, value, roughness, lubricant, where, "losses.friction"), None
    if geometry is None:
        raise reader.error(where, "a friction per mesh needs the gear geometry: add a 'geometry' table with module "
                                  "and face_width.")
    names = [m.name for m in geometry.meshes]
    values = _per_mesh(reader, value, names, "losses.friction", where)
    rough = _per_mesh(reader, roughness, names, "losses.roughness", where) if roughness is not None else None
    out = {}
    for name in names:
        v = values.get(name) if values is not None else value
        if v is None:
            raise reader.error(at_key(where, "losses.friction"), f"missing mesh {name!r}; give a friction for "
                                                                 f"every mesh ({', '.join(map(repr, names))}).")
        r = rough.get(name) if rough is not None else roughness
        if rough is not None and name in rough and not isinstance(v, str):
            raise reader.error(at_key(where, f"losses.roughness.{name}"),
                               f"mesh {name!r} has a given coefficient of friction ({short(v)}); roughness is for "
                               "friction = \"schlenk\": remove it for this mesh.")
        if isinstance(v, str) or r is None:
            out[name] = _one_friction(reader, v, r, lubricant, where, f"losses.friction.{name}")
        else:  # a coefficient for this mesh, roughness given for others
            out[name] = _one_friction(reader, v, None, lubricant, where, f"losses.friction.{name}")
    return None, out


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


def read_losses(reader, kind, table, element, geometry, element_table, lubricant, where: str) -> ElementLosses:
    """The ``losses`` table of one element as its :class:`~epicyclic.losses.ElementLosses`.

    Parameters
    ----------
    reader : Reader
        The file's reader (errors name the file, element and key).
    kind : {"planetary", "gear"}
        The element's table.
    table : mapping
        The ``losses`` table.
    element : PlanetarySet or GearStage
        The element.
    geometry : SetGeometry, StageGeometry or None
        Its geometry table's result.
    element_table : mapping
        The element's own table (for keys that conflict).
    lubricant : Lubricant or None
        The top-level ``[lubricant]``.
    where : str
        Where the table is, for messages.

    Returns
    -------
    ElementLosses
    """
    reader.check_keys(table, LOSSES_KEYS if kind == "planetary" else _STAGE_LOSSES_KEYS, where)
    friction, mesh_friction = _friction(reader, table, lubricant, where, geometry)
    own = ("stationary_efficiency", "mesh_efficiencies") if kind == "planetary" else ("efficiency",)
    given = [k for k in own if k in element_table]
    if friction is not None or mesh_friction:
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
        return ElementLosses.for_set(geometry, friction=friction, bearing=bearing, drag=drag,
                                     mesh_friction=mesh_friction)
    return ElementLosses.for_stage(geometry, friction=friction, drag=drag, mesh_friction=mesh_friction)
