"""Read a gear train description from a TOML file (stdlib :mod:`tomllib`).

The format is documented key by key in ``docs/file-format.md``; in short::

    title = "Brandenberger 1952, Bild 10"
    [units]                      # optional: units of plain numbers and of reports
    speed = "U/min"
    torque = "kp*cm"
    power = "PS"
    [[planetary]]                # a set: teeth = {...} or stationary_ratio
    name = "planetary"
    sun = "I"
    ring = "II"
    carrier = "III"
    teeth = { kind = "stepped", sun = 50, planet_sun = 24, planet_ring = 30, ring = 42, ring_internal = false }
    stationary_efficiency = 0.9
    [[gear]]                     # a fixed-axis stage: meshes or ratio
    name = "stage"
    first = "III"
    second = "II"
    meshes = [[40, 44, "external"], [20, 64, "external"]]
    [[clutch]], [[brake]]        # shift elements
    [operating_point]            # speeds, torques, powers, drives, loads, gear
    [transmission]               # optional: input, output, schedule

Every problem is reported as an :class:`InputFileError` (or the model's own
error, prefixed with the file and element) that names the file, the element,
the key, what was expected and what was given.  Unknown keys are errors.

References
----------
Brandenberger 1952, Beispiel
(the closed train of Bild 10 in ``examples/brandenberger_1952.toml``).
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

from ..errors import EpicyclicError, ModelError
from ..model import Brake, Clutch, GearStage, GearTrain, OperatingPoint, PlanetarySet
from ..units import Units, to_core
from . import geometry_format
from .expressions import evaluate

__all__ = ["InputFileError", "TrainFile", "Transmission", "load_train_file", "loads_train_file"]

_TOP_KEYS = {"title", "description", "units", "planetary", "gear", "clutch", "brake", "shafts",
             "operating_point", "transmission", "lubricant"}
_PLANETARY_KEYS = {"name", "sun", "ring", "carrier", "teeth", "stationary_ratio", "stationary_efficiency",
                   "mesh_efficiencies", "planets", "geometry", "losses"}
_TEETH_KEYS = {"simple": {"kind", "sun", "planet", "ring"},
               "double": {"kind", "sun", "planet_sun", "planet_ring", "ring"},
               "stepped": {"kind", "sun", "planet_sun", "planet_ring", "ring", "ring_internal", "module_ratio"},
               "two_rings": {"kind", "first", "planet_first", "planet_second", "second", "module_ratio"},
               "two_suns": {"kind", "first", "planet_first", "planet_second", "second", "module_ratio"}}
_GEAR_KEYS = {"name", "first", "second", "meshes", "ratio", "efficiency", "geometry", "losses"}
_CLUTCH_KEYS = {"name", "first", "second", "engaged"}
_BRAKE_KEYS = {"name", "shaft", "engaged"}
_UNIT_KEYS = {"speed", "torque", "power"}
_OP_KEYS = {"speeds", "torques", "powers", "drives", "loads", "gear"}
_TRANSMISSION_KEYS = {"input", "output", "schedule"}


class InputFileError(ModelError):
    """A train description file that cannot be read or is invalid.

    Attributes
    ----------
    source : str
        The file (or ``"<string>"``).
    where : str
        The table and key, e.g. ``"[[planetary]] 'P1', key 'teeth'"``.
    """

    def __init__(self, message: str, source: str = "", where: str = ""):
        self.source = source
        self.where = where
        super().__init__(message)


@dataclass(frozen=True)
class Transmission:
    """A multi-speed transmission: input and output shaft and the shift schedule.

    Parameters
    ----------
    input, output : str
        The input and output shafts.
    schedule : mapping gear name → tuple of str
        For each gear, the clutches and brakes engaged in it (all others open).
    """

    input: str
    output: str
    schedule: Mapping[str, tuple[str, ...]]

    def __post_init__(self) -> None:
        object.__setattr__(self, "schedule", MappingProxyType({k: tuple(v) for k, v in self.schedule.items()}))

    @property
    def gears(self) -> tuple[str, ...]:
        """Gear names in the file's order."""
        return tuple(self.schedule)

    def train_in_gear(self, train: GearTrain, gear: str) -> GearTrain:
        """``train`` with exactly the shift elements of ``gear`` engaged."""
        if gear not in self.schedule:
            raise ModelError(
                f"transmission: no gear {gear!r} in the schedule; gears are "
                f"{', '.join(repr(g) for g in self.schedule) or 'none'}."
            )
        return train.with_engaged(self.schedule[gear])


