"""``epicyclic cycle FILE --cycle CSV``: a transmission through a drive cycle, energies by source and element.

The cycle (``docs/drive-cycles.md``) gives time and the output speed, or the
vehicle speed with ``--wheel-radius`` and ``--axle-ratio``; the output torque,
or the road load from ``--mass``, ``--rolling-coefficient``, ``--drag-area``,
``--air-density`` (and the cycle's ``grade``).  The gear of each row is the
cycle's ``gear`` column, or ``--gear-rule best`` (least loss among the gears that
carry the row, ``--min-dwell`` s and ``--hysteresis`` W), or ``--gear-rule
schedule --schedule upshift.csv``.  Prints energy in and out, the energy lost
by source and element and the cycle efficiency (``-f table|json``); ``-o
rows.csv`` writes every row, ``-o result.json`` the summary.  A progress line
goes to stderr for cycles of :data:`PROGRESS_ROWS` rows or more (``--quiet``:
none).  Exit codes: 0, 2 bad input, 1 internal error.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Annotated, Optional

import typer

from ._common import FormatOption, OutputFormat, SetOption, check_finite, emit, guarded
from .shift_map import CapacityOption, EngineSpeedOption, MaxInputTorqueOption

__all__ = ["cycle", "PROGRESS_ROWS"]

#: Cycles with at least this many rows show a progress line on stderr.
PROGRESS_ROWS = 5000


def _progress(quiet: bool, rows: int):
    if quiet or rows < PROGRESS_ROWS:
        return None

    def report(done: int, total: int) -> None:
        percent = 100 * done // max(total, 1)
        line = f"cycle: {rows} rows, gear solves {done}/{total} ({percent} %)"
        if sys.stderr.isatty():
            typer.echo("\r" + line, err=True, nl=done == total)
        else:
            typer.echo(line, err=True)

    return report


#: Vehicle fields and the options that give them (in the order of Vehicle's arguments).
_VEHICLE_OPTIONS = (("wheel_radius", "--wheel-radius", "length"), ("axle_ratio", "--axle-ratio", None),
                    ("mass", "--mass", "mass"), ("rolling_coefficient", "--rolling-coefficient", None),
                    ("drag_area", "--drag-area", "area"), ("air_density", "--air-density", "density"),
                    ("rotating_mass_factor", "--rotating-mass-factor", None),
                    ("axle_efficiency", "--axle-efficiency", None))


def _vehicle(*values):
    """The Vehicle of the options; a bad value is an OptionError naming its option (not the train file)."""
    from ..transmission.vehicle import Vehicle
    from .options import naming_options, quantity_option

    read = [quantity_option(v, option, quantity) if quantity else v
            for v, (_, option, quantity) in zip(values, _VEHICLE_OPTIONS)]
    with naming_options("vehicle", {field: option for field, option, _ in _VEHICLE_OPTIONS}):
        return Vehicle(*read)


@guarded
def cycle(
    file: Annotated[Path, typer.Argument(help="Train description (.toml) with a [transmission] table and losses.")],
    cycle_file: Annotated[Path, typer.Option("--cycle", help="The drive cycle, CSV (docs/drive-cycles.md).")],
    mass: Annotated[Optional[str], typer.Option("--mass", help="Vehicle mass (road load): kg, or with a unit "
                                                "('1.8 t').")] = None,
    wheel_radius: Annotated[Optional[str], typer.Option("--wheel-radius", help="Dynamic wheel radius: m, or with a "
                                                        "unit ('310 mm').")] = None,
    axle_ratio: Annotated[Optional[float], typer.Option("--axle-ratio", help="Final-drive ratio.")] = None,
    rolling_coefficient: Annotated[float, typer.Option("--rolling-coefficient", help="c_r.")] = 0.010,
    drag_area: Annotated[str, typer.Option("--drag-area", help="c_d*A: m^2, or with a unit.")] = "0 m^2",
    air_density: Annotated[str, typer.Option("--air-density", help="kg/m^3, or with a unit.")] = "1.204 kg/m^3",
    rotating_mass_factor: Annotated[float, typer.Option("--rotating-mass-factor", help="lambda >= 1.")] = 1.0,
    axle_efficiency: Annotated[float, typer.Option("--axle-efficiency", help="Final-drive efficiency.")] = 1.0,
    gear_rule: Annotated[Optional[str], typer.Option(
        "--gear-rule", help="given (the cycle's gear column), best (least loss) or schedule. Default: given "
                            "where the cycle has gears, else best.")] = None,
    schedule: Annotated[Optional[Path], typer.Option("--schedule", help="Upshift lines, CSV (docs/shift-map.md).")] = None,
    min_dwell: Annotated[float, typer.Option("--min-dwell", help="best: least time in a gear, s.")] = 2.0,
    hysteresis: Annotated[float, typer.Option("--hysteresis", help="best: least loss a shift must save, W.")] = 0.0,
    engine_speed: EngineSpeedOption = None,
    max_input_torque: MaxInputTorqueOption = None,
    capacity: CapacityOption = None,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No progress line on stderr.")] = False,
    format: FormatOption = OutputFormat.table,
    out: Annotated[Optional[Path], typer.Option(
        "--out", "-o", help="Write every row (.csv) or the summary (.json, .txt).")] = None,
    set_: SetOption = None,
) -> None:
    """Run FILE's transmission through a drive cycle: energy in, out, lost by source and element."""
    from ..errors import ModelError
    from ..io import load_train_file
    from ..io.drive_cycle_csv import read_drive_cycle
    from ..io.output import refuse_input, write_atomic
    from ..transmission import Transmission
    from ..transmission.cycle_energy import GearRule, run_cycle
    from ._common import say
    from .options import OptionError, naming_options
    from .shift_map import limits_from_options

    if out is not None:
        if out.suffix.lower() not in (".csv", ".json", ".txt"):
            raise ModelError(f"--out {str(out)!r}: give a file ending in .csv (every row), .json or .txt (summary).")
        refuse_input(out, [cycle_file, schedule])
    spec = load_train_file(file, overrides=set_ or ())
    transmission = Transmission.from_train_file(spec)  # the file read once
    limits = limits_from_options(engine_speed, max_input_torque, capacity, spec.units, spec.transmission)
    vehicle = None
    if wheel_radius is not None or axle_ratio is not None or mass is not None:
        if wheel_radius is None or axle_ratio is None:
            raise OptionError("--wheel-radius", "and --axle-ratio go together (the vehicle's wheel and final drive).",
                              joined=" ")
        vehicle = _vehicle(wheel_radius, axle_ratio, mass, rolling_coefficient, drag_area, air_density,
                           rotating_mass_factor, axle_efficiency)
    drive_cycle = read_drive_cycle(cycle_file, vehicle)
    given = None
    if schedule is not None:
        from ..io.shift_schedule_csv import read_shift_schedule

        given = read_shift_schedule(schedule)
    mode = gear_rule or ("schedule" if given is not None else "given" if drive_cycle.gear is not None else "best")
    if mode not in ("given", "best", "schedule"):
        raise ModelError(f"--gear-rule {mode!r:.40}: expected given, best or schedule.")
    if given is not None and mode != "schedule":
        raise ModelError(f"--schedule is read by --gear-rule schedule only, not by --gear-rule {mode}; drop one.")
    if mode == "given" and drive_cycle.gear is None:
        raise ModelError(f"--gear-rule given: {cycle_file} has no 'gear' column; give one, or --gear-rule best.")
    with naming_options("gear rule", {"min_dwell": "--min-dwell", "hysteresis": "--hysteresis"}):
        rule = GearRule(mode, given, min_dwell, hysteresis)
    result = run_cycle(transmission, drive_cycle, rule=rule, limits=limits,
                       progress=_progress(quiet, drive_cycle.rows))
    check_finite(result.to_dict(), file)
    if out is not None:
        suffix = out.suffix.lower()
        text = result.to_csv() if suffix == ".csv" else result.to_json() if suffix == ".json" else result.table() + "\n"
        say(f"wrote {write_atomic(out, text).resolve()}")
        return
    emit(result.to_json() if format is OutputFormat.json else
         "```\n" + result.table() + "\n```" if format is OutputFormat.markdown else result.table(), None)
