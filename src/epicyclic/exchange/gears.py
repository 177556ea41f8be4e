"""The gear data of a REXS gear: tooth count, module, face width, helix angle, flank and tool data.

REXS keeps a cylindrical gear's data in three places: the gear
(``number_of_teeth``, ``normal_module``, ``face_width``,
``helix_angle_reference_diameter``), its flanks (``flank`` relation to
``flank_geometry`` in REXS 1.1, ``cylindrical_gear_flank`` from 1.4:
``addendum_modification_coefficient`` x, ``normal_pressure_angle`` α_n,
``addendum_coefficient_basic_profile`` h_a*), its roughness
(``averaged_peak_to_valley_height_flank``/``_root``, R_z), its material
(``reference`` to a ``material``: ``material_designation``, else the component's
name) and its tool (``ordered_reference``
or ``manufacturing_step`` to a ``rack_shaped_tool``/``cutter_wheel_tool``:
the tool's ``addendum_coefficient_reference_profile`` is the gear's
dedendum h_f*).  :func:`gear_data` collects them in the train file's units.

References
----------
REXS 1.1–1.7 component and attribute database (``rexs_model_1.x``, ``rexs_schema_1.7.xml``, FVA GmbH,
github.com/fva-net/rexs-api-java, Apache-2.0); ISO 21771:2007, basic rack and profile shift.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .rexs_model import Component, RexsModel

__all__ = ["GearData", "gear_data", "gear_links"]

_FLANK_TYPES = ("flank_geometry", "cylindrical_gear_flank")
_TOOL_TYPES = ("rack_shaped_tool", "cutter_wheel_tool")


@dataclass(frozen=True)
class GearData:
    """One gear as the train file needs it (mm, degrees); None where the file gives nothing."""

    component: Component
    teeth: int
    internal: bool
    module: float | None = None
    face_width: float | None = None
    helix_angle: float | None = None
    profile_shift: float | None = None
    pressure_angle: float | None = None
    addendum: float | None = None
    dedendum: float | None = None
    material: str | None = None
    flank_roughness: float | None = None
    root_roughness: float | None = None
    material_id: int | None = None
    flanks: tuple[int, ...] = ()
    tools: tuple[int, ...] = ()


def gear_links(model: RexsModel) -> tuple[dict[int, list[int]], dict[int, list[int]], dict[int, int]]:
    """(gear → flank ids, flank or gear → tool ids, gear → material id), from the relations.

    Parameters
    ----------
    model : RexsModel
    """
    flanks: dict[int, list[int]] = {}
    tools: dict[int, list[int]] = {}
    material: dict[int, int] = {}
    for relation in model.relations:
        if relation.type == "flank":
            gear = relation.role("gear")
            flanks[gear] = [r.id for r in relation.refs if r.role in ("left", "right")]
        elif relation.type in ("ordered_reference", "reference", "manufacturing_step"):
            origin = relation.role("origin") or relation.role("workpiece")
            target = relation.role("referenced") or relation.role("tool")
            kind = model.components.get(target)
            if origin is None or kind is None:
                continue
            if kind.type in _TOOL_TYPES:
                tools.setdefault(origin, []).append(target)
            elif kind.type == "material":
                material.setdefault(origin, target)
    return flanks, tools, material


def gear_data(model: RexsModel, gear: Component, links, used: set[int]) -> GearData:
    """The data of ``gear`` (a ``cylindrical_gear`` or ``ring_gear``) in mm and degrees.

    Parameters
    ----------
    model : RexsModel
    gear : Component
    links : tuple
        :func:`gear_links` of the model.
    used : set of int
        Component ids read; the gear's flanks, tools and material are added.

    Returns
    -------
    GearData

    Raises
    ------
    RexsValueError
        No ``number_of_teeth``, or a malformed value; the message names the component and attribute.
    """
    flanks, tools, materials = links
    flank = [model.components[f] for f in flanks.get(gear.id, []) if f in model.components]
    tool = [model.components[t] for owner in [gear.id] + [f.id for f in flank] for t in tools.get(owner, [])
            if t in model.components]
    used.update(c.id for c in flank + tool)
    used.add(gear.id)

    def optional(component: Component | None, attribute: str, quantity: str = "number") -> float | None:
        if component is None or not model.has(component, attribute):
            return None
        return model.number(component, attribute, quantity)

    def from_flank(attribute: str, quantity: str = "number") -> float | None:
        for owner in [gear] + flank:  # REXS 1.0-1.3 give some flank data on the gear itself
            value = optional(owner, attribute, quantity)
            if value is not None:
                return value
        return None

    helix = optional(gear, "helix_angle_reference_diameter", "angle")
    material = None
    if gear.id in materials:
        used.add(materials[gear.id])
        found = model.components.get(materials[gear.id])
        material = (model.text(found, "material_designation") or re.sub(r"\s*\[\d+\]$", "", found.name)
                    if found else None) or None
    return GearData(
        component=gear,
        teeth=model.integer(gear, "number_of_teeth"),
        internal=gear.type == "ring_gear",
        module=optional(gear, "normal_module", "length"),
        face_width=optional(gear, "face_width", "length"),
        helix_angle=None if helix is None else abs(helix),
        profile_shift=from_flank("addendum_modification_coefficient"),
        pressure_angle=from_flank("normal_pressure_angle", "angle") or optional(tool[0] if tool else None,
                                                                                 "normal_pressure_angle", "angle"),
        addendum=from_flank("addendum_coefficient_basic_profile"),
        dedendum=optional(tool[0] if tool else None, "addendum_coefficient_reference_profile"),
        material=material,
        flank_roughness=_micrometres(optional(gear, "averaged_peak_to_valley_height_flank", "length")),
        root_roughness=_micrometres(optional(gear, "averaged_peak_to_valley_height_root", "length")),
        material_id=materials.get(gear.id),
        flanks=tuple(f.id for f in flank),
        tools=tuple(t.id for t in tool),
    )


def _micrometres(mm: float | None) -> float | None:
    """R_z in µm (the rating's unit) from mm; REXS writes ``mum``."""
    return None if mm is None else round(mm * 1000.0, 9)
