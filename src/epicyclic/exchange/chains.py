"""Fixed-axis gear stages from chains of REXS ``cylindrical_stage``\\ s.

A parallel gearbox in REXS is a set of ``cylindrical_stage`` meshes between
gears on shafts.  A shaft that only passes torque from one mesh to the next
(an intermediate shaft with two gears, or an idler with one gear meshing
twice) is folded into one ``[[gear]]`` stage with one entry in ``meshes``
per mesh, from the first end shaft to the other, so that the ratio is the
product of the mesh ratios (Müller 1998, eq. 2.1: i = Π (−z_driven/z_driving)
for external meshes).  The chain ends at members that do more: carry a load
or a given speed, belong to a planetary set, clutch or brake, or meet more
than two meshes.

References
----------
Müller, H. W. (1998). *Die Umlaufgetriebe*, 2nd ed., Springer, ch. 2 (ratios of fixed-axis trains).
"""

from __future__ import annotations

from typing import Any

from ..model import HOUSING
from .custom import CUSTOM_ELEMENT, custom as _custom
from .rexs_model import Component
from .topology import element_name

__all__ = ["chains"]


def chains(mapper) -> list[tuple[dict[str, Any], None]]:
    """The ``[[gear]]`` tables of the stages outside planetary stages.

    Parameters
    ----------
    mapper : epicyclic.exchange.mapping._Mapper
        The mapping under way (its model, members, meshes and names).

    Returns
    -------
    list of (table, None)

    Raises
    ------
    RexsValueError
        A chain that closes on itself, ends at the casing or at its own start.
    """
    model, members = mapper.model, mapper.members
    free = [(s, g1, g2) for s, g1, g2 in mapper.meshes if s.id not in mapper.stage_owner]
    out = _ratio_stages(mapper)
    if not free:
        return out
    node = {}
    for _, g1, g2 in free:
        for g in (g1, g2):
            node[g] = members.find(mapper.shaft_of(g))
    incident: dict[object, list[int]] = {}
    for k, (_, g1, g2) in enumerate(free):
        incident.setdefault(node[g1], []).append(k)
        incident.setdefault(node[g2], []).append(k)
    planetary_members = {members.find(s) for r in model.relations_of("central_shaft", "planet_carrier_shaft",
                                                                     "planet_shaft") for s in [r.role("shaft")]
                         if s is not None}
    planetary_members |= {members.find(("carrier", r.role("planetary_stage")))
                          for r in model.relations_of("planet_carrier_shaft")}
    switched = {members.find(p) for r in model.relations_of("side")
                if (model.components.get(r.role("assembly")) or Component(0, "", "")).type == "switchable_coupling"
                for p in (r.role("inner_part"), r.role("outer_part")) if p is not None}
    loaded = {members.find(s) for s in mapper.operating.preferred_shafts()}
    ends = set()  # the shafts epicyclic wrote as a stage's first and second: a stage of its own starts there
    for k, (stage, g1, g2) in enumerate(free):
        extras = _custom(model, stage, CUSTOM_ELEMENT)
        for n in (node[g1], node[g2]):
            if members.name(n) in (extras.get("first"), extras.get("second")):
                ends.add(n)

    def terminal(n: object) -> bool:
        return (n in planetary_members or n in switched or n in loaded or n in ends or len(incident[n]) != 2
                or (members.casing is not None and n == members.find(members.casing)))

    visited: set[int] = set()
    starts = sorted((n for n in incident if terminal(n)), key=lambda n: min(incident[n]))
    for start in starts:
        for k in sorted(incident[start]):
            if k in visited:
                continue
            path, here = [], start
            while True:
                visited.add(k)
                stage, g1, g2 = free[k]
                a, b = (g1, g2) if node[g1] == here else (g2, g1)
                path.append((stage, a, b))
                here = node[b]
                mapper.used.update(members.shafts_of(mapper.shaft_of(b)))
                if terminal(here):
                    break
                k = next((j for j in incident[here] if j not in visited), None)
                if k is None:
                    break
            out.append(_stage_table(mapper, start, here, path, CUSTOM_ELEMENT, _custom))
    loop = [free[k][0] for k in range(len(free)) if k not in visited]
    if loop:
        raise model.error(loop[0], None, "the stage belongs to a chain of meshes that closes on itself without a "
                                         "loaded shaft; epicyclic cannot tell its input from its output.")
    return out


