"""Write a train description as REXS 1.7: the mapping of :mod:`~epicyclic.exchange.mapping` backwards.

Every shaft becomes a ``shaft`` (the housing is the ``gear_casing``; a set
member that is the housing sits on a shaft coupled to the casing); a
``[[planetary]]`` with tooth counts a ``planetary_stage`` with its central,
carrier and (one per planet) planet shafts, gears, ``cylindrical_stage``
meshes, flanks (profile shift, pressure angle) and tool (dedendum); a
``[[gear]]`` a chain of ``cylindrical_stage``\\ s over intermediate shafts; a
clutch or brake a ``switchable_coupling`` whose ``is_engaged`` lists the
schedule's gears; the operating point shaft speeds (``defines_speed``) and
``external_load``\\ s (``defines_torque``, ``torque_around_u_axis`` or
``power``).  What REXS has no attribute for travels in ``custom_epicyclic_*``
attributes (:mod:`~epicyclic.exchange.custom`), so the file reads back to the
same train: same ratios, efficiencies and forces (tested for every bundled
example).

References
----------
REXS 1.7 database (``rexs_schema_1.7.xml``, FVA GmbH, github.com/fva-net/rexs-api-java, Apache-2.0);
ISO 21771:2007 (helix hands: an external pair of opposite hand, an internal pair of the same hand).
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import Any

from ..io.expressions import evaluate
from ..model import HOUSING
from .bearing_map import planet_bearing_attributes
from .custom import CUSTOM_DOCUMENT, CUSTOM_ELEMENT, SPIN_TABLES
from .rating_write import RatingWriter
from .serialize import RexsBuilder

__all__ = ["build_rexs"]

_ROLE = "custom_epicyclic_role"
_NATIVE_SET = {"name", "sun", "ring", "carrier", "teeth", "planets", "geometry"}
_NATIVE_GEAR = {"name", "first", "second", "meshes", "geometry"}
_NATIVE_GEOMETRY = {"module", "pressure_angle", "helix_angle", "addendum", "dedendum", "profile_shift",
                    "face_width", "ring_module", "planets", "internal_shift_convention"}


def _iso(x: Any, internal: bool, geometry: Mapping[str, Any] | None) -> Any:
    """An internal gear's profile shift in the ISO 21771 sign REXS uses (a file in the KHK sign: −x)."""
    khk = internal and (geometry or {}).get("internal_shift_convention") == "khk"
    return -_number(x) if khk and x is not None else x


def _number(value: Any) -> float:
    return evaluate(value, "value") if isinstance(value, str) else float(value)


def _f(aid: str, value: Any, unit: str = "none") -> tuple[str, str, Any, str]:
    return (aid, "floating_point", None if value is None else _number(value), unit)


def _json(table: Mapping[str, Any]) -> str:
    return json.dumps(table, ensure_ascii=False, allow_nan=False, separators=(",", ":"))


def build_rexs(train_file, document: Mapping[str, Any], load_cases: Sequence = (), *,
               application_version: str = "", date: str | None = None) -> RexsBuilder:
    """The REXS model of ``train_file`` (read from ``document``), ready to be written as XML or JSON.

    Parameters
    ----------
    train_file : TrainFile
        The train read (and so checked) from ``document``.
    document : mapping
        The parsed train file (TOML tables, or a REXS file's mapped document).
    load_cases : sequence of RexsLoadCase, optional
        Several operating points (a REXS file's load spectrum) to write as a load spectrum; default the
        file's one operating point.
    application_version : str, default ""
        ``applicationVersion`` (epicyclic's version).
    date : str, optional
        The file's date (ISO 8601 with offset); default now.

    Returns
    -------
    RexsBuilder
    """
    return _Writer(train_file, document, application_version, date).run(load_cases)


