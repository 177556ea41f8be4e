"""The spin-loss tables of a train file: the oil, clutch drag, pump, churning, windage, seals, housing.

::

    [lubricant]                          # top level
    viscosity_40 = 29.5                  # mm²/s at 40 °C  } ASTM D341: ν at any temperature
    viscosity_100 = 6.0                  # mm²/s at 100 °C }  or viscosity_table = [[0.0, 250.0], [40.0, 29.5], ...]
    density = 850.0                      # kg/m³ at 15 °C (default 860)
    temperature = 80.0                   # °C, or "thermal" (needs [housing])
    lubricant_factor = 1.0               # X_L of Schlenk's friction (default 1)

    [[clutch]]                           # or [[brake]]
    name = "D"
    ...
    [clutch.drag]                        # drag of the open element (Yuan et al. 2007)
    gaps = 10                            # oil films (friction surfaces)
    inner_radius = 70.0                  # mm
    outer_radius = 90.0                  # mm
    clearance = 0.15                     # mm per gap
    supply = 3.0                         # l/min fed to the pack (omit: gaps full, no aeration)
    groove_factor = 1.0                  # share of the plate that shears oil (default 1)
    mist = true                          # past the peak the oil mist shears too (Iqbal et al. 2013; default)

    [pump]                               # the oil pump
    displacement = 18.0                  # cm³/rev
    pressure = 8.0                       # bar, or { "1" = 14.0, "2" = 10.0, default = 8.0 }
    efficiency = 0.85                    # η_hm (default 0.85)
    shaft = "in"                         # default: the transmission's input

    [[churning]]                         # a gear dipped in the sump (Changenet & Velex 2007)
    shaft = "out"
    element = "P4"                       # reported under this element (default: housing)
    pitch_radius = 80.0                  # mm
    face_width = 20.0                    # mm
    immersion = 15.0                     # mm below the oil level
    oil_volume = 8.0                     # litres in the sump

    [[windage]]                          # a fast gear in air or mist
    shaft = "in"
    radius = 90.0                        # mm
    face_width = 25.0                    # mm
    density = 1.204                      # kg/m³ (default: air)
    kinematic_viscosity = 15.1           # mm²/s (default: air)

    [[seal]]                             # radial lip seals (Simrit, ISO/TR 14179-2)
    shaft = "out"
    diameter = 55.0                      # mm
    count = 1

    [housing]                            # for temperature = "thermal" (ISO/TR 14179-1)
    area = 0.9                           # m²
    ambient = 20.0                       # °C (default 20)
    heat_transfer = 12.0                 # W/(m² K) (default: natural convection 1.32 (Δϑ/L)^0.25)
    height = 0.3                         # m, L of the natural-convection formula (default 0.3)
    emissivity = 0.9                     # (default 0.9)
    cooler = 80.0                        # W/K of an oil cooler (default 0)
    coolant = 90.0                       # °C of the coolant (default: ambient)

Every default is stated in ``docs/file-format.md`` and in the model's
``defaults`` (shown by ``explain``), can be replaced by giving the key, and is
refused — a missing key is then an error naming it — with the top-level key
``defaults = "refuse"``; every problem names the file, the table and the key.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..errors import EpicyclicError
from ..losses import ChurningGear, ClutchDrag, Housing, Lubricant, Oil, OilPump, ShaftSeal, SpinLosses, WindageGear
from ..text import short
from .reader import at_key

__all__ = ["SPIN_TOP_KEYS", "LUBRICANT_KEYS", "DRAG_KEYS", "read_lubricant", "read_spin", "has_spin",
           "refuses_defaults"]

#: Top-level tables this module reads (besides [lubricant]).
SPIN_TOP_KEYS = {"pump", "housing", "seal", "churning", "windage"}
LUBRICANT_KEYS = {"viscosity", "lubricant_factor", "viscosity_40", "viscosity_100", "viscosity_table", "density",
                  "temperature", "expansion", "specific_heat"}
DRAG_KEYS = {"gaps", "inner_radius", "outer_radius", "clearance", "supply", "groove_factor", "mist"}
_PUMP_KEYS = {"displacement", "pressure", "efficiency", "shaft"}
_HOUSING_KEYS = {"area", "ambient", "heat_transfer", "height", "emissivity", "cooler", "coolant"}
_CHURNING_KEYS = {"shaft", "element", "pitch_radius", "face_width", "immersion", "oil_volume"}
_WINDAGE_KEYS = {"shaft", "element", "radius", "face_width", "density", "kinematic_viscosity"}
_SEAL_KEYS = {"shaft", "diameter", "count", "factor"}


def has_spin(data: Mapping[str, Any]) -> bool:
    """Whether the file has any spin-loss table: a top-level one or a clutch's or brake's ``drag``."""
    if any(k in data for k in SPIN_TOP_KEYS):
        return True
    return any(isinstance(t, dict) and "drag" in t for kind in ("clutch", "brake")
               for t in (data.get(kind) if isinstance(data.get(kind), list) else []))


def refuses_defaults(reader, data: Mapping[str, Any]) -> bool:
    """Whether the file refuses the loss models' defaults (top-level ``defaults = "refuse"``)."""
    value = data.get("defaults", "use")
    if value not in ("use", "refuse"):
        raise reader.error("top level, key 'defaults'", f"expected \"use\" (the stated defaults of the loss tables) "
                                                        f"or \"refuse\" (every key given), got {short(value)}.")
    return value == "refuse"