def _stage_table(mapper, start, end, path, custom_key: str, custom) -> tuple[dict[str, Any], None]:
    model = mapper.model
    gear_1 = {r.role("stage"): r.role("gear_1") for r in model.relations_of("stage")}

    def reverse(path, start, end):
        return [(s, b, a) for s, a, b in reversed(path)], end, start

    extras = custom(model, path[0][0], custom_key) or custom(model, path[-1][0], custom_key)
    if extras.get("first"):  # written by epicyclic: the stage's first shaft
        if mapper.member(end) == extras["first"] and mapper.member(start) != extras["first"]:
            path, start, end = reverse(path, start, end)
    elif gear_1.get(path[0][0].id) != path[0][1] and gear_1.get(path[-1][0].id) == path[-1][2]:
        path, start, end = reverse(path, start, end)  # from the end where the file's gear_1 sits
    first_stage = path[0][0]
    extras.pop("first", None), extras.pop("second", None)
    label = " + ".join(s.name or f"cylindrical_stage {s.id}" for s, _, _ in path)
    name = element_name(Component(first_stage.id, first_stage.type, extras.pop("name", label)), mapper.element_names)
    mapper.origins[f"gear.{name}"] = ", ".join(mapper.label(s) for s, _, _ in path)
    first, second = mapper.member(start), mapper.member(end)
    for side, member in (("first", first), ("second", second)):
        if member == HOUSING:
            raise model.error(first_stage, None, f"the {side} end of the stage chain {label!r} is the casing; a "
                                                 "fixed-axis stage turns between two moving shafts.")
    if start == end:
        raise model.error(first_stage, None, f"the stage chain {label!r} starts and ends on the same shaft "
                                             f"{first!r}.")
    data = [(s, mapper.gear(a), mapper.gear(b)) for s, a, b in path]
    for stage, ga, gb in data:
        mapper.check_center_distance(stage, ga, gb)
    meshes = [[ga.teeth, gb.teeth, "internal" if ga.internal or gb.internal else "external"] for _, ga, gb in data]
    table: dict[str, Any] = {"name": name, "first": first, "second": second, "meshes": meshes}
    for k, (_, ga, gb) in enumerate(data):
        for side, g in (("first", ga), ("second", gb)):
            if g.material:
                mapper.materials[f"{name}.mesh{k + 1}.{side}"] = g.material
    if all(ga.module is not None and gb.module is not None for _, ga, gb in data):
        table["geometry"] = _stage_geometry(mapper, data)
        table["geometry"].update(extras.pop("geometry", {}))
    table.update(extras)
    return table, None


def _ratio_stages(mapper) -> list[tuple[dict[str, Any], None]]:
    """Stages epicyclic wrote by their ratio alone: a ``cylindrical_stage`` without gears, its data custom."""
    model, out = mapper.model, []
    meshed = {s.id for s, _, _ in mapper.meshes}
    for stage in model.of_type("cylindrical_stage"):
        if stage.id in meshed or stage.id in mapper.stage_owner:
            continue
        extras = _custom(model, stage, CUSTOM_ELEMENT)
        if "ratio" not in extras:
            continue  # a stage without gears and ratio: nothing to read (counted as ignored)
        mapper.used.add(stage.id)
        name = element_name(Component(stage.id, stage.type, extras.pop("name", stage.name)), mapper.element_names)
        mapper.origins[f"gear.{name}"] = mapper.label(stage)
        out.append(({"name": name, **extras}, None))
    return out


def _stage_geometry(mapper, data) -> dict[str, Any]:
    model = mapper.model

    def per_mesh(values: list[float | None], default: float | None = None):
        if all(v is None for v in values):
            return None
        filled = [default if v is None else v for v in values]
        return filled[0] if all(abs(v - filled[0]) < 1e-12 for v in filled) else filled

    for stage, ga, gb in data:
        if abs(ga.module - gb.module) > 1e-9:
            raise model.error(stage, None, f"its two gears have different normal modules ({ga.module} and "
                                           f"{gb.module} mm); a mesh has one.")
    geometry: dict[str, Any] = {"module": per_mesh([ga.module for _, ga, _ in data])}
    for key, attr, default in (("pressure_angle", "pressure_angle", 20.0), ("helix_angle", "helix_angle", 0.0),
                               ("addendum", "addendum", 1.0), ("dedendum", "dedendum", 1.25)):
        value = per_mesh([getattr(ga, attr) if getattr(ga, attr) is not None else getattr(gb, attr)
                          for _, ga, gb in data], default)
        if value is not None:
            geometry[key] = value
    if any(ga.profile_shift or gb.profile_shift for _, ga, gb in data):
        geometry["profile_shift"] = [[ga.profile_shift or 0.0, gb.profile_shift or 0.0] for _, ga, gb in data]
    widths = []
    for stage, ga, gb in data:
        if model.has(stage, "common_face_width"):
            widths.append(model.number(stage, "common_face_width", "length"))
        elif ga.face_width is not None and gb.face_width is not None:
            widths.append(min(ga.face_width, gb.face_width))
        else:
            widths.append(None)
    if all(w is not None for w in widths):
        geometry["face_width"] = widths[0] if len(set(widths)) == 1 else widths
    return geometry