class _Writer:
    def __init__(self, train_file, document, version: str, date: str | None):
        self.file, self.doc = train_file, document
        self.b = RexsBuilder("epicyclic", version or "0", date)
        self.shafts: dict[str, int] = {}
        self.loads: dict[str, int] = {}
        self.rating = RatingWriter(self.b, getattr(train_file, "rating", None))

    # ---- shafts
    def shaft(self, name: str) -> int:
        if name not in self.shafts:
            if name == HOUSING:
                self.shafts[name] = sid = self.b.component("shaft", "housing shaft")
                joint = self.b.component("coupling", "housing shaft to casing")
                self.b.relation("side", [(joint, "assembly"), (sid, "inner_part"), (self.casing, "outer_part")])
            else:
                self.shafts[name] = self.b.component("shaft", name)
            self.b.relation("assembly", [(self.unit, "assembly"), (self.shafts[name], "part")])
        return self.shafts[name]

    def gear(self, shaft: int, name: str, z: int, internal: bool, g: Mapping[str, Any] | None,
             module: float | None, hand: int, x: Any, width: Any) -> int:
        attrs = [("number_of_teeth", "integer", int(z), "none")]
        if g is not None:
            attrs += [_f("normal_module", module, "mm"), _f("face_width", width, "mm"),
                      _f("helix_angle_reference_diameter", hand * _number(g.get("helix_angle", 0.0)), "deg")]
        gid = self.b.component("ring_gear" if internal else "cylindrical_gear", name, attrs)
        self.b.relation("assembly", [(shaft, "assembly"), (gid, "part")])
        if g is not None:
            flank = [_f("normal_pressure_angle", g.get("pressure_angle", 20.0), "deg"),
                     _f("addendum_modification_coefficient", x if x is not None else 0.0),
                     _f("addendum_coefficient_basic_profile", g.get("addendum"))]
            left = self.b.component("cylindrical_gear_flank", f"{name} (left flank)", flank)
            right = self.b.component("cylindrical_gear_flank", f"{name} (right flank)", flank)
            self.b.relation("flank", [(gid, "gear"), (left, "left"), (right, "right")])
            self.rating.flanks[gid] = (left, right)
            if "dedendum" in g:
                tool = self.b.component("rack_shaped_tool", f"{name} tool", [
                    _f("addendum_coefficient_reference_profile", g["dedendum"])])
                self.rating.tool(gid, tool, f"{name} manufacturing", order=1)
        return gid

    def mesh(self, owner: int | None, name: str, g1: int, g2: int, width: Any = None, distance: float | None = None):
        sid = self.b.component("cylindrical_stage", name, [_f("common_face_width", width, "mm"),
                                                           _f("center_distance", distance, "mm")])
        self.b.relation("assembly", [(owner if owner is not None else self.unit, "assembly"), (sid, "part")])
        self.b.relation("stage", [(sid, "stage"), (g1, "gear_1"), (g2, "gear_2")])
        return sid

    # ---- the model
    def run(self, load_cases: Sequence):
        doc, b = self.doc, self.b
        transmission = self.file.transmission
        gears = list(transmission.schedule) if transmission else []
        index = gears.index(self.file.gear) + 1 if transmission and self.file.gear in gears else 1
        extras = {k: doc[k] for k in ("title", "description", "units", "shafts", "lubricant", "rating",
                                      "duty_cycle", *SPIN_TABLES) if k in doc}
        if transmission:
            extras["gears"] = gears
            extras["transmission"] = {"input": transmission.input, "output": transmission.output}
        if load_cases and "operating_point" in doc:  # the spectrum's cases replace the model's point: keep it,
            extras["operating_point"] = doc["operating_point"]  # also when the cases came from a REXS file
        self.unit = b.component("gear_unit", self.file.title, [
            ("number_of_gears", "integer", max(len(gears), 1), "none"), ("gear_shift_index", "integer", index, "none"),
            (CUSTOM_DOCUMENT, "string", _json(extras), "none")]
            + ([_f("operating_time", self.file.rating.life, "h")] if getattr(self.file, "rating", None) else []))
        self.casing = b.component("gear_casing", "casing")
        b.relation("assembly", [(self.unit, "assembly"), (self.casing, "part")])
        if "lubricant" in doc:
            oil = doc["lubricant"]
            b.component("lubricant", "lubricant", [
                _f("viscosity_at_40_degree_celsius", oil.get("viscosity_40"), "mm^2 / s"),
                _f("viscosity_at_100_degree_celsius", oil.get("viscosity_100"), "mm^2 / s")])
        for table in doc.get("planetary", []):
            self.planetary(table)
        for table in doc.get("gear", []):
            self.stage(table)
        for kind in ("clutch", "brake"):
            for table in doc.get(kind, []):
                self.shift(kind, table, gears)
        for name in self.file.train.shafts:
            if name != HOUSING:
                self.shaft(name)
        if load_cases:
            points = [c.to_operating_point() for c in load_cases]
        else:
            points = [self.file.operating_point] if self.file.operating_point is not None else []
        if points:
            self.operating(points, list(load_cases))
        return b

    def planetary(self, t: Mapping[str, Any]) -> None:
        b = self.b
        extras = {k: v for k, v in t.items() if k not in _NATIVE_SET}
        g = t.get("geometry")
        if g is not None:
            extras_geometry = {k: v for k, v in g.items() if k not in _NATIVE_GEOMETRY}
            if extras_geometry:
                extras["geometry"] = extras_geometry
        teeth = t.get("teeth")
        kind = (teeth or {}).get("kind", "simple")
        if teeth is not None and (kind == "stepped" and teeth.get("ring_internal", True) is False
                                  or "module_ratio" in teeth and g is None):
            extras["teeth"] = {k: v for k, v in teeth.items() if k in ("kind", "ring_internal", "module_ratio")}
        if teeth is None:
            extras["name"] = t["name"]
        stage = b.component("planetary_stage", t["name"], [(CUSTOM_ELEMENT, "string", _json(extras), "none")]
                            if extras else [])
        b.relation("assembly", [(self.unit, "assembly"), (stage, "part")])
        carrier = b.component("planet_carrier", f"{t['name']} carrier")
        b.relation("assembly", [(stage, "assembly"), (carrier, "part")])
        sun, ring, arm = (self.shaft(t[k]) for k in ("sun", "ring", "carrier"))
        b.relation("central_shaft", [(stage, "planetary_stage"), (sun, "shaft")], order=1)
        b.relation("central_shaft", [(stage, "planetary_stage"), (ring, "shaft")], order=2)
        b.relation("planet_carrier_shaft", [(stage, "planetary_stage"), (arm, "shaft")])
        if teeth is None:
            return
        planets = int(t.get("planets", (g or {}).get("planets", 3)))
        m1 = _number(g["module"]) if g is not None else None
        ratio = _number(teeth.get("module_ratio", 1.0))
        m2 = (_number(g["ring_module"]) if g is not None and "ring_module" in g else
              (m1 * ratio if m1 is not None else None))
        shift = (g or {}).get("profile_shift", {})
        width = (g or {}).get("face_width")

        def w(role):
            return width.get(role) if isinstance(width, dict) else width

        name = t["name"]
        shape = self.file.geometry.get(name)
        a = [m.center_distance for m in shape.meshes] if shape is not None else [None, None, None]
        if kind == "simple":
            roles = [("sun", False, m1, 1), ("ring", True, m1, -1)]
            planet_gears = [("planet", "planet", m1)]
        elif kind == "double":
            roles = [("sun", False, m1, 1), ("ring", True, m1, 1)]
            planet_gears = [("planet_sun", "planet1", m1), ("planet_ring", "planet2", m1)]
        elif kind == "stepped":
            roles = [("sun", False, m1, 1), ("ring", teeth.get("ring_internal", True) is not False, m2, 1)]
            planet_gears = [("planet_sun", "planet_sun", m1), ("planet_ring", "planet_ring", m2)]
        else:
            internal = kind == "two_rings"
            roles = [("first", internal, m1, 1), ("second", internal, m2, 1)]
            planet_gears = [("planet_first", "planet_first", m1), ("planet_second", "planet_second", m2)]
        (c1, int1, mod1, hand1), (c2, int2, mod2, _) = roles
        gear_name = {"sun": "sun", "ring": "ring", "first": "first", "second": "second"}
        central1 = self.gear(sun, f"{name} {c1}", teeth[c1], int1, g, mod1, hand1,
                             _iso(shift.get(gear_name[c1]), int1, g), w(c1))
        central2 = self.gear(ring, f"{name} {c2}", teeth[c2], int2, g, mod2, -1 if int2 else 1,
                             _iso(shift.get(gear_name[c2]), int2, g), w(c2))
        self.rating.gear(central1, name, c1)
        self.rating.gear(central2, name, c2)
        for k in range(planets):
            if kind == "double":
                inner = b.component("shaft", f"{name} planet {k + 1} (sun side)")
                outer = b.component("shaft", f"{name} planet {k + 1} (ring side)")
                for p in (inner, outer):
                    b.relation("planet_shaft", [(stage, "planetary_stage"), (p, "shaft")])
                p1 = self.gear(inner, f"{name} planet {k + 1} sun side", teeth["planet_sun"], False, g, m1, -1,
                               shift.get("planet1"), w("planet1"))
                p2 = self.gear(outer, f"{name} planet {k + 1} ring side", teeth["planet_ring"], False, g, m1, 1,
                               shift.get("planet2"), w("planet2"))
                self.rating.gear(p1, name, "planet1")
                self.rating.gear(p2, name, "planet2")
                for sid, mesh in ((self.mesh(stage, f"{name} sun-planet {k + 1}", central1, p1, w("sun"), a[0]),
                                   "sun-planet1"),
                                  (self.mesh(stage, f"{name} planets {k + 1}", p1, p2, w("planet1"),
                                             a[1] if len(a) > 2 else None), "planet1-planet2"),
                                  (self.mesh(stage, f"{name} planet {k + 1}-ring", p2, central2, w("ring"), a[-1]),
                                   "planet2-ring")):
                    self.rating.mesh(sid, name, mesh)
                continue
            pshaft = b.component("shaft", f"{name} planet {k + 1}")
            b.relation("planet_shaft", [(stage, "planetary_stage"), (pshaft, "shaft")])
            self.planet_bearing(name, k, arm, pshaft)
            made = [self.gear(pshaft, f"{name} planet {k + 1} {key}", teeth[key], False, g, module, -1,
                              shift.get(geo), w(geo)) for key, geo, module in planet_gears]
            for gid, (_, geo, _) in zip(made, planet_gears):
                self.rating.gear(gid, name, geo)
            first, last = planet_gears[0][1], planet_gears[-1][1]
            self.rating.mesh(self.mesh(stage, f"{name} {c1}-planet {k + 1}", central1, made[0], None, a[0]), name,
                             f"{c1}-{first}")
            self.rating.mesh(self.mesh(stage, f"{name} planet {k + 1}-{c2}", made[-1], central2, None, a[-1]), name,
                             f"{last}-{c2}")

    def planet_bearing(self, name: str, k: int, carrier: int, planet: int) -> None:
        """The planet's rolling bearing (``bearings.planet`` of the set) between carrier and planet shaft."""
        rating = (getattr(self.file, "bearings", None) or {}).get(name, {}).get("planet")
        if rating is None:
            return
        bid = self.b.component("rolling_bearing_with_catalog_geometry", f"{name} planet {k + 1} bearing",
                               planet_bearing_attributes(rating))
        self.b.relation("side", [(bid, "assembly"), (carrier, "inner_part"), (planet, "outer_part")])

    def stage(self, t: Mapping[str, Any]) -> None:
        b = self.b
        extras = {k: v for k, v in t.items() if k not in _NATIVE_GEAR}
        extras["name"], extras["first"], extras["second"] = t["name"], t["first"], t["second"]
        g = t.get("geometry")
        if g is not None:
            extras_geometry = {k: v for k, v in g.items() if k not in _NATIVE_GEOMETRY}
            if extras_geometry:
                extras["geometry"] = extras_geometry
        custom = [(CUSTOM_ELEMENT, "string", _json(extras), "none")]
        if "meshes" not in t:  # a stage given by its ratio: no gears, epicyclic's data only
            extras["second"] = t["second"]
            custom = [(CUSTOM_ELEMENT, "string", _json(extras), "none")]
            sid = b.component("cylindrical_stage", t["name"], custom)
            b.relation("assembly", [(self.unit, "assembly"), (sid, "part")])
            self.shaft(t["first"]), self.shaft(t["second"])
            return
        meshes = t["meshes"]
        here = self.shaft(t["first"])
        shape = self.file.geometry.get(t["name"])
        distances = [m.center_distance for m in shape.meshes] if shape is not None else [None] * len(meshes)

        def per(key, j, default=None):
            value = (g or {}).get(key, default)
            return value[j] if isinstance(value, list) else value

        for j, mesh in enumerate(meshes):
            z1, z2 = int(mesh[0]), int(mesh[1])
            internal = len(mesh) > 2 and mesh[2] == "internal"
            last = j == len(meshes) - 1
            there = self.shaft(t["second"]) if last else b.component("shaft", f"{t['name']} shaft {j + 1}")
            if not last:
                b.relation("assembly", [(self.unit, "assembly"), (there, "part")])
            geometry = None
            if g is not None:
                geometry = {k: per(k, j) for k in ("helix_angle", "pressure_angle", "addendum", "dedendum")
                            if per(k, j) is not None}
            module = per("module", j) if g is not None else None
            shifts = (g or {}).get("profile_shift", [[0.0, 0.0]] * len(meshes))[j]
            width = per("face_width", j)
            ring1 = internal and z1 > z2
            g1 = self.gear(here, f"{t['name']} mesh {j + 1} first", z1, ring1, geometry,
                           None if module is None else _number(module), 1, _iso(shifts[0], ring1, g), width)
            g2 = self.gear(there, f"{t['name']} mesh {j + 1} second", z2, internal and not ring1, geometry,
                           None if module is None else _number(module), 1 if internal else -1,
                           _iso(shifts[1], internal and not ring1, g), width)
            sid = self.mesh(None, t["name"] if j == 0 else f"{t['name']} mesh {j + 1}", g1, g2, width, distances[j])
            if j == 0:
                b.add(sid, custom)
            here = there

    def shift(self, kind: str, t: Mapping[str, Any], gears: list[str]) -> None:
        schedule = self.file.transmission.schedule if self.file.transmission else {}
        engaged = [t["name"] in schedule[gear] for gear in gears] or [bool(t.get("engaged", True))]
        attributes = [("is_engaged", "boolean_array", engaged, "none")]
        if "drag" in t:  # an open wet clutch's drag model (docs/losses.md): epicyclic's data, REXS has none
            attributes.append((CUSTOM_ELEMENT, "string", _json({"name": t["name"], "drag": t["drag"]}), "none"))
        joint = self.b.component("switchable_coupling", t["name"], attributes)
        self.b.relation("assembly", [(self.unit, "assembly"), (joint, "part")])
        inner = self.shaft(t["shaft"] if kind == "brake" else t["first"])
        outer = self.casing if kind == "brake" else self.shaft(t["second"])
        self.b.relation("side", [(joint, "assembly"), (inner, "inner_part"), (outer, "outer_part")])

    # ---- operating points
    def operating(self, points, cases) -> None:
        b = self.b
        first = points[0]
        roles: dict[str, str] = {}
        for p in points:
            for name in p.drives:
                roles[name] = "drive"
            for name in p.loads:
                roles.setdefault(name, "load")
            for name in list(p.torques) + list(p.powers):
                roles.setdefault(name, "none")
        for name, role in roles.items():
            lid = b.component("external_load", f"load on {name}", [("transmits_torque", "boolean", True, "none"),
                                                                   (_ROLE, "string", role, "none")])
            b.relation("assembly", [(self.shaft(name), "assembly"), (lid, "part")])
            self.loads[name] = lid
        speeds = {name for p in points for name in p.speeds}
        for name in speeds:
            b.add(self.shaft(name), [("defines_speed", "boolean", True, "none")])

        def values(p) -> list[tuple[int, list]]:
            out = []
            for name, speed in p.speeds.items():
                out.append((self.shafts[name], [_f("rotational_speed", speed, "1 / min")]))
            for name, lid in self.loads.items():
                sign = -1.0 if roles[name] == "load" else 1.0
                if name in p.speeds and p.speeds[name] < 0:
                    sign = -sign
                if name in p.torques:
                    value = p.torques[name] if roles[name] == "none" else sign * abs(p.torques[name])
                    out.append((lid, [("defines_torque", "boolean", True, "none"),
                                      _f("torque_around_u_axis", value, "N m")]))
                elif name in p.powers:
                    value = p.powers[name] if roles[name] == "none" else sign * abs(p.powers[name])
                    out.append((lid, [("defines_torque", "boolean", True, "none"),
                                      _f("power", value / 1000.0, "kW")]))
                else:
                    out.append((lid, [("defines_torque", "boolean", False, "none")]))
            return out

        if len(points) == 1:
            for cid, attributes in values(first):
                b.add(cid, attributes)
            return
        for p, case in zip(points, cases):
            overrides = values(p)
            if case.duration_fraction is not None:
                overrides.append((self.unit, [_f("operating_time_fraction", 100.0 * case.duration_fraction, "%")]))
            if case.lubricant_temperature is not None:
                overrides.append((self.casing, [_f("temperature_lubricant", case.lubricant_temperature, "C")]))
            schedule = list(self.file.transmission.schedule) if self.file.transmission else []
            if getattr(case, "gear", None) in schedule:
                overrides.append((self.unit, [("gear_shift_index", "integer", schedule.index(case.gear) + 1, "none")]))
            b.load_case(overrides)
