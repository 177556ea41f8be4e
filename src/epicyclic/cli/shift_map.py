"""``epicyclic shiftmap FILE``: best gear, efficiency envelope and saving over output speed × output torque.

Every forward gear of the file's ``[transmission]`` is solved over the grid
with the file's loss models (one batch solve per gear); at each point the best
gear is the one of least loss among those that can carry it: input speed within
``--engine-speed`` (default 800..6000 1/min), input torque at most
``--max-input-torque``, every engaged shift element within ``--capacity
NAME=TORQUE``.  ``--schedule upshift.csv`` compares with a given shift schedule
(upshift lines, ``docs/shift-map.md``).  ``--speed``/``--torque`` are output
axes ``A..B:N`` in the file's ``[units]`` or with a unit; without them the map
spans 50 1/min to the top gear's output speed at the highest engine speed, and
10 N·m to first gear's output torque at the input torque limit (500 N·m
without one).  ``-o map.png`` (``.svg``, ``.pdf``) draws the shift map,
``-o map.csv`` / ``-o map.json`` writes the numbers; otherwise ``-f table|json``
prints.  Exit codes: 0, 2 bad input, 1 internal error.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from ._common import FormatOption, OutputFormat, SetOption, check_finite, emit, guarded, say

__all__ = ["shift_map", "DEFAULT_MAP_INPUT_TORQUE", "limits_from_options", "EngineSpeedOption",
           "MaxInputTorqueOption", "CapacityOption"]

#: The carrying limits of ``shiftmap`` and ``cycle`` (:func:`limits_from_options`).
EngineSpeedOption = Annotated[Optional[str], typer.Option(
    "--engine-speed", help="Input speeds a gear may run at, LOW..HIGH. Default: the file's [transmission] "
                           "input_speed_range, else 800..6000 1/min.")]
MaxInputTorqueOption = Annotated[Optional[str], typer.Option(
    "--max-input-torque", help="Most input (engine) torque. Default: the file's [transmission] "
                               "max_input_torque, else none (cycle) or 500 N*m (shiftmap).")]
CapacityOption = Annotated[Optional[list[str]], typer.Option(
    "--capacity", help="Torque capacity of a shift element, NAME=TORQUE (repeatable).")]

#: Input torque (N·m) the default output-torque axis reaches in first gear when no --max-input-torque is given.
DEFAULT_MAP_INPUT_TORQUE = 500.0


def _capacities(values: list[str] | None) -> dict[str, str]:
    from ..errors import ModelError

    out = {}
    for text in values or ():
        name, sep, value = text.partition("=")
        if not sep or not name.strip() or not value.strip():
            raise ModelError(f"--capacity {text!r:.60}: expected NAME=TORQUE, e.g. --capacity B=1800 "
                             "or --capacity 'B=180 kp*m'.")
        out[name.strip()] = value.strip()
    return out


#: Input speeds beyond this (1/min) are beyond any road vehicle's engine or traction motor: warned.
PLAUSIBLE_INPUT_SPEED = 20000.0


def limits_from_options(engine_speed: str | None, max_input_torque: str | None, capacity: list[str] | None,
                        units=None, rated=None, default_torque: float | None = None):
    """The :class:`~epicyclic.transmission.gear_points.CarryLimits` of the options (shared with ``cycle``).

    Defaults are the file's rated range (``[transmission] input_speed_range``, ``max_input_torque``), else
    800 … 6000 1/min and ``default_torque``; an option beyond the file's rated range, or speeds beyond
    :data:`PLAUSIBLE_INPUT_SPEED`, are used and warned on stderr.

    Parameters
    ----------
    engine_speed : str or None
        ``"800..6000"`` in the file's speed unit, or with a unit.
    max_input_torque : str or None
        A torque, plain numbers in the file's unit.
    capacity : list of str or None
        ``NAME=TORQUE`` items.
    units : Units, optional
        The file's ``[units]``.
    rated : epicyclic.io.Transmission, optional
        The file's ``[transmission]`` (its rated input speeds and torque).
    default_torque : float, optional
        The input torque limit, N·m, where neither the option nor the file gives one (None: no limit).

    Returns
    -------
    CarryLimits
    """
    from ..io.ranges import parse_axis
    from ..transmission.gear_points import DEFAULT_INPUT_SPEED_RANGE, CarryLimits
    from ..units import Units, to_core
    from ._common import note

    units = units or Units()
    file_speeds = getattr(rated, "input_speed_range", None)
    file_torque = getattr(rated, "max_input_torque", None)
    speed_range = file_speeds or DEFAULT_INPUT_SPEED_RANGE
    if engine_speed is not None:
        axis = parse_axis(engine_speed, "--engine-speed", units.speed, "speed")
        speed_range = (float(axis[0]), float(axis[-1]))
        if file_speeds and (speed_range[0] < file_speeds[0] or speed_range[1] > file_speeds[1]):
            note(f"warning: --engine-speed {speed_range[0]:g}..{speed_range[1]:g} 1/min is outside the file's rated "
                 f"input_speed_range {file_speeds[0]:g}..{file_speeds[1]:g} 1/min ([transmission]).")
        elif speed_range[1] > PLAUSIBLE_INPUT_SPEED:
            note(f"warning: --engine-speed up to {speed_range[1]:g} 1/min is beyond any road vehicle's engine or "
                 f"motor (> {PLAUSIBLE_INPUT_SPEED:g} 1/min); state the rated range as [transmission] "
                 "input_speed_range.")
    torque = file_torque if file_torque is not None else default_torque
    if max_input_torque is not None:
        torque = to_core(max_input_torque, "torque", field="--max-input-torque", default_unit=units.torque)
        if file_torque is not None and torque > file_torque:
            note(f"warning: --max-input-torque {torque:g} N*m exceeds the file's rated max_input_torque "
                 f"{file_torque:g} N*m ([transmission]).")
    capacities = {k: to_core(v, "torque", field=f"--capacity {k}", default_unit=units.torque)
                  for k, v in _capacities(capacity).items()}
    return CarryLimits(speed_range, torque, capacities)


@guarded
def shift_map(
    file: Annotated[Path, typer.Argument(help="Train description (.toml) with a [transmission] table and losses.")],
    speed: Annotated[Optional[str], typer.Option(
        "--speed", help="Output speeds A..B:N in the file's [units] or with a unit. Default: 50 1/min to the "
                        "top gear's at the highest engine speed, 60 values.")] = None,
    torque: Annotated[Optional[str], typer.Option(
        "--torque", help="Output torques A..B:N. Default: 10 N*m to first gear's at the input torque limit "
                         "(the file's max_input_torque, else 500 N*m), 50 values.")] = None,
    engine_speed: EngineSpeedOption = None,
    max_input_torque: MaxInputTorqueOption = None,
    capacity: CapacityOption = None,
    schedule: Annotated[Optional[Path], typer.Option(
        "--schedule", help="A shift schedule to compare with: CSV of upshift lines (docs/shift-map.md).")] = None,
    gears: Annotated[Optional[str], typer.Option(
        "--gears", help="Gears compared, comma-separated. Default: every forward gear.")] = None,
    format: FormatOption = OutputFormat.table,
    out: Annotated[Optional[Path], typer.Option(
        "--out", "-o", help="Write the map: .png, .svg, .pdf (figure), .csv or .json.")] = None,
    set_: SetOption = None,
) -> None:
    """Shift map of FILE: the gear of least loss over output speed x torque, the envelope, the saving."""
    import numpy as np

    from ..errors import ModelError
    from ..io import load_train_file
    from ..io.output import atomic_path, refuse_input
    from ..io.ranges import parse_axis
    from ..limits import MAX_MAP_POINTS
    from ..transmission import Transmission
    from ..transmission.shift_map import SHIFT_MAP_SUFFIXES, forward_gears, shift_map as compute

    if out is not None and out.suffix.lower() not in SHIFT_MAP_SUFFIXES:
        raise ModelError(f"--out {str(out)!r}: give a file ending in {', '.join(SHIFT_MAP_SUFFIXES)}.")
    if out is not None and schedule is not None:
        refuse_input(out, [schedule])
    spec = load_train_file(file, overrides=set_ or ())
    transmission = Transmission.from_train_file(spec)  # the file read once
    limits = limits_from_options(engine_speed, max_input_torque, capacity, spec.units, spec.transmission,
                                 DEFAULT_MAP_INPUT_TORQUE)
    chosen = tuple(g.strip() for g in gears.split(",")) if gears else forward_gears(transmission)
    given = None
    if schedule is not None:
        from ..io.shift_schedule_csv import read_shift_schedule

        given = read_shift_schedule(schedule)
    ratios = [abs(transmission.ratio(g)) for g in chosen if g in transmission.schedule]
    if speed is None:
        top = limits.input_speed[1] / min(ratios) if ratios else 6000.0
        speeds = np.linspace(50.0, max(top, 100.0), 60)
    else:
        speeds = parse_axis(speed, "--speed", spec.units.speed, "speed")
    if torque is None:
        first = max(ratios) if ratios else 1.0
        torques = np.linspace(10.0, limits.max_input_torque * first, 50)
    else:
        torques = parse_axis(torque, "--torque", spec.units.torque, "torque")
    if speeds.size * torques.size > MAX_MAP_POINTS:
        raise ModelError(f"--speed/--torque: {speeds.size} × {torques.size} points exceed the limit of "
                         f"{MAX_MAP_POINTS:,}; use fewer values.")
    smap = compute(transmission, speeds, torques, gears=chosen, limits=limits, schedule=given)
    note = "" if transmission.losses else (
        "note: the file has no loss tables: every gear's loss comes from its typed-in stationary efficiencies "
        "(see docs/losses.md).")
    if out is None:
        if format is OutputFormat.json:
            text = smap.to_json()
        elif format is OutputFormat.html:
            text = ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>epicyclic shift map</title></head>"
                    "<body>" + smap._repr_html_() + "</body></html>")
        elif format is OutputFormat.markdown:
            text = "```\n" + smap.table() + "\n```"
        else:
            text = smap.table() + ("\n" + note if note else "")
        if format is OutputFormat.json:
            check_finite(smap.to_dict(), file)
        emit(text, None)
        return
    if out.suffix.lower() in (".png", ".svg", ".pdf"):
        import matplotlib

        matplotlib.use("Agg")
    with atomic_path(out) as temporary:  # the map appears whole or not at all
        smap.save(temporary)
    say(f"wrote {out.resolve()}")
    if note:
        say(note)