def _default(reader, table, key: str, where: str, default, meaning: str) -> None:
    """Record (or, with top-level ``defaults = "refuse"``, refuse) the default of a missing ``key``."""
    if key in table:
        return
    if getattr(reader, "refuse_defaults", False):
        raise reader.error(where, f"missing key {key!r}: the file refuses defaults (top level defaults = \"refuse\"); "
                                  f"give it (the default would be {meaning}).")
    stated = getattr(reader, "spin_defaults", None)
    if stated is not None:
        stated.append(f"{where} {key} = {meaning}")


def _number(reader, table, key: str, where: str, default=None, *, unit: str = "", minimum=None, maximum=None,
            positive: bool = False, meaning: str | None = None):
    if key not in table:
        if default is not None or meaning is not None:
            _default(reader, table, key, where, default, meaning or f"{default:g} {unit}".strip())
        return default
    value = reader.number(table[key], key, where)
    low_bad = (positive and not value > 0) or (minimum is not None and value < minimum)
    if low_bad or (maximum is not None and value > maximum):
        bounds = (f" >= {minimum:g}" if minimum is not None else "") + (f" <= {maximum:g}" if maximum is not None else "")
        kind = "a positive number" if positive else "a number"
        raise reader.error(at_key(where, key), f"expected {kind}{bounds} ({unit}), got {short(table[key])}.")
    return value