@dataclass(frozen=True)
class TrainFile:
    """A train description read from a TOML file.

    Attributes
    ----------
    source : str
        File name (or ``"<string>"``).
    title : str
    description : str
    train : GearTrain
        The train as written (clutches and brakes engaged as the file says).
    operating_point : OperatingPoint or None
        In core units (1/min, N·m, W); None if the file has none.
    units : Units
        The user's units (for plain numbers in the file and for reports).
    transmission : Transmission or None
    gear : str or None
        The gear of ``[operating_point] gear``: the operating point applies
        to the train in that gear.
    geometry : mapping element → SetGeometry or StageGeometry
        The elements' ``geometry`` tables (see ``docs/file-format.md``).
    losses : mapping element → ElementLosses
        The elements' ``losses`` tables (mesh friction, planet bearings, drag).
    """

    source: str
    title: str
    train: GearTrain
    operating_point: OperatingPoint | None
    units: Units = field(default_factory=Units)
    transmission: Transmission | None = None
    description: str = ""
    gear: str | None = None
    geometry: Mapping[str, Any] = field(default_factory=dict)
    losses: Mapping[str, Any] = field(default_factory=dict)

    @property
    def operating_train(self) -> GearTrain:
        """The train the operating point applies to (in ``gear`` if one is named)."""
        if self.gear is not None and self.transmission is not None:
            return self.transmission.train_in_gear(self.train, self.gear)
        return self.train

    def solve(self, *, lossless: bool = False):
        """Solve the operating train at the file's operating point.

        Raises
        ------
        InputFileError
            The file has no ``[operating_point]``.
        """
        from ..solver import solve

        if self.operating_point is None:
            raise InputFileError(
                f"{self.source}: the file has no [operating_point] table, so there is nothing to solve; "
                "add speeds, torques or powers, drives and loads.", self.source, "[operating_point]",
            )
        return solve(self.operating_train, self.operating_point, lossless=lossless)


