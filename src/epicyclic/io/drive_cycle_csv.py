"""Read a drive cycle from CSV: time, output or vehicle speed, optional output torque, grade and gear.

Columns (header ``name [unit]``; the unit in brackets is optional, the defaults are these):

========================  ==========  ===============================================
column                    default     meaning
========================  ==========  ===============================================
``time``                  s           strictly increasing (required)
``output_speed``          1/min       at the transmission output; or
``vehicle_speed``         km/h        with the wheel radius and axle ratio
``output_torque``         N*m         optional; else the road load of the vehicle
``grade``                 %           optional road grade (tan α), for the road load
``gear``                  (a name)    optional gear of every row
========================  ==========  ===============================================

Examples
--------
>>> c = read_drive_cycle_text("time,output_speed,output_torque,gear\\n0,0,0,1\\n1,500,80,1\\n", "c.csv")
>>> c.rows, c.gear
(2, ('1', '1'))
"""

from __future__ import annotations

from pathlib import Path

from ..errors import ModelError
from ..transmission.drive_cycle import DriveCycle
from ..transmission.vehicle import Vehicle
from .csv_table import Column, read_csv_text
from .source import InputFileError, read_source

__all__ = ["read_drive_cycle", "read_drive_cycle_text", "CYCLE_COLUMNS"]

#: The columns of a drive-cycle CSV and how each is read.
CYCLE_COLUMNS = {
    "time": Column("time", "s"),
    "output_speed": Column("speed", "1/min"),
    "vehicle_speed": Column("velocity", "km/h"),
    "output_torque": Column("torque", "N*m"),
    "grade": Column("fraction", "%"),
    "gear": Column("text"),
}


def read_drive_cycle_text(text: str, source: str, vehicle: Vehicle | None = None) -> DriveCycle:
    """The :class:`~epicyclic.transmission.drive_cycle.DriveCycle` of the CSV ``text``.

    Parameters
    ----------
    text : str
    source : str
        Its name, for messages.
    vehicle : Vehicle, optional
        Wheel radius and axle ratio (for ``vehicle_speed``) and the road-load data (without
        ``output_torque``).

    Returns
    -------
    DriveCycle

    Raises
    ------
    InputFileError
        A bad table (empty, unknown or missing column, a value that is no finite number: line and column
        named), or a cycle that cannot be built from its columns (no speed column, time not increasing,
        a negative speed: line and column named).
    UnitError
        A header unit that does not fit its column.
    """
    table = read_csv_text(text, source, CYCLE_COLUMNS, required=("time",))
    values = table.values
    if "output_speed" not in values and "vehicle_speed" not in values:
        raise InputFileError(f"{source}: missing column 'output_speed' or 'vehicle_speed'; a drive cycle needs one "
                             "of them beside 'time' (docs/drive-cycles.md).", source)
    try:
        return DriveCycle.from_columns(
            values["time"], output_speed=values.get("output_speed"), vehicle_speed=values.get("vehicle_speed"),
            output_torque=values.get("output_torque"), grade=values.get("grade"), gear=table.text.get("gear"),
            vehicle=vehicle, name=source, lines=table.lines)
    except ModelError as exc:  # its message names the file (the cycle's name), the line and the column
        message = str(exc) if str(exc).startswith(source) else f"{source}: {exc}"
        raise InputFileError(message, source) from None


def read_drive_cycle(path: str | Path, vehicle: Vehicle | None = None) -> DriveCycle:
    """:func:`read_drive_cycle_text` of the file ``path`` (read safely).

    Parameters
    ----------
    path : str or Path
    vehicle : Vehicle, optional

    Returns
    -------
    DriveCycle
    """
    return read_drive_cycle_text(read_source(path), str(path), vehicle)
