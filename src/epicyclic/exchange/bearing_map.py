"""Planet bearings in REXS: a set's ``bearings.planet`` table as ``rolling_bearing_with_catalog_geometry``.

Each planet's bearing is a ``rolling_bearing_with_catalog_geometry`` in a ``side`` relation between
the carrier (``inner_part``; FVA-Workbench writes the planet pin there) and the planet's shaft
(``outer_part``), with its ISO 281 rating data:

==========================  ============================================================
``bearings.planet`` key     REXS attribute
==========================  ============================================================
``type``                    ``bearing_type`` (enum, e.g. ``radial_roller_bearing``)
``dynamic_load_rating``     ``radial_dynamic_load_rating`` (C, kN)
``fatigue_load_limit``      ``fatigue_limit_load`` (C_u, kN)
``contamination``           ``contamination_factor_according_to_iso_281_2007`` (e_C)
``viscosity``               ``operating_viscosity`` (ν, mm²/s)
==========================  ============================================================

Reading, the standard attributes win over epicyclic's custom copy of the table; the type is the
copy's where it gives one (REXS has one enum value for full-complement and caged cylindrical
roller bearings); bearings of the planets that differ are taken at the smallest C (a note).

References
----------
ISO 281:2007 (C, C_u, e_C, ν); REXS 1.7 attribute database (``rexs_schema_1.7.xml``,
FVA GmbH, github.com/fva-net/rexs-api-java, Apache-2.0).
"""

from __future__ import annotations

from typing import Any

from .rexs_model import Component, RexsModel

__all__ = ["BEARING_TYPE_ENUM", "planet_bearing_attributes", "planet_bearings"]

#: epicyclic's bearing type → the REXS ``bearing_type`` enum value.
BEARING_TYPE_ENUM = {
    "deep groove ball": "radial_grooved_ball_bearing", "angular contact ball": "angular_contact_ball_bearing",
    "self-aligning ball": "radial_self_aligning_ball_bearing", "needle roller": "radial_needle_roller_bearing",
    "cylindrical roller": "radial_roller_bearing", "cylindrical roller full complement": "radial_roller_bearing",
    "tapered roller": "radial_tapered_roller_bearing", "spherical roller": "radial_spherical_roller_bearing",
}
_FROM_ENUM = {v: k for k, v in reversed(list(BEARING_TYPE_ENUM.items()))}
#: ``bearings.planet`` key → (REXS attribute, REXS quantity, REXS unit written, factor from the file's unit).
_ATTRIBUTES = {
    "dynamic_load_rating": ("radial_dynamic_load_rating", "force", "kN", 1e-3),
    "fatigue_load_limit": ("fatigue_limit_load", "force", "kN", 1e-3),
    "contamination": ("contamination_factor_according_to_iso_281_2007", "number", "none", 1.0),
    "viscosity": ("operating_viscosity", "kinematic viscosity", "mm^2 / s", 1.0),
}


def planet_bearing_attributes(rating) -> list[tuple[str, str, Any, str]]:
    """The REXS attributes of a planet's bearing from its :class:`~epicyclic.rating.BearingRating`.

    Parameters
    ----------
    rating : BearingRating

    Returns
    -------
    list of (attribute, kind, value, unit)
    """
    out: list[tuple[str, str, Any, str]] = []
    if rating.type in BEARING_TYPE_ENUM:
        out.append(("bearing_type", "enum", BEARING_TYPE_ENUM[rating.type], "none"))
    for key, (attribute, _, unit, factor) in _ATTRIBUTES.items():
        value = getattr(rating, key, None)
        if value is not None:
            out.append((attribute, "floating_point", float(value) * factor, unit))
    return out


def planet_bearings(model: RexsModel, planet_shafts: set[int], used: set[int], notes: list[str],
                    custom: dict[str, Any] | None, default_type: Any = None) -> dict[str, Any] | None:
    """The ``bearings.planet`` table of the rolling bearings on ``planet_shafts`` over the ``custom`` copy.

    Parameters
    ----------
    model : RexsModel
    planet_shafts : set of int
        The stage's planet shafts.
    used : set of int
        Gets the bearings read.
    notes : list of str
        Gets a note where the planets' bearings differ or the standard overrides the copy.
    custom : dict or None
        epicyclic's copy of the set's ``bearings.planet`` table.
    default_type : str, optional
        The set's ``losses.bearing.type`` (a planet bearing's type where its table gives none).

    Returns
    -------
    dict or None
        None where the stage has no catalogue bearing with a C and no copy.
    """
    found: list[tuple[Component, dict[str, Any]]] = []
    for relation in model.relations_of("side"):
        bearing = model.components.get(relation.role("assembly"))
        if bearing is None or bearing.type != "rolling_bearing_with_catalog_geometry":
            continue
        if not {relation.role("inner_part"), relation.role("outer_part")} & planet_shafts:
            continue
        values: dict[str, Any] = {}
        for key, (attribute, quantity, _, _) in _ATTRIBUTES.items():
            if model.has(bearing, attribute):
                values[key] = model.number(bearing, attribute, quantity)
        if model.has(bearing, "bearing_type"):
            kind = bearing.attributes["bearing_type"].value
            if isinstance(kind, str) and kind in _FROM_ENUM:
                values["type"] = _FROM_ENUM[kind]
        if "dynamic_load_rating" in values:
            used.add(bearing.id)
            found.append((bearing, values))
    if not found:
        return custom
    weakest = min(found, key=lambda bv: bv[1]["dynamic_load_rating"])
    ratings = sorted({v["dynamic_load_rating"] for _, v in found})
    if len(ratings) > 1:
        notes.append(f"the planet bearings give C = {', '.join(f'{c:g}' for c in ratings)} N; the smallest "
                     f"({weakest[0].type} {weakest[0].id}) rates every planet")
    standard = dict(weakest[1])
    table = dict(custom or {})
    given_type = table.get("type", default_type)
    if isinstance(given_type, str) and BEARING_TYPE_ENUM.get(given_type) == BEARING_TYPE_ENUM.get(standard.get("type")):
        standard.pop("type", None)  # the copy's type is the finer one (full complement or caged)
    for key, value in standard.items():
        given = table.get(key)
        if isinstance(given, (int, float)) and not isinstance(given, bool) and abs(float(given) - value) > 1e-9 * abs(
                value):  # a copy with units ("120 kN") is not compared: the standard value replaces it
            notes.append(f"bearings.planet.{key}: the REXS bearing gives {value!r}, epicyclic's custom copy "
                         f"{given!r}; the standard attribute is used")
    table.update(standard)
    return table