# ---------------------------------------------------------------------- public functions
def load_train_file(path: str | Path) -> TrainFile:
    """Read a train description from a TOML file.

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    TrainFile

    Raises
    ------
    InputFileError
        The file cannot be read, is not valid TOML, or its content is invalid.
    EpicyclicError
        Model errors (tooth counts, efficiencies, shafts), prefixed with the
        file and the element.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputFileError(f"{path}: no such file; give the path of a .toml train description.",
                             str(path)) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputFileError(f"{path}: cannot read the file ({exc}).", str(path)) from None
    return loads_train_file(text, source=str(path))


def loads_train_file(text: str, source: str = "<string>") -> TrainFile:
    """Read a train description from TOML text.

    Examples
    --------
    >>> f = loads_train_file('''
    ... [[planetary]]
    ... name = "P"
    ... sun = "in"
    ... ring = "ring"
    ... carrier = "out"
    ... teeth = { sun = 30, planet = 24, ring = 78 }
    ... [[brake]]
    ... name = "B"
    ... shaft = "ring"
    ... [operating_point]
    ... speeds = { in = "3000 rpm" }
    ... torques = { in = 10 }
    ... drives = ["in"]
    ... loads = ["out"]
    ... ''')
    >>> round(f.solve().speed("out"), 6)
    833.333333
    """
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputFileError(f"{source}: not valid TOML: {exc}. Check quotes, brackets and '=' signs.",
                             source) from None
    return _Reader(source).read(data)


# ---------------------------------------------------------------------- the reader
class _Reader:
    def __init__(self, source: str):
        self.source = source
        self.units = Units()

    # ---- messages
    def error(self, where: str, message: str) -> InputFileError:
        return InputFileError(f"{self.source}: {where}: {message}", self.source, where)

    def wrap(self, where: str, exc: EpicyclicError) -> EpicyclicError:
        """Prefix a model error with file and element, keeping its class where possible."""
        message = f"{self.source}: {where}: {exc}"
        try:
            wrapped = type(exc)(message)
        except TypeError:
            wrapped = InputFileError(message, self.source, where)
        return wrapped

    def check_keys(self, table: Mapping[str, Any], allowed: set[str], where: str) -> None:
        unknown = [k for k in table if k not in allowed]
        if unknown:
            close = _close(unknown[0], allowed)
            raise self.error(
                where,
                f"unknown key {unknown[0]!r}; expected one of {', '.join(sorted(allowed))}"
                + (f" (did you mean {close!r}?)" if close else "") + ".",
            )

    def table(self, value: object, where: str) -> Mapping[str, Any]:
        if not isinstance(value, dict):
            raise self.error(where, f"expected a table, got {_kind(value)} {value!r}.")
        return value

    def require(self, table: Mapping[str, Any], key: str, where: str) -> Any:
        if key not in table:
            raise self.error(where, f"missing key {key!r}.")
        return table[key]

    def string(self, table: Mapping[str, Any], key: str, where: str, default: str | None = None) -> str:
        if key not in table and default is not None:
            return default
        value = self.require(table, key, where)
        if not isinstance(value, str) or not value.strip():
            raise self.error(where, f"key {key!r}: expected a non-empty string, got {_kind(value)} {value!r}.")
        return value

    def boolean(self, table: Mapping[str, Any], key: str, where: str, default: bool) -> bool:
        value = table.get(key, default)
        if not isinstance(value, bool):
            raise self.error(where, f"key {key!r}: expected true or false, got {_kind(value)} {value!r}.")
        return value

    def integer(self, value: object, key: str, where: str) -> int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.error(where, f"key {key!r}: expected a whole number, got {_kind(value)} {value!r}.")
        return value

    def number(self, value: object, key: str, where: str) -> float:
        """A plain number or an arithmetic expression string."""
        if isinstance(value, bool):
            raise self.error(where, f"key {key!r}: expected a number, got the boolean {value!r}.")
        if isinstance(value, (int, float)):
            if not math.isfinite(value):
                raise self.error(where, f"key {key!r}: expected a finite number, got {value!r}.")
            return float(value)
        if isinstance(value, str):
            try:
                return evaluate(value, f"key {key!r}")
            except EpicyclicError as exc:
                raise self.wrap(where, exc) from None
        raise self.error(where, f"key {key!r}: expected a number or an expression such as "
                                f"'(24/50)*(42/30)', got {_kind(value)} {value!r}.")

    def efficiency(self, value: object, key: str, where: str) -> float:
        eta = self.number(value, key, where)
        if not 0.0 < eta <= 1.0:
            raise self.error(where, f"key {key!r}: expected an efficiency in (0, 1] (1 = lossless), got "
                                    f"{value!r}. Give e.g. 0.98, not a percentage or a loss.")
        return eta

    def elements_of(self, data: Mapping[str, Any], key: str) -> list[Mapping[str, Any]]:
        value = data.get(key, [])
        if isinstance(value, dict):
            raise self.error(f"[{key}]", f"write [[{key}]] (an array of tables, one per element), not [{key}].")
        if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
            raise self.error(f"[[{key}]]", f"expected an array of tables, got {_kind(value)}.")
        return value

    # ---- top level
    def read(self, data: Mapping[str, Any]) -> TrainFile:
        self.check_keys(data, _TOP_KEYS, "top level")
        title = self.string(data, "title", "top level", default="gear train")
        description = data.get("description", "")
        if not isinstance(description, str):
            raise self.error("top level", f"key 'description': expected a string, got {_kind(description)}.")
        if "units" in data:
            self.units = self.read_units(self.table(data["units"], "[units]"))
        elements: list = []
        lubricant = geometry_format.read_lubricant(self, data)
        geometry: dict[str, Any] = {}
        losses: dict[str, Any] = {}
        for kind, read in (("planetary", self.read_planetary), ("gear", self.read_gear)):
            for k, table in enumerate(self.elements_of(data, kind)):
                element, shape, model = geometry_format.read_extras(
                    self, kind, table, read(table, k), self.element_where(kind, k, table), lubricant)
                elements.append(element)
                if shape is not None:
                    geometry[element.name] = shape
                if model is not None:
                    losses[element.name] = model
        for k, table in enumerate(self.elements_of(data, "clutch")):
            elements.append(self.read_shift(table, k, "clutch"))
        for k, table in enumerate(self.elements_of(data, "brake")):
            elements.append(self.read_shift(table, k, "brake"))
        if not elements:
            raise self.error("top level", "the file describes no element; add at least one [[planetary]], "
                                          "[[gear]], [[clutch]] or [[brake]] table.")
        shafts = data.get("shafts", [])
        if not isinstance(shafts, list) or not all(isinstance(s, str) and s.strip() for s in shafts):
            raise self.error("top level", f"key 'shafts': expected a list of shaft names, got {shafts!r}.")
        try:
            train = GearTrain(elements, tuple(shafts), title)
        except EpicyclicError as exc:
            raise self.wrap("elements", exc) from None
        transmission = None
        if "transmission" in data:
            transmission = self.read_transmission(self.table(data["transmission"], "[transmission]"), train)
        op, gear = None, None
        if "operating_point" in data:
            op, gear = self.read_operating_point(
                self.table(data["operating_point"], "[operating_point]"), train, transmission)
        return TrainFile(self.source, title, train, op, self.units, transmission, description, gear,
                         MappingProxyType(geometry), MappingProxyType(losses))

    def read_units(self, table: Mapping[str, Any]) -> Units:
        self.check_keys(table, _UNIT_KEYS, "[units]")
        chosen = {k: self.string(table, k, "[units]") for k in table}
        try:
            return Units(**chosen)
        except EpicyclicError as exc:
            raise self.wrap("[units]", exc) from None

    # ---- elements
    def element_where(self, kind: str, k: int, table: Mapping[str, Any]) -> str:
        name = table.get("name")
        return f"[[{kind}]] #{k + 1}" + (f" {name!r}" if isinstance(name, str) else "")

    def read_planetary(self, table: Mapping[str, Any], k: int) -> PlanetarySet:
        where = self.element_where("planetary", k, table)
        self.check_keys(table, _PLANETARY_KEYS, where)
        name = self.string(table, "name", where)
        shafts = {role: self.string(table, role, where) for role in ("sun", "ring", "carrier")}
        planets = self.integer(table.get("planets", 3), "planets", where)
        eta = table.get("stationary_efficiency")
        meshes = table.get("mesh_efficiencies")
        if eta is not None and meshes is not None:
            raise self.error(where, "give 'stationary_efficiency' or 'mesh_efficiencies', not both.")
        eta = None if eta is None else self.efficiency(eta, "stationary_efficiency", where)
        if meshes is not None:
            if not isinstance(meshes, list) or not meshes:
                raise self.error(where, f"key 'mesh_efficiencies': expected a list of efficiencies such as "
                                        f"[0.98, 0.98], got {meshes!r}.")
            meshes = tuple(self.efficiency(v, f"mesh_efficiencies[{j}]", where) for j, v in enumerate(meshes))
        has_teeth, has_ratio = "teeth" in table, "stationary_ratio" in table
        if has_teeth == has_ratio:
            raise self.error(where, "give either 'teeth' (tooth counts) or 'stationary_ratio' (i0), "
                                    + ("not both." if has_teeth else "got neither."))
        try:
            if has_ratio:
                ratio = self.number(table["stationary_ratio"], "stationary_ratio", where)
                if meshes is not None:
                    eta = math.prod(meshes)
                return PlanetarySet(name, stationary_ratio=ratio,
                                    stationary_efficiency=1.0 if eta is None else eta,
                                    planets=planets, **shafts)
            return self.planetary_from_teeth(self.table(table["teeth"], f"{where}, key 'teeth'"),
                                             name, shafts, eta, meshes, planets, where,
                                             geometry_format.module_ratio(self, table, where))
        except InputFileError:
            raise
        except EpicyclicError as exc:
            raise self.wrap(where, exc) from None

    def planetary_from_teeth(self, teeth, name, shafts, eta, meshes, planets, where, ratio=1.0) -> PlanetarySet:
        kind = teeth.get("kind", "simple")
        if kind not in _TEETH_KEYS:
            raise self.error(where, f"key 'teeth.kind': expected 'simple', 'double' or 'stepped' (or "
                                    f"'two_rings' for a Wolfrom set, 'two_suns'), got {kind!r}.")
        self.check_keys(teeth, _TEETH_KEYS[kind], f"{where}, key 'teeth' (kind {kind!r})")
        z = {key: self.integer(self.require(teeth, key, f"{where}, key 'teeth' (kind {kind!r})"), f"teeth.{key}",
                               where)
             for key in _TEETH_KEYS[kind] - {"kind", "ring_internal", "module_ratio"}}
        if "module_ratio" in teeth:
            ratio = self.number(teeth["module_ratio"], "teeth.module_ratio", where)
        common = dict(stationary_efficiency=eta, mesh_efficiencies=meshes, planets=planets, **shafts)
        if kind in ("two_rings", "two_suns"):
            both = dict(first=common.pop("sun"), second=common.pop("ring"), z_first=z["first"],
                        z_planet_first=z["planet_first"], z_planet_second=z["planet_second"], z_second=z["second"],
                        module_ratio=ratio)
            build = PlanetarySet.two_rings if kind == "two_rings" else PlanetarySet.two_suns
            return build(name, **both, **common)
        if kind == "simple":
            return PlanetarySet.simple(name, z_sun=z["sun"], z_planet=z["planet"], z_ring=z["ring"], **common)
        if kind == "double":
            return PlanetarySet.double_planet(name, z_sun=z["sun"], z_planet_sun=z["planet_sun"],
                                              z_planet_ring=z["planet_ring"], z_ring=z["ring"], **common)
        internal = self.boolean(teeth, "ring_internal", where, True)
        return PlanetarySet.stepped(name, z_sun=z["sun"], z_planet_sun=z["planet_sun"],
                                    z_planet_ring=z["planet_ring"], z_ring=z["ring"], ring_internal=internal,
                                    module_ratio=ratio, **common)

    def read_gear(self, table: Mapping[str, Any], k: int) -> GearStage:
        where = self.element_where("gear", k, table)
        self.check_keys(table, _GEAR_KEYS, where)
        name = self.string(table, "name", where)
        first, second = self.string(table, "first", where), self.string(table, "second", where)
        eta = self.efficiency(table.get("efficiency", 1.0), "efficiency", where)
        has_meshes, has_ratio = "meshes" in table, "ratio" in table
        if has_meshes == has_ratio:
            raise self.error(where, "give either 'meshes' (tooth counts) or 'ratio' (n_first/n_second), "
                                    + ("not both." if has_meshes else "got neither."))
        try:
            if has_ratio:
                return GearStage(name, first, second, self.number(table["ratio"], "ratio", where), eta)
            meshes = table["meshes"]
            if not isinstance(meshes, list) or not meshes:
                raise self.error(where, f"key 'meshes': expected a list such as [[40, 44, \"external\"]], "
                                        f"got {meshes!r}.")
            checked = []
            for j, mesh in enumerate(meshes):
                if not isinstance(mesh, list) or len(mesh) not in (2, 3):
                    raise self.error(where, f"key 'meshes[{j}]': expected [z_driving, z_driven] or "
                                            f"[z_driving, z_driven, \"external\"|\"internal\"], got {mesh!r}.")
                checked.append(tuple(mesh))
            return GearStage.from_teeth(name, first, second, checked, eta)
        except InputFileError:
            raise
        except EpicyclicError as exc:
            raise self.wrap(where, exc) from None

    def read_shift(self, table: Mapping[str, Any], k: int, kind: str):
        where = self.element_where(kind, k, table)
        self.check_keys(table, _CLUTCH_KEYS if kind == "clutch" else _BRAKE_KEYS, where)
        name = self.string(table, "name", where)
        engaged = self.boolean(table, "engaged", where, True)
        try:
            if kind == "clutch":
                return Clutch(name, self.string(table, "first", where), self.string(table, "second", where), engaged)
            return Brake(name, self.string(table, "shaft", where), engaged)
        except InputFileError:
            raise
        except EpicyclicError as exc:
            raise self.wrap(where, exc) from None

    # ---- operating point and transmission
    def read_operating_point(self, table, train: GearTrain, transmission: Transmission | None):
        where = "[operating_point]"
        self.check_keys(table, _OP_KEYS, where)
        values: dict[str, dict[str, float]] = {}
        for group, quantity in (("speeds", "speed"), ("torques", "torque"), ("powers", "power")):
            given = self.table(table.get(group, {}), f"{where} key {group!r}")
            values[group] = {}
            for shaft, value in given.items():
                self.shaft(train, shaft, f"{where} {group}")
                try:
                    values[group][shaft] = to_core(value, quantity, field=f"{group}.{shaft}",
                                                   default_unit=self.units.of(quantity))
                except EpicyclicError as exc:
                    raise self.wrap(where, exc) from None
        roles = {}
        for group in ("drives", "loads"):
            names = table.get(group, [])
            if isinstance(names, str):
                names = [names]
            if not isinstance(names, list) or not all(isinstance(n, str) for n in names):
                raise self.error(where, f"key {group!r}: expected a list of shaft names, got {names!r}.")
            for shaft in names:
                self.shaft(train, shaft, f"{where} {group}")
            roles[group] = tuple(names)
        gear = None
        if "gear" in table:
            gear = table["gear"]
            if transmission is None:
                raise self.error(where, "key 'gear' needs a [transmission] table with a schedule.")
            if not isinstance(gear, str) or gear not in transmission.schedule:
                raise self.error(where, f"key 'gear': expected one of the schedule's gears "
                                        f"{', '.join(repr(g) for g in transmission.schedule)}, got {gear!r}.")
        try:
            op = OperatingPoint(values["speeds"], values["torques"], values["powers"], **roles)
        except EpicyclicError as exc:
            raise self.wrap(where, exc) from None
        return op, gear

    def shaft(self, train: GearTrain, name: str, where: str) -> None:
        train.check_shaft(name, f"{self.source}: {where}")

    def read_transmission(self, table, train: GearTrain) -> Transmission:
        where = "[transmission]"
        self.check_keys(table, _TRANSMISSION_KEYS, where)
        ends = {}
        for key in ("input", "output"):
            ends[key] = self.string(table, key, where)
            self.shaft(train, ends[key], f"{where} {key}")
        schedule_table = self.table(self.require(table, "schedule", where), f"{where}.schedule")
        shift_names = {e.name for e in train.shift_elements}
        schedule: dict[str, tuple[str, ...]] = {}
        for gear, names in schedule_table.items():
            if not isinstance(names, list) or not all(isinstance(n, str) for n in names):
                raise self.error(f"{where}.schedule", f"gear {gear!r}: expected a list of clutch and brake "
                                                      f"names, got {names!r}.")
            for n in names:
                if n not in shift_names:
                    raise self.error(f"{where}.schedule", f"gear {gear!r}: {n!r} is not a clutch or brake of "
                                                          f"the train; shift elements are "
                                                          f"{', '.join(sorted(shift_names)) or 'none'}.")
            schedule[gear] = tuple(names)
        if not schedule:
            raise self.error(f"{where}.schedule", "expected at least one gear, got none.")
        return Transmission(ends["input"], ends["output"], schedule)


def _kind(value: object) -> str:
    return {bool: "a boolean", int: "an integer", float: "a number", str: "a string", list: "an array",
            dict: "a table"}.get(type(value), type(value).__name__)


def _close(word: str, options: set[str]) -> str | None:
    import difflib

    match = difflib.get_close_matches(word, sorted(options), n=1, cutoff=0.6)
    return match[0] if match else None