def read_lubricant(reader, data: Mapping[str, Any]) -> tuple[Lubricant | None, Oil | None, Any]:
    """(Lubricant for Schlenk's friction, Oil, temperature) of the top-level ``[lubricant]``.

    The temperature is a number (°C), ``"thermal"`` or None (not given).
    """
    if "lubricant" not in data:
        return None, None, None
    where = "[lubricant]"
    table = reader.table(data["lubricant"], where)
    reader.check_keys(table, LUBRICANT_KEYS, where)
    factor = _number(reader, table, "lubricant_factor", where, 1.0, unit="X_L", positive=True)
    has_40, has_100 = "viscosity_40" in table, "viscosity_100" in table
    has_table = "viscosity_table" in table
    if has_table and (has_40 or has_100):
        raise reader.error(at_key(where, "viscosity_table"), "give the table or 'viscosity_40' and 'viscosity_100', "
                                                             "not both.")
    if has_table:
        has_40 = has_100 = True
    rating_only = has_40 and not has_100 and "temperature" not in table  # the rating's Z_L needs ν40 alone
    if has_40 != has_100 and not rating_only:
        raise reader.error(where, "give both 'viscosity_40' and 'viscosity_100' (mm^2/s at 40 and 100 degC, from the "
                                  "oil's data sheet), or 'viscosity' (mPa*s at the operating temperature).")
    temperature = table.get("temperature")
    if isinstance(temperature, str):
        if temperature.strip().lower() != "thermal":
            raise reader.error(at_key(where, "temperature"), f"expected an oil temperature in degC or \"thermal\", "
                                                             f"got {short(temperature)}.")
        temperature = "thermal"
    elif temperature is not None:
        temperature = _number(reader, table, "temperature", where, unit="degC", minimum=-40.0, maximum=200.0)
    if not has_40:
        for key in ("density", "expansion", "specific_heat", "temperature"):
            if key in table:
                raise reader.error(at_key(where, key), "needs the oil's viscosity-temperature line: add "
                                                       "'viscosity_40' and 'viscosity_100' (mm^2/s).")
        viscosity = _number(reader, table, "viscosity", where, unit="mPa*s", positive=True)
        if viscosity is None:
            raise reader.error(where, "missing key 'viscosity' (mPa*s at the operating temperature) or "
                                      "'viscosity_40' and 'viscosity_100' (mm^2/s).")
        return Lubricant(viscosity, factor), None, None
    if temperature is None:  # the data sheet alone (e.g. for the rating): no oil state for the spin losses
        for key in ("density", "expansion", "specific_heat"):
            if key in table:
                raise reader.error(at_key(where, key), "is for the spin losses at the oil temperature: add "
                                                       "'temperature' (degC, or \"thermal\" with [housing]).")
        viscosity = _number(reader, table, "viscosity", where, unit="mPa*s", positive=True)
        return (None if viscosity is None else Lubricant(viscosity, factor)), None, None
    if "viscosity" in table:
        raise reader.error(at_key(where, "viscosity"), "'viscosity' and 'temperature' both give the oil's viscosity "
                                                       "at the operating point (the second from 'viscosity_40' and "
                                                       "'viscosity_100'); give one.")
    data_sheet = dict(density=_number(reader, table, "density", where, 860.0, unit="kg/m^3", positive=True),
                      expansion=_number(reader, table, "expansion", where, 6.5e-4, unit="1/K", minimum=0.0),
                      specific_heat=_number(reader, table, "specific_heat", where, 2000.0, unit="J/(kg K)",
                                            positive=True), lubricant_factor=factor)
    try:
        if has_table:
            rows = table["viscosity_table"]
            key = at_key(where, "viscosity_table")
            if not isinstance(rows, list) or not all(isinstance(r, list) and len(r) == 2 for r in rows):
                raise reader.error(key, f"expected pairs [temperature degC, mm^2/s] such as [[40.0, 29.5], [100.0, "
                                        f"6.0]], got {short(rows)}.")
            points = [(reader.number(t, f"viscosity_table[{k}][0]", where),
                       reader.number(v, f"viscosity_table[{k}][1]", where)) for k, (t, v) in enumerate(rows)]
            oil = Oil.from_table(points, **data_sheet)
        else:
            oil = Oil(_number(reader, table, "viscosity_40", where, unit="mm^2/s", positive=True),
                      _number(reader, table, "viscosity_100", where, unit="mm^2/s", positive=True), **data_sheet)
    except EpicyclicError as exc:
        if hasattr(exc, "source") and hasattr(exc, "where"):
            raise
        raise reader.wrap(where, exc) from None
    reference = 80.0 if temperature == "thermal" else temperature  # Schlenk's η: replaced per point when solved
    return oil.lubricant(reference), oil, temperature


def _checked(reader, where: str, build, *args, **kwargs):
    try:
        return build(*args, **kwargs)
    except EpicyclicError as exc:
        raise reader.wrap(where, exc) from None


