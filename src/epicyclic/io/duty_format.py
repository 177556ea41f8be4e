"""The ``[duty_cycle]`` table and the sets' ``bearings`` tables of a train file.

Bearing ratings, per ``[[planetary]]`` set and position (``planet``; the
central members ``sun``, ``ring``, ``carrier``)::

    [planetary.bearings.planet]
    type = "cylindrical roller"        # default: the set's losses.bearing type
    dynamic_load_rating = "120 kN"     # C (required); a number is N
    fatigue_load_limit = "14 kN"       # C_u  } the modified life L_nm = a1 a_ISO L10:
    pitch_diameter = 45.0              # d_m, mm  } give all four,
    viscosity = "15 mm^2/s"            # nu at operating temperature } or none
    contamination = 0.5                # e_C (ISO 281 clause 9)      }
    reliability = 90                   # %, ISO 281 Table 12 (default 90)
    radial_factor = 1.0                # X of P = X F_r + Y F_a (default 1)
    axial_factor = 0.0                 # Y (default 0)
    exponent = 3.333                   # p (default by type: 3 ball, 10/3 roller)
    external_load = "0 N"              # added radial load (central bearings)

A duty cycle of load cases, each an operating point for a time::

    [duty_cycle]
    name = "city and highway"
    hours = 8000                       # total, for cases given by share
    drives = ["in"]                    # default: [operating_point] drives, else [transmission] input
    loads = ["out"]                    # default: [operating_point] loads, else [transmission] output

    [[duty_cycle.case]]
    name = "launch"
    gear = "1"                         # a gear of the [transmission] schedule
    share = 0.1                        # or hours = 800
    speeds = { in = "1500 rpm" }       # default: [operating_point] speeds
    torques = { in = "250 N*m" }       # powers = {...} as in [operating_point]; without both:
                                       # [operating_point] torques and powers

Every problem names the file, the table, the key, what was expected and what
was given (``docs/file-format.md``).

References
----------
ISO 281:2007 (bearing inputs C, C_u, d_m, e_C, a_1); ISO 6336-6:2019, clause 4 (load spectrum).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..errors import EpicyclicError
from ..limits import MAX_LOAD_CASES, check_count
from ..model import HOUSING, OperatingPoint
from ..rating.bearing_life import BEARING_KINDS, BearingRating
from ..rating.duty_cycle import DutyCycle, LoadCase
from ..text import short
from ..transmission.errors import UnknownGearError
from ..units import to_core
from .reader import at_key

__all__ = [
    "read_design_tables",
    "BEARING_KEYS",
    "BEARING_POSITIONS",
    "CASE_KEYS",
    "DUTY_KEYS",
    "analyse_file_duty_cycle",
    "read_bearings",
    "read_duty_cycle",
]

BEARING_POSITIONS = ("planet", "sun", "ring", "carrier")
BEARING_KEYS = {"type", "dynamic_load_rating", "fatigue_load_limit", "pitch_diameter", "viscosity",
                "contamination", "reliability", "radial_factor", "axial_factor", "exponent", "external_load"}
DUTY_KEYS = {"name", "hours", "drives", "loads", "case"}
CASE_KEYS = {"name", "gear", "hours", "share", "speeds", "torques", "powers", "drives", "loads"}

#: Key → (unit of a plain number, pint unit it converts to, what it is).
_DIMENSIONAL = {
    "dynamic_load_rating": ("N", "N", "the basic dynamic load rating C, e.g. \"120 kN\""),
    "fatigue_load_limit": ("N", "N", "the fatigue load limit C_u, e.g. \"14 kN\""),
    "external_load": ("N", "N", "a radial load, e.g. \"500 N\""),
    "pitch_diameter": ("mm", "mm", "the pitch diameter d_m = (d + D)/2, e.g. 45.0 (mm)"),
    "viscosity": ("mm^2/s", "mm**2/s", "the kinematic viscosity at operating temperature, e.g. \"15 mm^2/s\""),
}


def _dimensional(reader, value: object, key: str, where: str) -> float:
    unit, target, what = _DIMENSIONAL[key]
    if isinstance(value, str) and any(c.isalpha() for c in value):
        from pint.errors import PintError

        from ..units import (  # the project's unit grammar (never pint's own parser)
            UnitError,
            _parse,
        )

        try:
            number = float(_parse(value, key, "power").to(target).magnitude)
        except (UnitError, PintError):  # a unit the grammar refuses, or of another dimension
            raise reader.error(at_key(where, key), f"expected {what} (a plain number is {unit}), "
                                                   f"got {short(value)}.") from None
    else:
        number = reader.number(value, key, where)
    return number


def read_bearings(reader, value: object, where: str, losses_table: object) -> dict[str, BearingRating]:
    """Position → :class:`~epicyclic.rating.BearingRating` of one set's ``bearings`` table.

    Parameters
    ----------
    reader : TableReader
        The file reader (for located errors).
    value : object
        The ``bearings`` table.
    where : str
        The element, for messages.
    losses_table : object
        The set's ``losses`` table (its ``bearing.type`` is the default type).

    Returns
    -------
    dict
    """
    b_where = at_key(where, "bearings")
    table = reader.table(value, b_where)
    reader.check_keys(table, set(BEARING_POSITIONS), b_where)
    default_type = None
    if isinstance(losses_table, dict) and isinstance(losses_table.get("bearing"), dict):
        default_type = losses_table["bearing"].get("type")
    out = {}
    for position, entry in table.items():
        p_where = f"{where}, table 'bearings.{position}'"
        entry = reader.table(entry, p_where)
        reader.check_keys(entry, BEARING_KEYS, p_where)
        kind = entry.get("type", default_type if position == "planet" else None)
        if kind is None:
            raise reader.error(p_where, "missing key 'type': the bearing type sets the life exponent p; give one of "
                                        + ", ".join(f'"{k}"' for k in BEARING_KINDS) + ".")
        if not isinstance(kind, str) or kind not in BEARING_KINDS:
            raise reader.error(at_key(p_where, "type"), "expected one of "
                               + ", ".join(f'"{k}"' for k in BEARING_KINDS) + f", got {short(kind)}.")
        if "dynamic_load_rating" not in entry:
            raise reader.error(p_where, "missing key 'dynamic_load_rating': the basic dynamic load rating C of the "
                                        "bearing (from its catalogue), e.g. dynamic_load_rating = \"120 kN\".")
        values: dict[str, Any] = {}
        for key, raw in entry.items():
            if key == "type":
                continue
            values[key] = _dimensional(reader, raw, key, p_where) if key in _DIMENSIONAL else \
                reader.number(raw, key, p_where)
        try:
            out[position] = BearingRating(kind, **values)
        except EpicyclicError as exc:
            raise reader.wrap(p_where, exc, "bearing") from None
    return out


def _default_roles(data: Mapping[str, Any], op: OperatingPoint | None, transmission) -> tuple[tuple, tuple]:
    if op is not None:
        return tuple(op.drives), tuple(op.loads)
    if transmission is not None:
        return (transmission.input,), (transmission.output,)
    return (), ()


def _inherited(values: dict[str, dict[str, float]], table, operating_point) -> dict[str, dict[str, float]]:
    """A case's speeds and loads, the file's ``[operating_point]`` where the case gives none: its speeds
    without ``speeds``, its torques and powers without ``torques`` and ``powers``."""
    if operating_point is None:
        return values
    out = dict(values)
    if "speeds" not in table:
        out["speeds"] = dict(operating_point.speeds)
    if "torques" not in table and "powers" not in table:
        out["torques"], out["powers"] = dict(operating_point.torques), dict(operating_point.powers)
    return out


def _case(reader, table, k: int, train, transmission, units, roles, total_given: bool,
          operating_point=None) -> LoadCase:
    name = table.get("name", f"case {k + 1}")
    where = f"[[duty_cycle.case]] #{k + 1}" + (f" {short(name, 40)}" if isinstance(name, str) else "")
    reader.check_keys(table, CASE_KEYS, where)
    name = reader.name(table, "name", where) if "name" in table else f"case {k + 1}"
    values: dict[str, dict[str, float]] = {}
    for group, quantity in (("speeds", "speed"), ("torques", "torque"), ("powers", "power")):
        given = reader.table(table.get(group, {}), at_key(where, group))
        values[group] = {}
        for shaft, value in given.items():
            key = at_key(where, f"{group}.{shaft}")
            reader.checked(key, "", train.check_shaft, shaft, "")
            if shaft == HOUSING:
                raise reader.error(key, "the housing is the frame; remove this entry.")
            values[group][shaft] = reader.checked(key, f"{group}.{shaft}", to_core, value, quantity,
                                                  field=f"{group}.{shaft}", default_unit=units.of(quantity))
    values = _inherited(values, table, operating_point)
    drives = reader.names(table["drives"], "drives", where) if "drives" in table else roles[0]
    loads = reader.names(table["loads"], "loads", where) if "loads" in table else roles[1]
    for shaft in (*drives, *loads):
        reader.checked(at_key(where, "drives" if shaft in drives else "loads"), "", train.check_shaft, shaft, "")
    gear = None
    if "gear" in table:
        gear = table["gear"]
        if transmission is None:
            raise reader.error(at_key(where, "gear"), "needs a [transmission] table with a schedule.")
        if not isinstance(gear, str) or gear not in transmission.schedule:
            raise reader.wrap(at_key(where, "gear"), UnknownGearError(gear, transmission.schedule))
    if "hours" in table and "share" in table:
        raise reader.error(where, "give 'hours' or 'share', not both.")
    if "hours" not in table and "share" not in table:
        raise reader.error(where, "missing key 'hours' or 'share': how long the case runs (h) or its time share "
                                  "of the cycle.")
    duration_key = "hours" if "hours" in table else "share"
    duration = reader.number(table[duration_key], duration_key, where, "h" if duration_key == "hours" else "1")
    if duration < 0:
        raise reader.error(at_key(where, duration_key), f"expected a duration >= 0, got {short(duration)}.")
    if duration_key == "hours" and total_given:
        raise reader.error(at_key(where, "hours"), "[duty_cycle] gives the total 'hours' already: give each case "
                                                   "a 'share' of it, or remove the total.")
    try:
        op = OperatingPoint(values["speeds"], values["torques"], values["powers"], drives=drives, loads=loads)
        return LoadCase(name, op, gear, **{duration_key: duration})
    except EpicyclicError as exc:
        raise reader.wrap(where, exc, "operating point") from None


def read_duty_cycle(reader, value: object, train, transmission, operating_point, units) -> DutyCycle:
    """The :class:`~epicyclic.rating.DutyCycle` of the ``[duty_cycle]`` table.

    Parameters
    ----------
    reader : TableReader
        The file reader (for located errors).
    value : object
        The ``duty_cycle`` table.
    train : GearTrain
        The file's train (shaft names).
    transmission : Transmission or None
        The file's schedule (gear names; default drives and loads).
    operating_point : OperatingPoint or None
        The file's operating point (default drives and loads).
    units : Units
        Units of plain numbers.

    Returns
    -------
    DutyCycle
    """
    where = "[duty_cycle]"
    table = reader.table(value, where)
    reader.check_keys(table, DUTY_KEYS, where)
    name = reader.string(table, "name", where, default="duty cycle")
    total = None
    if "hours" in table:
        total = reader.number(table["hours"], "hours", where, "h")
        if not total > 0:
            raise reader.error(at_key(where, "hours"), f"expected the cycle's total hours > 0, got {short(total)}.")
    roles = _default_roles(table, operating_point, transmission)
    roles = (reader.names(table["drives"], "drives", where) if "drives" in table else roles[0],
             reader.names(table["loads"], "loads", where) if "loads" in table else roles[1])
    cases_raw = table.get("case")
    if not isinstance(cases_raw, list) or not cases_raw or not all(isinstance(c, dict) for c in cases_raw):
        raise reader.error(where, "expected at least one [[duty_cycle.case]] table (name, gear, hours or share, "
                                  f"speeds, torques), got {short(cases_raw)}.")
    reader.checked(where, "", check_count, len(cases_raw), "duty_cycle.case", MAX_LOAD_CASES, "load cases")
    cases = [_case(reader, c, k, train, transmission, units, roles, total is not None, operating_point)
             for k, c in enumerate(cases_raw)]
    try:
        return DutyCycle(tuple(cases), total, name)
    except EpicyclicError as exc:
        raise reader.wrap(where, exc, "duty cycle") from None


def analyse_file_duty_cycle(train_file):
    """The :class:`~epicyclic.rating.DutyCycleResult` of a train file's ``[duty_cycle]``.

    Parameters
    ----------
    train_file : TrainFile
        Read by :func:`~epicyclic.io.load_train_file`; its train, schedule, loss models,
        geometry and bearing ratings are used.

    Returns
    -------
    DutyCycleResult

    Raises
    ------
    InputFileError
        The file has no ``[duty_cycle]`` table.
    """
    from ..rating.duty_analysis import analyse_duty_cycle
    from .located import locate_error, located
    from .source import InputFileError

    if train_file.duty_cycle is None:
        raise InputFileError(
            f"{train_file.source}: [duty_cycle]: the file has no [duty_cycle] table; add one with "
            "[[duty_cycle.case]] tables (name, gear, hours or share, speeds, torques; see docs/file-format.md).",
            train_file.source, "[duty_cycle]")
    try:
        return analyse_duty_cycle(train_file.train, train_file.duty_cycle, schedule=train_file.transmission,
                                  losses=train_file.losses, geometry=train_file.geometry,
                                  bearings=train_file.bearings, rating=getattr(train_file, "rating", None),
                                  spin=getattr(train_file, "spin", None), title=train_file.title)
    except EpicyclicError as exc:
        k = getattr(exc, "duty_case", None)
        if k is not None:  # a case the solver refuses: located at its own table
            name = train_file.duty_cycle.cases[k].name
            raise located(exc, train_file.source, f"[[duty_cycle.case]] #{k + 1} {short(name, 40)}",
                          f"duty cycle, case {name!r}") from None
        raise locate_error(exc, train_file.source, None, "[duty_cycle]") from None


def read_design_tables(reader, data: Mapping[str, Any], planetary: list, geometry: Mapping[str, Any], train,
                       transmission, operating_point) -> tuple[Any, dict, DutyCycle | None]:
    """The design-check tables of a file: ``[rating]``, the sets' ``bearings`` and ``[duty_cycle]``.

    Parameters
    ----------
    reader : TableReader
        The file's reader (errors name the file and key).
    data : mapping
        The whole document.
    planetary : list of mapping
        The ``[[planetary]]`` tables.
    geometry : mapping element → geometry
        The sets' geometry (the bearing loads come from the tooth forces).
    train, transmission, operating_point
        As read from the file.

    Returns
    -------
    tuple
        (RatingSpec or None, element → read-only mapping position → BearingRating, DutyCycle or None).
    """
    from types import MappingProxyType

    rating = None
    if "rating" in data:
        from .rating_format import read_rating

        lubricant_table = data.get("lubricant") if isinstance(data.get("lubricant"), dict) else None
        rating = read_rating(reader, data["rating"], lubricant_table)
    bearings: dict[str, Any] = {}
    for k, table in enumerate(planetary):
        if isinstance(table, dict) and "bearings" in table:
            where = reader.element_where("planetary", k, table)
            if table["name"] not in geometry:
                raise reader.error(at_key(where, "bearings"), "the bearing loads come from the tooth forces: "
                                                              "add a 'geometry' table (module, ...).")
            bearings[table["name"]] = MappingProxyType(read_bearings(reader, table["bearings"], where,
                                                                     table.get("losses")))
    duty = None
    if "duty_cycle" in data:
        duty = read_duty_cycle(reader, data["duty_cycle"], train, transmission, operating_point, reader.units)
    return rating, bearings, duty
