"""Read a shift schedule from CSV: output torque, then the output speed of every upshift.

The layout (``docs/shift-map.md``)::

    # upshift lines of an illustrative schedule
    output_torque [N*m],1-2 [1/min],2-3 [1/min],3-4 [1/min]
    0,260,390,580
    1000,420,640,950

One row per output torque (increasing), one column per upshift ``<from>-<to>`` in shift order with
the output speed at which it happens; units as in :mod:`epicyclic.io.csv_table` (default N·m and
1/min).

Examples
--------
>>> s = read_shift_schedule_text("output_torque,1-2,2-3\\n0,300,600\\n400,600,1200\\n", "s.csv")
>>> s.gears, s.upshift_speeds.tolist()
(('1', '2', '3'), [[300.0, 600.0], [600.0, 1200.0]])
"""

from __future__ import annotations

from pathlib import Path

from ..transmission.shift_schedule import ShiftSchedule
from .csv_table import Column, read_csv_text
from .source import InputFileError, read_source

__all__ = ["read_shift_schedule", "read_shift_schedule_text"]

TORQUE = "output_torque"


def read_shift_schedule_text(text: str, source: str) -> ShiftSchedule:
    """The :class:`~epicyclic.transmission.shift_schedule.ShiftSchedule` of the CSV ``text``.

    Parameters
    ----------
    text : str
    source : str
        Its name, for messages.

    Returns
    -------
    ShiftSchedule

    Raises
    ------
    InputFileError
        A bad table (see :func:`~epicyclic.io.csv_table.read_csv_text`), no upshift column.
    ModelError
        Upshifts out of order, torques not increasing.
    """
    import csv
    import io

    first = next((line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")), "")
    names = [cell.split("[")[0].strip() for cell in next(csv.reader(io.StringIO(first)), [])]
    upshifts = [n for n in names if n != TORQUE]
    odd = [n for n in upshifts if "-" not in n.strip("-")]
    if odd:
        raise InputFileError(f"{source}: column {odd[0]!r:.60} is neither {TORQUE!r} nor an upshift such as '1-2'; "
                             f"a shift schedule has the columns {TORQUE}, 1-2, 2-3, ... (docs/shift-map.md).", source)
    if not upshifts:
        raise InputFileError(f"{source}: a shift schedule needs the column {TORQUE!r} and one column per upshift "
                             "('1-2', '2-3', ...) with its output speed.", source)
    columns = {TORQUE: Column("torque", "N*m"), **{n: Column("speed", "1/min") for n in upshifts}}
    table = read_csv_text(text, source, columns, required=(TORQUE,))
    return ShiftSchedule.from_columns(table.values[TORQUE], {n: table.values[n] for n in upshifts},
                                      name=Path(source).name)


def read_shift_schedule(path: str | Path) -> ShiftSchedule:
    """:func:`read_shift_schedule_text` of the file ``path`` (read safely).

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    ShiftSchedule
    """
    return read_shift_schedule_text(read_source(path), str(path))