def _drag(reader, name: str, value, where: str) -> ClutchDrag:
    d_where = f"{where}, table 'drag'"
    table = reader.table(value, d_where)
    reader.check_keys(table, DRAG_KEYS, d_where)
    gaps = reader.integer(reader.require(table, "gaps", d_where), "drag.gaps", where)
    numbers = {key: _number(reader, table, key, d_where, unit="mm", positive=True)
               for key in ("inner_radius", "outer_radius", "clearance")}
    for key, number in numbers.items():
        if number is None:
            raise reader.error(d_where, f"missing key {key!r} (mm).")
    supply = _number(reader, table, "supply", d_where, None, unit="l/min", minimum=0.0,
                     meaning="none: the gaps stay full, no aeration (an upper bound)")
    groove = _number(reader, table, "groove_factor", d_where, 1.0, unit="share of the plate", positive=True,
                     maximum=1.0)
    if supply is not None:  # the mist matters only where the film can aerate
        _default(reader, table, "mist", d_where, True, "true (the oil mist past the film edge shears)")
    mist = reader.boolean(table, "mist", d_where, True)
    return _checked(reader, d_where, ClutchDrag, name, gaps, numbers["inner_radius"], numbers["outer_radius"],
                    numbers["clearance"], supply, groove, mist)


def _pump(reader, value) -> OilPump:
    where = "[pump]"
    table = reader.table(value, where)
    reader.check_keys(table, _PUMP_KEYS, where)
    displacement = _number(reader, table, "displacement", where, unit="cm^3", positive=True)
    if displacement is None:
        raise reader.error(where, "missing key 'displacement' (cm^3 per revolution).")
    pressure = reader.require(table, "pressure", where)
    default = None
    if isinstance(pressure, dict):
        by_gear = {}
        for gear, bar in pressure.items():
            number = reader.number(bar, f"pressure.{gear}", where)
            if number < 0:
                raise reader.error(at_key(where, f"pressure.{gear}"), f"expected bar >= 0, got {short(bar)}.")
            if gear == "default":
                default = number
            else:
                by_gear[gear] = number
        if not by_gear:
            raise reader.error(at_key(where, "pressure"), "expected bar by gear, e.g. { \"1\" = 14.0, default = 8.0 }.")
        pressure = by_gear
    else:
        pressure = _number(reader, table, "pressure", where, unit="bar", minimum=0.0)
    efficiency = _number(reader, table, "efficiency", where, 0.85, unit="eta_hm in (0, 1]", positive=True,
                         maximum=1.0)
    _default(reader, table, "shaft", where, None, "the transmission's input")
    shaft = reader.shaft(table, "shaft", where) if "shaft" in table else None
    return _checked(reader, where, OilPump, displacement, pressure, efficiency, shaft, default)


def _housing(reader, value) -> Housing:
    where = "[housing]"
    table = reader.table(value, where)
    reader.check_keys(table, _HOUSING_KEYS, where)
    area = _number(reader, table, "area", where, unit="m^2", positive=True)
    if area is None:
        raise reader.error(where, "missing key 'area' (outer surface of the housing, m^2).")
    return _checked(reader, where, Housing, area,
                    _number(reader, table, "ambient", where, 20.0, unit="degC", minimum=-40.0, maximum=80.0),
                    _number(reader, table, "heat_transfer", where, None, unit="W/(m^2 K)", positive=True,
                            meaning="natural convection 1.32 (dT/L)^0.25 W/(m^2 K)"),
                    _number(reader, table, "height", where, 0.3, unit="m", positive=True),
                    _number(reader, table, "emissivity", where, 0.9, unit="in [0, 1]; 0: convection only", minimum=0.0,
                            maximum=1.0),
                    _number(reader, table, "cooler", where, 0.0, unit="W/K", minimum=0.0),
                    _number(reader, table, "coolant", where, None, unit="degC", minimum=-40.0, maximum=150.0,
                            meaning="the ambient temperature"))


