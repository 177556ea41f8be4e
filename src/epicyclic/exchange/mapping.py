"""Map a REXS model onto a train description: the same document a TOML train file parses to.

:func:`map_model` turns a :class:`~epicyclic.exchange.rexs_model.RexsModel`
into the plain ``dict`` that :func:`tomllib.loads` gives for a train file
(``docs/file-format.md``), so that the train file reader — geometry tables,
operating point, shift schedule, every check and message — reads REXS too.
Which REXS component/attribute becomes which key is tabled in
``docs/file-format.md`` ("REXS"):

* ``planetary_stage``: its ``central_shaft``\\ s carry the sun
  (``cylindrical_gear``) and ring (``ring_gear``), its ``planet_shaft``\\ s the
  planets (one gear: simple; two gears: stepped, two rings, two suns; planets
  meshing each other: double), its ``planet_carrier_shaft``\\ s the carrier →
  ``[[planetary]]`` with ``teeth``, ``planets`` and a ``geometry`` table;
* ``cylindrical_stage`` chains outside planetary stages → ``[[gear]]`` with
  ``meshes`` (intermediate shafts and idlers folded in) and ``geometry``;
* ``switchable_coupling`` → ``[[clutch]]`` between two members, ``[[brake]]``
  against the casing; ``is_engaged`` per gear with the ``gear_unit``'s
  ``number_of_gears`` → ``[transmission]`` schedule;
* shafts and ``external_load``\\ s, and each ``load_case`` of a
  ``load_spectrum`` → ``[operating_point]`` (:mod:`~epicyclic.exchange.operating`).

What the train model has no use for (shaft sections, bearings, FE data, ...)
is counted in one summary line, never an error.  Values that only epicyclic
knows (efficiencies, loss models, gear names of the schedule) travel in
``custom_epicyclic_*`` attributes — REXS's extension mechanism — so that a
file written by :mod:`~epicyclic.exchange.writing` reads back unchanged.

References
----------
REXS 1.7 component and relation database (``rexs_schema_1.7.xml``, FVA GmbH,
github.com/fva-net/rexs-api-java, Apache-2.0); REXS modelling guideline for planetary stages
(the FVA-Workbench model ``FVA_Planetary_stage_-_Minus_gearing_1.1.rexs`` in the same repository).
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any

from ..model import HOUSING
from .chains import chains
from .custom import CUSTOM_DOCUMENT, CUSTOM_ELEMENT, SPIN_TABLES, custom as _custom
from .gears import GearData, gear_data, gear_links
from .operating import OperatingMapper, RexsLoadCase
from .bearing_map import planet_bearings
from .operating import standard_cases
from .rating_map import merge_rating, rating_table
from .rexs_model import Component, RexsModel
from .topology import GEAR_TYPES, Members, element_name

__all__ = ["CUSTOM_DOCUMENT", "CUSTOM_ELEMENT", "RexsDocument", "map_model"]



@dataclass(frozen=True)
class RexsDocument:
    """A REXS model mapped onto a train description.

    Attributes
    ----------
    source : str
        The REXS file.
    data : mapping
        The train document (as :func:`tomllib.loads` gives it for a TOML train file).
    origins : mapping str → str
        ``"planetary.P"``, ``"gear.G"``, ``"clutch.C"``, ``"brake.B"``, ``"shaft.S"`` → the REXS
        component(s) it came from, e.g. ``"planetary_stage 9 'Planetenstufe [9]'"``.
    load_cases : tuple of RexsLoadCase
        Every load case of the file's load spectra (the first is ``data["operating_point"]``), or the
        one operating point of the model's components.
    ignored : str
        One line: what the file holds that the train model does not use (``"ignored: 11 shaft sections,
        ..."``), or ``""``.
    version, application, container : str
        The REXS version, the program that wrote it, ``"xml"``/``"json"``/``"zip/xml"``/``"zip/json"``.
    materials : mapping str → str
        Gear (``"P.sun"``, ``"G.mesh1.first"``) → material designation.
    lubricant : mapping or None
        The REXS lubricant as given: ``name``, ``viscosity_40``, ``viscosity_100`` (mm²/s),
        ``density_15`` (kg/dm³), ``temperature`` (°C).
    notes : tuple of str
        What the mapping assumed (a drive read from the sign of torque and speed, ...).
    rating_inputs : mapping
        The ISO 6336 inputs the file's standard attributes give (:func:`~epicyclic.exchange.rating_map.
        rating_table`), also where they are incomplete: what ``epicyclic rate --rating`` completes.
    """

    source: str
    data: Mapping[str, Any]
    origins: Mapping[str, str] = field(default_factory=dict)
    load_cases: tuple[RexsLoadCase, ...] = ()
    ignored: str = ""
    version: str = ""
    application: str = ""
    container: str = "xml"
    materials: Mapping[str, str] = field(default_factory=dict)
    lubricant: Mapping[str, Any] | None = None
    notes: tuple[str, ...] = ()
    rating_inputs: Mapping[str, Any] = field(default_factory=dict)

    def __repr__(self) -> str:
        return f"RexsDocument({self.summary!r})"

    @property
    def summary(self) -> str:
        """One line for the terminal: what was read, and what was ignored."""
        counts = Counter(k for k in ("planetary", "gear", "clutch", "brake") for _ in self.data.get(k, []))
        read = ", ".join(f"{n} {k if n == 1 else k + 's'}" for k, n in counts.items() if n)
        cases = f", {len(self.load_cases)} load cases" if len(self.load_cases) > 1 else ""
        notes = f"; {len(self.notes)} note(s), the first: {self.notes[0]}" if self.notes else ""
        return (f"{self.source}: REXS {self.version} ({self.container}, {self.application or 'unknown program'}): "
                f"{read}{cases}" + (f"; {self.ignored}" if self.ignored else "") + notes)


def _plural(kind: str, n: int) -> str:
    """``"11 shaft sections"``, ``"3 rolling bearings with catalog geometry"``."""
    words = kind.replace("_", " ")
    if n == 1:
        return f"1 {words}"
    head, sep, tail = words.partition(" with ")
    if head.endswith("y") and not head.endswith(("ay", "ey", "oy")):
        head = head[:-1] + "ies"
    elif not head.endswith("s"):
        head += "es" if head.endswith(("sh", "ch", "x")) else "s"
    return f"{n} {head}{sep}{tail}"


def map_model(model: RexsModel) -> RexsDocument:
    """The train document of the REXS ``model``.

    Parameters
    ----------
    model : RexsModel
        As :func:`~epicyclic.exchange.container.read_model` reads it.

    Returns
    -------
    RexsDocument

    Raises
    ------
    RexsValueError
        A component the train needs is incomplete or malformed (the message names the file, the
        component id and name, and the attribute), or the model describes no gear set or stage.
    """
    return _Mapper(model).run()


class _Mapper:
    def __init__(self, model: RexsModel):
        self.model = model
        self.members = Members(model)
        self.used: set[int] = set(self.members.used)
        self.links = gear_links(model)
        self.origins: dict[str, str] = {}
        self.materials: dict[str, str] = {}
        self.element_names: set[str] = set()
        self.notes: list[str] = []
        self.checked: set[tuple] = set()
        self.rating_gears: list[tuple[str, str, GearData]] = []
        self.rating_meshes: list[tuple[str, Component, str | None]] = []  # (element, stage, mesh name)
        self.operating = OperatingMapper(model, self.members, self.used, self.notes)
        self.members.preferred = self.operating.preferred_shafts()
        self.stage_owner: dict[int, int] = {}  # cylindrical_stage id → planetary_stage id
        for relation in model.relations_of("assembly"):
            whole = model.components.get(relation.role("assembly"))
            part = model.components.get(relation.role("part"))
            if whole is not None and part is not None and whole.type == "planetary_stage" \
                    and part.type == "cylindrical_stage":
                self.stage_owner[part.id] = whole.id
        self.meshes: list[tuple[Component, int, int]] = []  # (cylindrical_stage, gear_1, gear_2)
        for relation in model.relations_of("stage"):
            stage = model.component(relation.role("stage"), relation)
            g1, g2 = relation.role("gear_1"), relation.role("gear_2")
            if not all(model.component(g, relation).type in GEAR_TYPES for g in (g1, g2)):
                continue  # a worm, bevel or crossed-helical stage: not read (counted as ignored)
            self.meshes.append((stage, g1, g2))
            self.used.add(stage.id)
        for relation in model.relations_of("stage_gear_data"):
            self.used.add(relation.role("stage_gear_data") or -1)

    def label(self, component: Component) -> str:
        return f"{component.type} {component.id}" + (f" {component.name!r}" if component.name else "")

    def check_center_distance(self, stage: Component, a: GearData, b: GearData) -> None:
        """A note where the REXS ``center_distance`` differs from the working centre distance of the profile
        shifts (ISO 21771), which the geometry tables use."""
        from ..errors import EpicyclicError
        from ..geometry import BasicRack, GearGeometry, MeshGeometry

        if a.module is None or not self.model.has(stage, "center_distance"):
            return
        given = self.model.number(stage, "center_distance", "length")
        key = (frozenset((a.teeth, b.teeth)), given, a.module)  # the planets of a set: one note
        if key in self.checked:
            return
        self.checked.add(key)
        if b.internal and not a.internal or not a.internal and not b.internal:
            first, second = a, b
        else:
            first, second = b, a
        try:
            rack = BasicRack(a.module, a.pressure_angle or 20.0, a.helix_angle or 0.0)
            mesh = MeshGeometry(GearGeometry(first.teeth, rack, first.profile_shift or 0.0),
                                GearGeometry(second.teeth, rack, second.profile_shift or 0.0, internal=second.internal))
            working = mesh.center_distance
        except EpicyclicError:
            return
        if abs(working - given) > max(1e-3, 1e-4 * a.module):
            self.notes.append(f"{self.label(stage)}: REXS gives the centre distance a = {given:g} mm, its profile "
                              f"shifts give a_w = {working:.4f} mm (ISO 21771), which the geometry uses")

    def gear(self, gid: int) -> GearData:
        return gear_data(self.model, self.model.components[gid], self.links, self.used)

    def shaft_of(self, gid: int) -> int:
        if gid not in self.members.gear_shaft:
            raise self.model.error(self.model.components[gid], None,
                                   "the gear is assembled on no shaft (no 'assembly' relation with a shaft).")
        return self.members.gear_shaft[gid]

    def member(self, cid: object) -> str:
        name = self.members.name(cid)
        if name != HOUSING:
            shafts = self.members.shafts_of(cid)
            self.origins.setdefault(f"shaft.{name}", ", ".join(
                self.label(self.model.components[s]) for s in shafts[:4]) + (" ..." if len(shafts) > 4 else ""))
            self.used.update(shafts)
        return name

    # ---- the document
    def run(self) -> RexsDocument:
        model = self.model
        unit = next(iter(model.of_type("gear_unit")), None)
        extras = _custom(model, unit, CUSTOM_DOCUMENT)
        if unit is not None:
            self.used.add(unit.id)
        data: dict[str, Any] = {"title": extras.pop("title", None) or (unit.name if unit and unit.name else
                                                                         f"REXS model {model.source}")[:200]}
        planetary = [self.planetary(stage) for stage in model.of_type("planetary_stage")]
        gears = self.stage_chains()
        clutches, brakes = self.shift_elements()
        if not planetary and not gears:
            raise model.error(None, None, "the model holds no planetary_stage and no cylindrical_stage, so there is "
                                          "no gear train to read (worm, bevel and other stages are not read).")
        for key, items in (("planetary", planetary), ("gear", gears), ("clutch", clutches), ("brake", brakes)):
            if items:
                data[key] = [item for item, _ in items]
                for item, engaged in items:
                    if engaged is not None:
                        item["engaged"] = engaged
        members = {v for group in planetary + gears for k, v in group[0].items() if k in (
            "sun", "ring", "carrier", "first", "second")}
        members |= {t.get("shaft") for t, _ in brakes} | {t.get(k) for t, _ in clutches for k in ("first", "second")}
        lubricant = self.operating.lubricant(extras.pop("lubricant", None))
        if lubricant is not None:
            data["lubricant"] = lubricant
        for key in ("description", "units", "shafts", "rating", "duty_cycle", "operating_point", *SPIN_TABLES):
            if key in extras:
                data[key] = extras.pop(key)
        rating_inputs: dict[str, Any] = {}
        if not gears:  # fixed-axis stages: their gears are not named for [rating]
            rating_inputs, complete = rating_table(model, self.rating_gears, self.rating_meshes, data.get("lubricant"))
            if "rating" in data:  # the standard attributes win over epicyclic's custom copy
                data["rating"] = merge_rating(data["rating"], rating_inputs, self.notes)
            elif complete:
                data["rating"] = rating_inputs
        cases = self.operating.load_cases(members - {None})
        schedule = self.schedule(unit, [t for t, _ in clutches + brakes], cases, extras)
        if schedule is not None:
            data["transmission"] = schedule
            names = list(schedule["schedule"])
            cases = [replace(c, gear=names[int(c.gear) - 1] if c.gear and 1 <= int(c.gear) <= len(names) else None)
                     for c in cases]
        else:
            cases = [replace(c, gear=None) for c in cases]
        if len(cases) > 1 and "duty_cycle" not in data:
            duty = self.duty_cycle(unit, cases)
            if duty is not None:
                data["duty_cycle"] = duty
        if "duty_cycle" in data and len(cases) == len(data["duty_cycle"].get("case", [])) > 1:
            data["duty_cycle"] = standard_cases(data["duty_cycle"], cases)  # the load cases win over the copy
        if cases and "operating_point" not in data:
            data["operating_point"] = dict(cases[0].operating_point)
            if schedule is not None and unit is not None:
                gear = self.current_gear(unit, schedule)
                if gear is not None:
                    data["operating_point"]["gear"] = gear
        return RexsDocument(model.source, data, MappingProxyType(self.origins), tuple(cases), self.ignored(),
                            model.version, model.application, model.container, MappingProxyType(self.materials),
                            self.operating.lubricant_data, tuple(self.notes), MappingProxyType(rating_inputs))

    def ignored(self) -> str:
        left = Counter(c.type for c in self.model.components.values() if c.id not in self.used)
        if not left:
            return ""
        return "ignored: " + ", ".join(_plural(kind, n) for kind, n in sorted(left.items(), key=lambda x: (-x[1], x[0])))

    # ---- planetary stages
    def planetary(self, stage: Component) -> tuple[dict[str, Any], None]:
        model = self.model
        self.used.add(stage.id)
        central = [r.role("shaft") for r in model.relations_of("central_shaft") if r.role("planetary_stage") == stage.id]
        order = {r.role("shaft"): r.order for r in model.relations_of("central_shaft")
                 if r.role("planetary_stage") == stage.id}
        planet_shafts = [r.role("shaft") for r in model.relations_of("planet_shaft")
                         if r.role("planetary_stage") == stage.id]
        carriers = [r.role("shaft") for r in model.relations_of("planet_carrier_shaft")
                    if r.role("planetary_stage") == stage.id]
        self.used.update(s for s in planet_shafts + [r.role("shaft") for r in model.relations_of("planet_pin")
                                                     if r.role("planetary_stage") == stage.id] if s is not None)
        extras = _custom(model, stage, CUSTOM_ELEMENT)
        name = element_name(Component(stage.id, stage.type, extras.pop("name", stage.name)), self.element_names)
        self.origins[f"planetary.{name}"] = self.label(stage)
        if not carriers:
            raise model.error(stage, None, "the stage has no 'planet_carrier_shaft' relation, so the carrier's shaft "
                                           "is unknown; relate the carrier's shaft to the stage.")
        meshes = [(s, g1, g2) for s, g1, g2 in self.meshes if self.stage_owner.get(s.id) == stage.id]
        table: dict[str, Any] = {"name": name}
        if not meshes:  # a stage without gears: only its stationary ratio, from epicyclic's custom data
            if "stationary_ratio" not in extras:
                raise model.error(stage, None, "the stage has no cylindrical_stage meshes (gears with tooth counts) "
                                               "and no stationary ratio; epicyclic cannot read its ratio.")
            centrals = sorted(central, key=lambda s: (order.get(s) or 0, s))
            if len(centrals) != 2:
                raise model.error(stage, None, f"expected 2 central shafts, found {len(centrals)}.")
            table.update(sun=self.member(centrals[0]), ring=self.member(centrals[1]),
                         carrier=self.member(("carrier", stage.id)))
            table.update(extras)
            return table, None
        on = {}
        for _, g1, g2 in meshes:
            for g in (g1, g2):
                on[g] = self.shaft_of(g)
        central_gears = sorted({g for g in on if on[g] in central or self.members.is_housing(on[g])},
                               key=lambda g: (order.get(on[g]) or 0, g))
        planet_gears = {g for g in on if on[g] in planet_shafts}
        stray = [g for g in on if g not in central_gears and g not in planet_gears]
        if stray:
            raise model.error(model.components[stray[0]], None, f"the gear meshes in {self.label(stage)} but sits "
                                                                "neither on a central shaft nor on a planet shaft.")
        if len(central_gears) != 2:
            raise model.error(stage, None, f"the stage meshes {len(central_gears)} central gears; epicyclic reads "
                                           "stages with two (sun and ring, two rings or two suns).")
        gear = {g: self.gear(g) for g in on}
        for mesh_stage, g1, g2 in meshes:
            self.check_center_distance(mesh_stage, gear[g1], gear[g2])
        first, second = central_gears
        if gear[first].internal and not gear[second].internal:
            first, second = second, first  # the external gear is the sun
        links = {(a, b) if b in planet_gears else (b, a) for _, a, b in meshes if (a in central_gears) != (b in central_gears)}
        doubles = {frozenset((a, b)) for _, a, b in meshes if a in planet_gears and b in planet_gears}
        kind, teeth, names = self.kind(stage, gear, first, second, links, doubles, on, extras)
        written = extras.pop("teeth", None)
        if isinstance(written, dict) and "module_ratio" in written:  # epicyclic's module ratio, no geometry
            teeth["module_ratio"] = written["module_ratio"]
        planets = len({on[p] for c, p in links if c == first})
        table.update(sun=self.member(on[first]), ring=self.member(on[second]),
                     carrier=self.member(("carrier", stage.id)), teeth=teeth, planets=planets)
        geometry = self.set_geometry(kind, names, gear, stage, meshes)
        role = {gid: r for r, gid in names.items() if gid in (first, second)}
        self.rating_meshes.extend((name, s, (f"{role[first]}-planet" if first in (g1, g2) else f"planet-{role[second]}")
                                   if kind == "simple" else None) for s, g1, g2 in meshes)
        for role, gid in names.items():
            self.rating_gears.append((name, role, gear[gid]))
            if gear[gid].material:
                self.materials[f"{name}.{role}"] = gear[gid].material
        extra_geometry = extras.pop("geometry", {})
        if geometry is not None:
            geometry.update(extra_geometry)
            table["geometry"] = geometry
        for key, value in extras.items():
            table[key] = value
        bearings = table.get("bearings") if isinstance(table.get("bearings"), dict) else {}
        planet = planet_bearings(model, {p for p in planet_shafts if p is not None}, self.used, self.notes,
                                 bearings.get("planet") if isinstance(bearings.get("planet"), dict) else None,
                                 ((table.get("losses") or {}).get("bearing") or {}).get("type")
                                 if isinstance(table.get("losses"), dict) else None)
        if planet is not None:
            table["bearings"] = {**bearings, "planet": planet}
        return table, None

    def kind(self, stage, gear: dict[int, GearData], first: int, second: int, links, doubles, on, extras):
        model = self.model
        ext_first, ext_second = not gear[first].internal, not gear[second].internal
        pairs_first = {p for c, p in links if c == first}
        pairs_second = {p for c, p in links if c == second}

        def same(gears: set[int], what: str) -> int:
            counts = {gear[g].teeth for g in gears}
            if len(counts) != 1:
                raise model.error(stage, None, f"the {what} gears have different tooth counts "
                                               f"{sorted(counts)}; epicyclic reads identical planets.")
            return counts.pop()

        wanted = (extras.get("teeth") or {}).get("kind") if isinstance(extras.get("teeth"), dict) else None
        if doubles:
            if not (ext_first and not ext_second):
                raise model.error(stage, None, "planets mesh each other, but the central gears are not a sun and a "
                                               "ring; epicyclic reads such a double-planet set with a sun and a ring.")
            inner = {g for g in pairs_first}
            outer = {g for g in pairs_second}
            z = {"sun": gear[first].teeth, "planet_sun": same(inner, "inner planet"),
                 "planet_ring": same(outer, "outer planet"), "ring": gear[second].teeth}
            return "double", {"kind": "double", **z}, {"sun": first, "planet1": min(inner), "planet2": min(outer),
                                                      "ring": second}
        common = pairs_first & pairs_second
        if common and common == pairs_first == pairs_second:  # one planet gear meshes both: a simple set
            if ext_first == ext_second:
                raise model.error(stage, None, "one planet gear meshes two central gears of the same kind "
                                               "(both external or both internal); that set cannot turn.")
            z = {"sun": gear[first].teeth, "planet": same(common, "planet"), "ring": gear[second].teeth}
            return "simple", z, {"sun": first, "planet": min(common), "ring": second}
        if not pairs_first or not pairs_second:
            raise model.error(stage, None, "no planet gear meshes one of the two central gears.")
        by_shaft = {on[p]: p for p in pairs_second}
        try:
            steps = [(p, by_shaft[on[p]]) for p in pairs_first]
        except KeyError:
            raise model.error(stage, None, "a planet shaft carries a gear that meshes only one central gear and no "
                                           "second gear meshing the other.") from None
        z1, z2 = same({a for a, _ in steps}, "first planet"), same({b for _, b in steps}, "second planet")
        p1, p2 = min(a for a, _ in steps), min(b for _, b in steps)
        if ext_first and not ext_second:
            return "stepped", {"kind": "stepped", "sun": gear[first].teeth, "planet_sun": z1, "planet_ring": z2,
                               "ring": gear[second].teeth}, {"sun": first, "planet_sun": p1, "planet_ring": p2,
                                                             "ring": second}
        if ext_first and ext_second and wanted == "stepped":
            return "stepped", {"kind": "stepped", "sun": gear[first].teeth, "planet_sun": z1, "planet_ring": z2,
                               "ring": gear[second].teeth, "ring_internal": False}, {
                "sun": first, "planet_sun": p1, "planet_ring": p2, "ring": second}
        kind = "two_suns" if ext_first else "two_rings"
        return kind, {"kind": kind, "first": gear[first].teeth, "planet_first": z1, "planet_second": z2,
                      "second": gear[second].teeth}, {"first": first, "planet_first": p1, "planet_second": p2,
                                                      "second": second}

    def set_geometry(self, kind: str, names: dict[str, int], gear: dict[int, GearData], stage, meshes):
        data = {role: gear[g] for role, g in names.items()}
        if any(d.module is None for d in data.values()):
            return None
        roles = list(names)
        first_mesh_module = data[roles[0]].module
        last = data[roles[-1]].module
        geometry: dict[str, Any] = {"module": first_mesh_module}
        if kind in ("stepped", "two_rings", "two_suns") and abs(last - first_mesh_module) > 1e-12:
            geometry["ring_module"] = last
        elif abs(last - first_mesh_module) > 1e-12 or any(abs(d.module - first_mesh_module) > 1e-12 for d in
                                                          data.values() if kind in ("simple", "double")):
            raise self.model.error(stage, None, f"the gears have different normal modules "
                                                f"{sorted({d.module for d in data.values()})} mm; a {kind} set has one.")
        self.optional(geometry, "pressure_angle", [d.pressure_angle for d in data.values()])
        self.optional(geometry, "helix_angle", [d.helix_angle for d in data.values()])
        self.optional(geometry, "addendum", [d.addendum for d in data.values()])
        self.optional(geometry, "dedendum", [d.dedendum for d in data.values()])
        if any(d.profile_shift for d in data.values()):
            geometry["profile_shift"] = {role: d.profile_shift or 0.0 for role, d in data.items()}
        widths = {role: d.face_width for role, d in data.items()}
        if all(w is not None for w in widths.values()):
            geometry["face_width"] = widths
        return geometry

    @staticmethod
    def optional(table: dict, key: str, values: list[float | None]) -> None:
        given = [v for v in values if v is not None]
        if given:
            table[key] = given[0]

    # ---- fixed-axis stages
    def stage_chains(self) -> list[tuple[dict[str, Any], None]]:
        return chains(self)

    # ---- clutches and brakes
    def shift_elements(self):
        model = self.model
        clutches, brakes, seen = [], [], {}
        for relation in model.relations_of("side"):
            joint = model.components.get(relation.role("assembly"))
            if joint is None or joint.type != "switchable_coupling":
                continue
            inner, outer = relation.role("inner_part"), relation.role("outer_part")
            if inner is None or outer is None:
                raise model.error(joint, None, "the coupling's 'side' relation lacks an inner or outer part.")
            self.used.add(joint.id)
            engaged = model.booleans(joint, "is_engaged") if model.has(joint, "is_engaged") else (True,)
            a, b = self.member(inner), self.member(outer)
            if a == b:
                self.notes.append(f"{self.label(joint)} joins {a!r} to itself; skipped")
                continue
            key = (frozenset((a, b)), engaged)
            if key in seen:  # two couplings in parallel (FVA models hold a ring with two): one element
                self.origins[seen[key]] += f", {self.label(joint)}"
                continue
            extras = _custom(model, joint, CUSTOM_ELEMENT)
            name = element_name(Component(joint.id, joint.type, extras.pop("name", joint.name)), self.element_names)
            drag = {"drag": extras["drag"]} if "drag" in extras else {}  # written by epicyclic (spin losses)
            if HOUSING in (a, b):
                table = {"name": name, "shaft": b if a == HOUSING else a, **drag}
                brakes.append((table, engaged))
                self.origins[seen.setdefault(key, f"brake.{name}")] = self.label(joint)
            else:
                table = {"name": name, "first": a, "second": b, **drag}
                clutches.append((table, engaged))
                self.origins[seen.setdefault(key, f"clutch.{name}")] = self.label(joint)
        return clutches, brakes

    def schedule(self, unit, elements: list[dict], cases: list[RexsLoadCase], extras: dict) -> dict | None:
        """The [transmission] of a multi-gear model, or None; each element's ``engaged`` set to the current gear."""
        model = self.model
        gears = model.integer(unit, "number_of_gears") if unit is not None and model.has(unit, "number_of_gears") else 1
        index = model.integer(unit, "gear_shift_index") if unit is not None and model.has(unit, "gear_shift_index") else 1
        names = [str(n) for n in extras.get("gears", [])] or [str(k + 1) for k in range(gears)]
        for table in elements:
            engaged = table["engaged"]
            if gears > 1 and len(engaged) != gears:
                raise model.error(unit, "number_of_gears", f"the gear unit has {gears} gears, but "
                                  f"{self.origins.get('clutch.' + table['name']) or self.origins.get('brake.' + table['name'])} "
                                  f"gives is_engaged for {len(engaged)}.")
            table["engaged"] = engaged[min(max(index, 1), len(engaged)) - 1]
            table["_per_gear"] = engaged
        if gears <= 1 or not elements:
            for table in elements:
                table.pop("_per_gear")
            return None
        ends = extras.get("transmission") or {}
        start = ends.get("input") or next((d for c in cases[:1] for d in c.operating_point.get("drives", [])), None)
        end = ends.get("output") or next((d for c in cases[:1] for d in c.operating_point.get("loads", [])), None)
        schedule = {names[k]: [t["name"] for t in elements if t["_per_gear"][k]] for k in range(gears)}
        for table in elements:
            table.pop("_per_gear")
        if start is None or end is None:
            self.notes.append("the gear unit has several gears, but no drive and load to name the transmission's "
                              "input and output: the clutches and brakes are set as in gear_shift_index")
            return None
        return {"input": start, "output": end, "schedule": schedule}

    def duty_cycle(self, unit, cases: list[RexsLoadCase]) -> dict[str, Any] | None:
        """The ``[duty_cycle]`` of a load spectrum whose shares of time sum to 1 (else None and a note); its
        hours are the gear unit's ``operating_time`` where given."""
        shares = [c.duration_fraction for c in cases]
        if any(share is None for share in shares) or abs(sum(shares) - 1.0) > 1e-6:
            self.notes.append("the load spectrum's operating_time_fraction values are missing or do not sum to "
                              "100 %, so it is not read as a [duty_cycle] (TrainFile.load_cases holds its cases)")
            return None
        table: dict[str, Any] = {"name": f"REXS load spectrum {cases[0].spectrum}"}
        if unit is not None and self.model.has(unit, "operating_time"):
            table["hours"] = self.model.number(unit, "operating_time", "time")
        table["case"] = [{"name": f"load case {c.id}", "share": c.duration_fraction, **dict(c.operating_point),
                          **({"gear": c.gear} if c.gear else {})} for c in cases]
        return table

    def current_gear(self, unit, schedule: dict) -> str | None:
        model = self.model
        index = model.integer(unit, "gear_shift_index") if model.has(unit, "gear_shift_index") else 1
        gears = list(schedule["schedule"])
        return gears[index - 1] if 1 <= index <= len(gears) else None
