"""Read a numeric CSV table with units in its header: drive cycles and shift schedules.

A header cell is a column name with an optional unit in brackets,
``vehicle_speed [km/h]``; without one the column's default unit holds (named
in ``docs/drive-cycles.md``).  Lines starting with ``#`` are comments.  Every
value must be a finite number; the errors name the file, the line and the
column, and say what to write instead.  The file itself is read by
:func:`~epicyclic.io.source.read_source` (a regular file, at most
:func:`~epicyclic.limits.max_file_bytes`, UTF-8).

Speeds, torques and powers take every unit of :mod:`epicyclic.units`; the
other quantities one of a fixed list (:data:`UNITS`), so a header can never
make the reader parse an expression.

Examples
--------
>>> table = read_csv_text("time [s],vehicle_speed [km/h]\\n0,0\\n1,3.6\\n", "c.csv",
...                       {"time": Column("time", "s"), "vehicle_speed": Column("velocity", "km/h")})
>>> table.values["vehicle_speed"].tolist(), table.units["vehicle_speed"]
([0.0, 1.0], 'km/h')
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType

import numpy as np

from ..limits import MAX_NAME_CHARS, MAX_UNIT_CHARS
from ..units import UnitError, unit_factor
from .source import InputFileError, read_source

__all__ = ["Column", "CsvTable", "read_csv_text", "read_csv_file", "UNITS"]

#: Accepted units of the quantities :mod:`epicyclic.units` does not hold, with the factor to the core unit
#: (time s, velocity m/s, mass kg, length m, area m², density kg/m³, fraction 1).
UNITS: Mapping[str, Mapping[str, float]] = MappingProxyType({
    "time": {"s": 1.0, "ms": 1e-3, "min": 60.0, "h": 3600.0},
    "velocity": {"m/s": 1.0, "km/h": 1 / 3.6, "kph": 1 / 3.6, "mph": 0.44704},
    "mass": {"kg": 1.0, "t": 1000.0, "lb": 0.45359237},
    "length": {"m": 1.0, "mm": 1e-3, "cm": 1e-2},
    "area": {"m^2": 1.0, "m**2": 1.0, "m²": 1.0},
    "density": {"kg/m^3": 1.0, "kg/m**3": 1.0, "kg/m³": 1.0},
    "fraction": {"1": 1.0, "%": 0.01, "percent": 0.01},
})
#: Quantities whose units :func:`epicyclic.units.unit_factor` reads.
_CORE_QUANTITIES = ("speed", "torque", "power")


@dataclass(frozen=True)
class Column:
    """How a column is read: its quantity and the unit of a header without one.

    Parameters
    ----------
    quantity : str
        ``"speed"``, ``"torque"``, ``"power"`` or a key of :data:`UNITS`; ``"text"`` for a column of
        names (a gear).
    unit : str
        The default unit ("" for text).
    """

    quantity: str
    unit: str = ""


@dataclass(frozen=True, eq=False)
class CsvTable:
    """A CSV table read: numeric columns in core units, text columns, and where each row stood.

    Attributes
    ----------
    source : str
    values : mapping name → ndarray
        Numeric columns, core units (1/min, N·m, W, s, m/s, kg, m, m², kg/m³, 1).
    text : mapping name → tuple of str
    units : mapping name → str
        The unit each column was given in.
    lines : ndarray of int
        The file's line of each row (1-based), for messages.
    """

    source: str
    values: Mapping[str, np.ndarray]
    text: Mapping[str, tuple[str, ...]]
    units: Mapping[str, str]
    lines: np.ndarray

    @property
    def rows(self) -> int:
        return int(self.lines.size)

    def where(self, row: int, column: str) -> str:
        """``"cycle.csv: line 12, column 'time'"`` for messages."""
        return f"{self.source}: line {int(self.lines[row])}, column {column!r}"


def _factor(unit: str, quantity: str, field: str) -> float:
    if quantity in _CORE_QUANTITIES:
        return unit_factor(unit, quantity, field)
    table = UNITS[quantity]
    if unit not in table:
        raise UnitError(f"{field}: unknown unit {unit!r:.40} for a {quantity}; write one of "
                        f"{', '.join(table)}.", field, quantity, unit)
    return table[unit]


def _header(cell: str, source: str, line: int) -> tuple[str, str | None]:
    text = cell.strip()
    name, unit = text, None
    if text.endswith("]") and "[" in text:
        name, _, rest = text.partition("[")
        name, unit = name.strip(), rest[:-1].strip()
        if not unit or len(unit) > MAX_UNIT_CHARS:
            raise InputFileError(f"{source}: line {line}: the unit of column {name!r:.60} is empty or longer than "
                                 f"{MAX_UNIT_CHARS} characters.", source)
    if not name or len(name) > MAX_NAME_CHARS:
        raise InputFileError(f"{source}: line {line}: a column name must have 1..{MAX_NAME_CHARS} characters, "
                             f"got {text!r:.80}.", source)
    return name, unit


def read_csv_text(text: str, source: str, columns: Mapping[str, Column], *,
                  required: tuple[str, ...] = ()) -> CsvTable:
    """Read the CSV ``text`` of ``source``: the named ``columns`` (others are refused), in core units.

    Parameters
    ----------
    text : str
        The file's text.
    source : str
        Its name, for messages.
    columns : mapping name → Column
        The columns this table may have.
    required : tuple of str
        Columns it must have.

    Returns
    -------
    CsvTable

    Raises
    ------
    InputFileError
        No header or no rows, an unknown, repeated or missing column, a row of another length, a value
        that is not a finite number (the message names the line and column).
    UnitError
        A header unit that does not fit the column's quantity.
    """
    lines = [(k + 1, line) for k, line in enumerate(text.splitlines())
             if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        raise InputFileError(f"{source}: the file is empty; the first line names the columns "
                             f"({', '.join(columns)}), the lines after it hold the values.", source)
    reader = csv.reader(io.StringIO("\n".join(line for _, line in lines)))
    try:
        rows = list(reader)
    except csv.Error as exc:  # a cell beyond csv's field limit (128 KiB), a NUL byte, an unclosed quote at the end
        line = lines[min(max(reader.line_num, 1), len(lines)) - 1][0]
        reason = (f"a value is longer than {csv.field_size_limit()} characters; a cell holds one number or name"
                  if "field limit" in str(exc) else f"not readable as CSV ({exc})")
        raise InputFileError(f"{source}: line {line}: {reason}.", source) from None
    head_line = lines[0][0]
    names, units = [], {}
    for cell in rows[0]:
        name, unit = _header(cell, source, head_line)
        if name not in columns:
            from ..errors import closest

            close = closest(name, list(columns))
            raise InputFileError(f"{source}: line {head_line}: unknown column {name!r:.60}"
                                 + (f" (did you mean {close!r}?)" if close else "")
                                 + f"; the columns are {', '.join(columns)}.", source)
        if name in units:
            raise InputFileError(f"{source}: line {head_line}: column {name!r} is given twice.", source)
        spec = columns[name]
        if spec.quantity != "text":
            unit = unit or spec.unit
            _factor(unit, spec.quantity, f"{source}: line {head_line}, column {name!r}")
        names.append(name)
        units[name] = unit or spec.unit
    missing = [c for c in required if c not in units]
    if missing:
        raise InputFileError(f"{source}: line {head_line}: missing column {', '.join(repr(m) for m in missing)}; "
                             f"the columns are {', '.join(columns)}.", source)
    body = rows[1:]
    if not body:
        raise InputFileError(f"{source}: the file has a header but no rows of values.", source)
    numbers = {n: np.empty(len(body)) for n in names if columns[n].quantity != "text"}
    texts: dict[str, list[str]] = {n: [] for n in names if columns[n].quantity == "text"}
    for r, row in enumerate(body):
        line = lines[r + 1][0]
        if len(row) != len(names):
            raise InputFileError(f"{source}: line {line}: {len(row)} values, expected {len(names)} "
                                 f"({', '.join(names)}).", source)
        for name, cell in zip(names, row):
            cell = cell.strip()
            if name in texts:
                if not cell or len(cell) > MAX_NAME_CHARS:
                    raise InputFileError(f"{source}: line {line}, column {name!r}: expected a name of 1.."
                                         f"{MAX_NAME_CHARS} characters, got {cell!r:.60}.", source)
                texts[name].append(cell)
                continue
            try:
                value = float(cell)
            except ValueError:
                value = math.nan
            if not math.isfinite(value):
                raise InputFileError(f"{source}: line {line}, column {name!r}: expected a finite number in "
                                     f"{units[name]}, got {cell!r:.60}.", source)
            numbers[name][r] = value
    values = {}
    for name, array in numbers.items():
        core = array * _factor(units[name], columns[name].quantity, name)
        core.flags.writeable = False
        values[name] = core
    line_numbers = np.array([line for line, _ in lines[1:]], dtype=int)
    return CsvTable(source, MappingProxyType(values), MappingProxyType({k: tuple(v) for k, v in texts.items()}),
                    MappingProxyType(units), line_numbers)


def read_csv_file(path: str | Path, columns: Mapping[str, Column], *, required: tuple[str, ...] = ()) -> CsvTable:
    """:func:`read_csv_text` of the file ``path``, read safely (:func:`~epicyclic.io.source.read_source`).

    Parameters
    ----------
    path : str or Path
    columns : mapping name → Column
    required : tuple of str

    Returns
    -------
    CsvTable

    Raises
    ------
    InputFileError
        The file cannot be read, or its table is invalid.
    """
    return read_csv_text(read_source(path), str(path), columns, required=required)