def _gears(reader, data, kind: str, keys: set[str], build, numbers: dict[str, tuple[str, Any]]):
    out = []
    for k, table in enumerate(reader.array_of_tables(data, kind)):
        where = f"[[{kind}]] #{k + 1}"
        reader.check_keys(table, keys, where)
        shaft = reader.shaft(table, "shaft", where)
        values = {}
        for key, (unit, default) in numbers.items():
            value = _number(reader, table, key, where, default, unit=unit, positive=True)
            if value is None:
                raise reader.error(where, f"missing key {key!r} ({unit}).")
            values[key] = value
        if "element" in table:
            values["element"] = reader.name(table, "element", where)
        elif "element" in keys:
            _default(reader, table, "element", where, None, "housing (the loss is reported under it)")
        if "count" in table:
            values["count"] = reader.integer(table["count"], "count", where)
        elif "count" in keys:
            _default(reader, table, "count", where, 1, "1")
        out.append(_checked(reader, where, build, shaft, **values))
    return tuple(out)


def read_spin(reader, data: Mapping[str, Any], oil: Oil | None, temperature, train, input: str | None):
    """The file's :class:`~epicyclic.losses.SpinLosses`, or None when it has no spin-loss table.

    Parameters
    ----------
    reader : TableReader
        The file's reader (errors name the file and key).
    data : mapping
        The parsed file.
    oil : Oil or None
        From ``[lubricant]``.
    temperature : float, "thermal" or None
        From ``[lubricant]``.
    train : GearTrain
        The file's train (names checked against it).
    input : str or None
        The transmission's input (drives the pump by default).

    Returns
    -------
    SpinLosses or None
    """
    drags = []
    for kind in ("clutch", "brake"):
        for k, table in enumerate(reader.array_of_tables(data, kind)):
            if isinstance(table, dict) and "drag" in table:
                where = reader.element_where(kind, k, table)
                drags.append(_drag(reader, table.get("name", ""), table["drag"], where))
    pump = _pump(reader, data["pump"]) if "pump" in data else None
    housing = _housing(reader, data["housing"]) if "housing" in data else None
    churning = _gears(reader, data, "churning", _CHURNING_KEYS, ChurningGear,
                      {"pitch_radius": ("mm", None), "face_width": ("mm", None), "immersion": ("mm", None),
                       "oil_volume": ("l", None)})
    windage = _gears(reader, data, "windage", _WINDAGE_KEYS, WindageGear,
                     {"radius": ("mm", None), "face_width": ("mm", None), "density": ("kg/m^3", 1.204),
                      "kinematic_viscosity": ("mm^2/s", 15.1)})
    seals = _gears(reader, data, "seal", _SEAL_KEYS, ShaftSeal, {"diameter": ("mm", None),
                                                                 "factor": ("W per mm^2 per 1/min", 7.69e-6)})
    if temperature == "thermal" and housing is None:
        raise reader.error("[lubricant], key 'temperature'", "\"thermal\" needs a [housing] table (area, ...) for the "
                                                            "heat balance; add one or give the temperature in degC.")
    if housing is not None and temperature != "thermal":
        raise reader.error("[housing]", "the housing's heat balance is used with [lubricant] temperature = "
                                        "\"thermal\"; set that, or remove [housing].")
    if (drags or churning) and oil is None:
        raise reader.error("[lubricant]", "clutch drag and churning need the oil at its temperature: give "
                                          "'viscosity_40', 'viscosity_100' (mm^2/s) and 'temperature' (degC or "
                                          "\"thermal\") in [lubricant].")
    if not (drags or pump or churning or windage or seals or oil is not None):
        return None
    spin = _checked(reader, "top level", SpinLosses, oil, None if temperature == "thermal" else temperature,
                    housing, tuple(drags), pump, churning, windage, seals,
                    tuple(getattr(reader, "spin_defaults", ()) or ()))
    _checked(reader, "top level", spin.check, train, input)
    return spin
