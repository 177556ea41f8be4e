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
the key, what was expected and what was given.  Unknown keys are errors.  The
file is read within the limits of :mod:`epicyclic.limits` (size, nesting,
string lengths, counts; see :mod:`epicyclic.io.source`), and errors the
solver raises later are located in ``[operating_point]`` by
:meth:`TrainFile.solve`.

References
----------
Brandenberger 1952, Beispiel
(the closed train of Bild 10 in ``examples/brandenberger_1952.toml``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

from ..errors import EpicyclicError
from ..limits import MAX_ELEMENTS, MAX_GEARS, MAX_MESHES, MAX_SHAFTS, MAX_TITLE_CHARS, check_count, max_file_bytes
from ..model import HOUSING, Brake, Clutch, GearStage, GearTrain, OperatingPoint, PlanetarySet
from ..model.planetary import check_planets
from ..text import short, terminal_text
from ..units import Units, to_core
from .elastic_format import read_elastic
from .located import locate_error, operating_point_where
from .overrides import OverrideError, apply_overrides
from .reader import TableReader, at_key, kind_of
from .schedule import Transmission, rated_limits
from .source import InputFileError, check_document, decode_source, parse_toml, read_bytes, sniff

__all__ = ["InputFileError", "TrainFile", "Transmission", "load_train_file", "loads_train_file", "read_document"]

_SPIN_TABLES = ("pump", "housing", "seal", "churning", "windage", "defaults")  # io.spin_format reads them
_TOP_KEYS = {"title", "description", "units", "planetary", "gear", "clutch", "brake", "shafts",
             "operating_point", "transmission", "lubricant", "rating", "duty_cycle", "elastic", *_SPIN_TABLES,
             "dynamics", "engine"}  # the transient's inputs: io.dynamics_format reads them
_PLANETARY_KEYS = {"name", "sun", "ring", "carrier", "teeth", "stationary_ratio", "stationary_efficiency",
                   "mesh_efficiencies", "planets", "geometry", "losses", "bearings"}
_TEETH_KEYS = {"simple": {"kind", "sun", "planet", "ring"},
               "double": {"kind", "sun", "planet_sun", "planet_ring", "ring"},
               "stepped": {"kind", "sun", "planet_sun", "planet_ring", "ring", "ring_internal", "module_ratio"},
               "two_rings": {"kind", "first", "planet_first", "planet_second", "second", "module_ratio"},
               "two_suns": {"kind", "first", "planet_first", "planet_second", "second", "module_ratio"}}
_GEAR_KEYS = {"name", "first", "second", "meshes", "ratio", "efficiency", "geometry", "losses"}
_CLUTCH_KEYS = {"name", "first", "second", "engaged", "drag", "capacity"}  # capacity: io.dynamics_format
_BRAKE_KEYS = {"name", "shaft", "engaged", "drag", "capacity"}
_UNIT_KEYS = {"speed", "torque", "power"}
_OP_KEYS = {"speeds", "torques", "powers", "drives", "loads", "gear"}
_TRANSMISSION_KEYS = {"input", "output", "schedule", "input_speed_range", "max_input_torque"}


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
    rating : RatingSpec or None
        The ``[rating]`` table (ISO 6336 inputs, :mod:`epicyclic.io.rating_format`), None without one.
    bearings : mapping element → mapping position → BearingRating
        The sets' ``bearings`` tables (ISO 281 rating inputs; ``docs/file-format.md``).
    duty_cycle : DutyCycle or None
        The ``[duty_cycle]`` table.
    exchange : RexsDocument or None
        For a REXS file: its load cases, what was ignored, each element's component (:mod:`epicyclic.exchange`).
    spin, elastic : SpinLosses, ElasticInputs or None
        The spin losses (oil, drag, pump, churning, windage, seals, housing); the ``[elastic]`` table.
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
    rating: Any = None
    bearings: Mapping[str, Any] = field(default_factory=dict)
    duty_cycle: Any = None
    exchange: Any = None
    spin: Any = None
    elastic: Any = None

    @property
    def operating_train(self) -> GearTrain:
        """The train the operating point applies to (in ``gear`` if one is named)."""
        if self.gear is not None and self.transmission is not None:
            return self.transmission.train_in_gear(self.train, self.gear)
        return self.train

    @property
    def load_cases(self) -> tuple:
        """The operating points of a REXS file's load spectrum (:class:`~epicyclic.exchange.RexsLoadCase`),
        the first of which is :attr:`operating_point`; ``()`` for a TOML file."""
        return tuple(self.exchange.load_cases) if self.exchange is not None else ()

    def solve(self, *, lossless: bool = False):
        """Solve the operating train at the file's operating point.

        Raises
        ------
        InputFileError
            The file has no ``[operating_point]``.
        """
        from ..solver import solve

        if self.operating_point is None:
            fix = ("add speeds, torques or powers, drives and loads." if self.exchange is None else
                   "no shaft has defines_speed = true with a rotational_speed and no external_load defines a "
                   "torque or power (in the components or a load_case).")
            raise InputFileError(
                f"{self.source}: [operating_point]: the file has no [operating_point] table, so there is nothing "
                f"to solve; {fix}", self.source, "[operating_point]",
            )
        try:
            if (self.losses or self.spin is not None) and not lossless:  # loss models (docs/losses.md)
                from ..losses import solve_with_losses

                return solve_with_losses(self.operating_train, self.operating_point, self.losses, spin=self.spin,
                                         gear=self.gear, input=getattr(self.transmission, "input", None))
            return solve(self.operating_train, self.operating_point, lossless=lossless)
        except EpicyclicError as exc:
            located_error = locate_error(exc, self.source, self.operating_point, "[operating_point]")
            if self.exchange is not None:  # name the REXS components behind the shafts the message names
                origins = [f"{name!r} is {origin}" for key, origin in self.exchange.origins.items()
                           for name in [key.partition(".")[2]] if key.startswith("shaft.") and repr(name) in
                           str(located_error)]
                if origins:
                    located_error.args = (f"{located_error} (REXS: {'; '.join(origins[:4])})",)
            raise located_error from None


# ---------------------------------------------------------------------- public functions
def load_train_file(path: str | Path, *, max_bytes: int | None = None, overrides: Sequence[str] = ()) -> TrainFile:
    """Read a train description from a TOML file.

    Parameters
    ----------
    path : str or Path
        A regular file of at most ``max_bytes`` bytes of UTF-8 TOML.
    max_bytes : int, optional
        Size limit; default :func:`epicyclic.limits.max_file_bytes` (1 MiB).
    overrides : sequence of str
        ``KEY=VALUE`` overrides applied to the parsed file before it is read
        (the CLI's ``--set``; see :mod:`epicyclic.io.overrides`).

    Returns
    -------
    TrainFile

    Raises
    ------
    InputFileError
        The file cannot be read (missing, a folder, a FIFO or device, too
        large, not UTF-8), is not valid TOML, is nested too deeply, or its
        content is invalid.
    EpicyclicError
        Model errors (tooth counts, efficiencies, shafts), prefixed with the
        file and the element.
    """
    from ..limits import max_rexs_bytes

    limit = max_file_bytes() if max_bytes is None else max_bytes
    data = read_bytes(path, limit, rexs_bytes=max(max_rexs_bytes(), limit))
    if sniff(data) is not None:  # REXS, by content: zip signature, '<' or '{' first
        from ..exchange.reading import loads_rexs_document

        return read_document(loads_rexs_document(data, str(path)), overrides)
    return loads_train_file(decode_source(data, str(path), limit), source=str(path), overrides=overrides)


def read_document(document, overrides: Sequence[str] = ()) -> TrainFile:
    """The train file of a mapped REXS document (:class:`~epicyclic.exchange.RexsDocument`).

    Parameters
    ----------
    document : RexsDocument
        Its ``data`` is read as a parsed TOML train file is, within the same limits.
    overrides : sequence of str, default ()
        ``KEY=VALUE`` overrides applied to the document before it is read.

    Returns
    -------
    TrainFile
        With :attr:`TrainFile.exchange` set to ``document``.
    """
    from dataclasses import replace

    data = document.data
    check_document(data, document.source)
    if overrides:
        try:
            data = apply_overrides(data, overrides)
        except OverrideError as exc:
            raise OverrideError(f"{document.source}: {exc}") from None
    return replace(_Reader(document.source).read(data), exchange=document)


def loads_train_file(text: str, source: str = "<string>", overrides: Sequence[str] = ()) -> TrainFile:
    """Read a train description from TOML text (``overrides`` as in :func:`load_train_file`).

    Parameters
    ----------
    text : str
        The file's TOML text (the layout is in ``docs/file-format.md``).
    source : str, default "<string>"
        What the text came from, the start of every error message.
    overrides : sequence of str, default ()
        ``KEY=VALUE`` overrides applied to the parsed text before it is read
        (:func:`~epicyclic.io.overrides.apply_overrides`).

    Returns
    -------
    TrainFile

    Raises
    ------
    InputFileError
        Text too long, not valid TOML, nested too deeply, or invalid content.
    OverrideError
        A malformed override or one for a key the text cannot have.
    EpicyclicError
        Model errors (tooth counts, efficiencies, shafts, units), prefixed with the
        source and the key.

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
    data = parse_toml(text, source)
    if overrides:
        try:
            data = apply_overrides(data, overrides)
        except OverrideError as exc:
            raise OverrideError(f"{source}: {exc}") from None
    return _Reader(source).read(data)


# ---------------------------------------------------------------------- the reader
class _Reader(TableReader):
    def __init__(self, source: str):
        super().__init__(source)
        self.units = Units()
        self.element_names: dict[str, str] = {}

    def checked(self, where: str, owner: str, build, *args, **kwargs):
        """``build(*args, **kwargs)`` with model errors located at ``where``."""
        try:
            return build(*args, **kwargs)
        except InputFileError:
            raise
        except EpicyclicError as exc:
            raise self.wrap(where, exc, owner) from None

    def shaft(self, table: Mapping[str, Any], key: str, where: str) -> str:
        """A shaft name; one spelt like the housing but not exactly is refused."""
        name = self.name(table, key, where)
        if name != HOUSING and name.casefold() == HOUSING:
            raise self.error(at_key(where, key), f"{name!r} is not the frame: the housing is spelt {HOUSING!r} "
                                                 "(lower case). Write 'housing', or another name for a shaft.")
        return name

    # ---- top level
    def read(self, data: Mapping[str, Any]) -> TrainFile:
        self.check_keys(data, _TOP_KEYS, "top level")
        title = self.string(data, "title", "top level", default="gear train")
        if len(title) > MAX_TITLE_CHARS:
            raise self.error("top level, key 'title'", f"the title is {len(title):,} characters long; at most "
                                                       f"{MAX_TITLE_CHARS} are accepted (see docs/limits.md).")
        description = data.get("description", "")
        if not isinstance(description, str):
            raise self.error("top level, key 'description'", f"expected a string, got {kind_of(description)}.")
        title, description = terminal_text(title), terminal_text(description)  # no escapes in reports or figures
        if "units" in data:
            self.units = self.read_units(self.table(data["units"], "[units]"))
        tables = {kind: self.array_of_tables(data, kind) for kind in ("planetary", "gear", "clutch", "brake")}
        count = sum(len(t) for t in tables.values())
        self.checked("top level", "", check_count, count, "top level", MAX_ELEMENTS, "elements")
        if not count:
            raise self.error("top level", "the file describes no element; add at least one [[planetary]], "
                                          "[[gear]], [[clutch]] or [[brake]] table.")
        read = {"planetary": self.read_planetary, "gear": self.read_gear,
                "clutch": self.read_shift, "brake": self.read_shift}
        # geometry and loss tables are optional: their reader (and the geometry and loss packages) is
        # imported only for a file that has them, so that a plain file starts fast
        extras = spin = None
        if any(k in data for k in (*_SPIN_TABLES, "lubricant")) or any(
                k in t for g in tables.values() for t in g if isinstance(t, dict) for k in ("geometry", "losses", "drag")):
            from . import geometry_format as extras, spin_format as spin  # only for a file that has them
        lubricant = oil = temperature = None
        if extras:
            self.refuse_defaults, self.spin_defaults = spin.refuses_defaults(self, data), []
            lubricant, oil, temperature = spin.read_lubricant(self, data)
        elements, geometry, losses = [], {}, {}
        for kind, group in tables.items():
            for k, table in enumerate(group):
                element = read[kind](table, k, kind)
                shape = model = None
                if extras:
                    element, shape, model = extras.read_extras(
                        self, kind, table, element, self.element_where(kind, k, table), lubricant)
                elements.append(element)
                if shape is not None:
                    geometry[element.name] = shape
                if model is not None:
                    losses[element.name] = model
        shafts = self.names(data.get("shafts", []), "shafts", "top level")
        train = self.checked("top level", "gear train", GearTrain, elements, shafts, title)
        self.checked("top level, key 'shafts'", "", check_count, len(train.shafts), "top level", MAX_SHAFTS,
                     "shafts")
        transmission = None
        if "transmission" in data:
            transmission = self.read_transmission(self.table(data["transmission"], "[transmission]"), train)
        op, gear = None, None
        if "operating_point" in data:
            op, gear = self.read_operating_point(
                self.table(data["operating_point"], "[operating_point]"), train, transmission)
        rating, bearings, duty = None, {}, None
        if "rating" in data or "duty_cycle" in data or any("bearings" in t for t in tables["planetary"]
                                                           if isinstance(t, dict)):
            from .duty_format import read_design_tables  # the rating package only for a file that has them

            rating, bearings, duty = read_design_tables(self, data, tables["planetary"], geometry, train,
                                                        transmission, op)
        spin = spin.read_spin(self, data, oil, temperature, train, transmission and transmission.input) if (
            spin is not None and (spin.has_spin(data) or oil is not None)) else None  # spin losses, docs/losses.md
        elastic = read_elastic(self, data["elastic"]) if "elastic" in data else None  # docs/elastic.md
        return TrainFile(self.source, title, train, op, self.units, transmission, description, gear,
                         MappingProxyType(geometry), MappingProxyType(losses), rating,
                         bearings=MappingProxyType(bearings), duty_cycle=duty, spin=spin, elastic=elastic)

    def read_units(self, table: Mapping[str, Any]) -> Units:
        self.check_keys(table, _UNIT_KEYS, "[units]")
        chosen = {k: self.string(table, k, "[units]") for k in table}
        for key, unit in chosen.items():
            self.checked(at_key("[units]", key), f"units.{key}", Units, **{key: unit})
        return Units(**chosen)

    # ---- elements
    @staticmethod
    def element_where(kind: str, k: int, table: Mapping[str, Any]) -> str:
        """Where the k-th ``[[kind]]`` table is, for messages: ``[[kind]] #k 'name'``."""
        name = table.get("name")
        return f"[[{kind}]] #{k + 1}" + (f" {short(name, 40)}" if isinstance(name, str) else "")

    def element(self, kind: str, k: int, table: Mapping[str, Any], keys: set[str]) -> tuple[str, str]:
        """(where, name) of the k-th ``[[kind]]`` table, its keys and its name checked."""
        where = self.element_where(kind, k, table)
        self.check_keys(table, keys, where)
        name = self.name(table, "name", where)
        if name in self.element_names:
            raise self.error(at_key(where, "name"), f"{name!r} is used twice: it is already the name of {self.element_names[name]}; "
                                                    "element names must be unique.")
        self.element_names[name] = where
        return where, name

    def read_planetary(self, table: Mapping[str, Any], k: int, kind: str = "planetary") -> PlanetarySet:
        where, name = self.element(kind, k, table, _PLANETARY_KEYS)
        owner = f"planetary set {name!r}"
        shafts = {role: self.shaft(table, role, where) for role in ("sun", "ring", "carrier")}
        planets = self.checked(at_key(where, "planets"), owner, check_planets,
                               self.integer(table.get("planets", 3), "planets", where), "planets", owner)
        eta = table.get("stationary_efficiency")
        meshes = table.get("mesh_efficiencies")
        if eta is not None and meshes is not None:
            raise self.error(where, "give 'stationary_efficiency' or 'mesh_efficiencies', not both.")
        eta = None if eta is None else self.efficiency(eta, "stationary_efficiency", where)
        if meshes is not None:
            if not isinstance(meshes, list) or not 1 <= len(meshes) <= 3:
                raise self.error(at_key(where, "mesh_efficiencies"), f"expected a list of 2 or 3 efficiencies "
                                                                     f"such as [0.98, 0.98], got {short(meshes)}.")
            meshes = tuple(self.efficiency(v, f"mesh_efficiencies[{j}]", where) for j, v in enumerate(meshes))
        has_teeth, has_ratio = "teeth" in table, "stationary_ratio" in table
        if has_teeth == has_ratio:
            raise self.error(where, "give either 'teeth' (tooth counts) or 'stationary_ratio' (i0), "
                                    + ("not both." if has_teeth else "got neither."))
        if has_ratio:
            key = at_key(where, "stationary_ratio")
            ratio = self.ratio(table["stationary_ratio"], "stationary_ratio", where)
            if meshes is not None:
                eta = math.prod(meshes)
            return self.checked(key, owner, PlanetarySet, name, stationary_ratio=ratio,
                                stationary_efficiency=1.0 if eta is None else eta, planets=planets, **shafts)
        teeth = self.table(table["teeth"], at_key(where, "teeth"))
        ratio = 1.0
        if "geometry" in table:  # a stepped set's module ratio m2/m1 from its geometry table
            from .geometry_format import module_ratio

            ratio = module_ratio(self, table, where)
        return self.planetary_from_teeth(teeth, name, shafts, eta, meshes, planets, where, ratio)

    def planetary_from_teeth(self, teeth, name, shafts, eta, meshes, planets, where, ratio=None) -> PlanetarySet:
        kind = teeth.get("kind", "simple")
        if kind not in _TEETH_KEYS:
            raise self.error(at_key(where, "teeth.kind"), f"expected 'simple', 'double' or 'stepped' (or "
                                                          f"'two_rings' for a Wolfrom set, 'two_suns'), got "
                                                          f"{short(kind)}.")
        in_teeth = at_key(where, "teeth") + f" (kind {kind!r})"
        self.check_keys(teeth, _TEETH_KEYS[kind], in_teeth)
        z = {key: self.integer(self.require(teeth, key, in_teeth), f"teeth.{key}", where)
             for key in sorted(_TEETH_KEYS[kind] - {"kind", "ring_internal", "module_ratio"})}
        if "module_ratio" in teeth:
            ratio = self.number(teeth["module_ratio"], "teeth.module_ratio", where)
        owner = f"planetary set {name!r}"
        common = dict(stationary_efficiency=eta, mesh_efficiencies=meshes, planets=planets, **shafts)
        key = at_key(where, "teeth")
        if kind == "simple":
            return self.checked(key, owner, PlanetarySet.simple, name, z_sun=z["sun"], z_planet=z["planet"],
                                z_ring=z["ring"], **common)
        if kind == "double":
            return self.checked(key, owner, PlanetarySet.double_planet, name, z_sun=z["sun"],
                                z_planet_sun=z["planet_sun"], z_planet_ring=z["planet_ring"], z_ring=z["ring"],
                                **common)
        if kind in ("two_rings", "two_suns"):
            build = PlanetarySet.two_rings if kind == "two_rings" else PlanetarySet.two_suns
            return self.checked(key, owner, build, name, first=common.pop("sun"), second=common.pop("ring"),
                                z_first=z["first"], z_planet_first=z["planet_first"],
                                z_planet_second=z["planet_second"], z_second=z["second"], module_ratio=ratio,
                                **common)
        internal = self.boolean(teeth, "ring_internal", at_key(where, "teeth"), True)
        return self.checked(key, owner, PlanetarySet.stepped, name, z_sun=z["sun"], z_planet_sun=z["planet_sun"],
                            z_planet_ring=z["planet_ring"], z_ring=z["ring"], ring_internal=internal,
                            module_ratio=ratio, **common)

    def read_gear(self, table: Mapping[str, Any], k: int, kind: str = "gear") -> GearStage:
        where, name = self.element(kind, k, table, _GEAR_KEYS)
        owner = f"gear stage {name!r}"
        first, second = self.shaft(table, "first", where), self.shaft(table, "second", where)
        eta = self.efficiency(table.get("efficiency", 1.0), "efficiency", where)
        has_meshes, has_ratio = "meshes" in table, "ratio" in table
        if has_meshes == has_ratio:
            raise self.error(where, "give either 'meshes' (tooth counts) or 'ratio' (n_first/n_second), "
                                    + ("not both." if has_meshes else "got neither."))
        if has_ratio:
            ratio = self.ratio(table["ratio"], "ratio", where)
            return self.checked(at_key(where, "ratio"), owner, GearStage, name, first, second, ratio, eta)
        meshes = table["meshes"]
        key = at_key(where, "meshes")
        if not isinstance(meshes, list) or not meshes:
            raise self.error(key, f"expected a list such as [[40, 44, \"external\"]], got {short(meshes)}.")
        self.checked(key, "", check_count, len(meshes), key, MAX_MESHES, "meshes")
        checked = []
        for j, mesh in enumerate(meshes):
            if not isinstance(mesh, list) or len(mesh) not in (2, 3):
                raise self.error(at_key(where, f"meshes[{j}]"), f"expected [z_driving, z_driven] or [z_driving, "
                                                                f"z_driven, \"external\"|\"internal\"], got {short(mesh)}.")
            checked.append(tuple(mesh))
        return self.checked(key, owner, GearStage.from_teeth, name, first, second, checked, eta)

    def read_shift(self, table: Mapping[str, Any], k: int, kind: str):
        where, name = self.element(kind, k, table, _CLUTCH_KEYS if kind == "clutch" else _BRAKE_KEYS)
        engaged = self.boolean(table, "engaged", where, True)
        if kind == "clutch":
            first, second = self.shaft(table, "first", where), self.shaft(table, "second", where)
            return self.checked(where, f"clutch {name!r}", Clutch, name, first, second, engaged)
        return self.checked(at_key(where, "shaft"), f"brake {name!r}", Brake, name,
                            self.shaft(table, "shaft", where), engaged)

    # ---- operating point and transmission
    def read_operating_point(self, table, train: GearTrain, transmission: Transmission | None):
        where = "[operating_point]"
        self.check_keys(table, _OP_KEYS, where)
        values: dict[str, dict[str, float]] = {}
        for group, quantity in (("speeds", "speed"), ("torques", "torque"), ("powers", "power")):
            given = self.table(table.get(group, {}), at_key(where, group))
            values[group] = {}
            for shaft, value in given.items():
                key = at_key(where, f"{group}.{shaft}")
                self.known_shaft(train, shaft, key)
                if shaft == HOUSING and (group != "speeds" or value not in (0, 0.0, "0")):
                    raise self.error(key, "the housing is the frame: its speed is 0 and its torque is the reaction "
                                          "the solver computes; remove this entry.")
                values[group][shaft] = self.checked(key, f"{group}.{shaft}", to_core, value, quantity,
                                                    field=f"{group}.{shaft}", default_unit=self.units.of(quantity))
        roles = {}
        for group in ("drives", "loads"):
            roles[group] = self.names(table.get(group, []), group, where)
            for shaft in roles[group]:
                self.known_shaft(train, shaft, at_key(where, group))
                if shaft == HOUSING:
                    raise self.error(at_key(where, group), "the housing cannot drive or be loaded; it only takes "
                                                           "reactions. Name a moving shaft.")
        gear = None
        if "gear" in table:
            gear = table["gear"]
            if transmission is None:
                raise self.error(at_key(where, "gear"), "needs a [transmission] table with a schedule.")
            if not isinstance(gear, str) or gear not in transmission.schedule:
                raise self.error(at_key(where, "gear"), f"expected one of the schedule's gears "
                                                        f"{', '.join(repr(g) for g in transmission.schedule)}, "
                                                        f"got {short(gear)}.")
        try:
            op = OperatingPoint(values["speeds"], values["torques"], values["powers"], **roles)
        except EpicyclicError as exc:
            raise self.wrap(operating_point_where(exc), exc, "operating point") from None
        return op, gear

    def known_shaft(self, train: GearTrain, name: str, where: str) -> None:
        self.checked(where, "", train.check_shaft, name, "")

    def read_transmission(self, table, train: GearTrain) -> Transmission:
        where = "[transmission]"
        self.check_keys(table, _TRANSMISSION_KEYS, where)
        ends = {}
        for key in ("input", "output"):
            ends[key] = self.name(table, key, where)
            self.known_shaft(train, ends[key], at_key(where, key))
            if ends[key] == HOUSING:
                raise self.error(at_key(where, key), "the housing stands still; name a moving shaft.")
        if ends["input"] == ends["output"]:
            raise self.error(at_key(where, "output"), f"input and output must be different shafts, got "
                                                      f"{ends['input']!r} twice.")
        schedule_table = self.table(self.require(table, "schedule", where), at_key(where, "schedule"))
        self.checked(at_key(where, "schedule"), "", check_count, len(schedule_table), "schedule", MAX_GEARS,
                     "gears")
        shift_names = {e.name for e in train.shift_elements}
        schedule: dict[str, tuple[str, ...]] = {}
        for gear, names in schedule_table.items():
            key = at_key(where, f"schedule.{gear}")
            self.check_name(gear, key)
            names = self.names(names, f"schedule.{gear}", where)
            for n in names:
                if n not in shift_names:
                    raise self.error(key, f"{n!r} is not a clutch or brake of the train; shift elements are "
                                          f"{', '.join(sorted(shift_names)) or 'none'}.")
            schedule[gear] = names
        if not schedule:
            raise self.error(at_key(where, "schedule"), "expected at least one gear, got none.")
        return Transmission(ends["input"], ends["output"], schedule, *rated_limits(self, table, where))

