"""``epicyclic shift FILE --from 2 --to 3`` and ``epicyclic launch FILE``: a shift or launch as it happens.

Both read the train, its ``[transmission]`` and the transient inputs (``[dynamics]``, ``[engine]``,
every element's ``capacity``; ``docs/dynamics.md``) from FILE and print the shift's figures (status,
shift time, torque and inertia phase, energy, peak power, specific energy and power, plate temperature
rise per element, warnings, the energy balance) as a table or JSON, or the time traces as CSV.
``--plot PATH`` also draws the test-bench picture (PNG, SVG or PDF).  The simulated time is the file's
``[dynamics] duration`` (a bound, stated); a shift that does not complete within it says so.
"""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ._common import OutOption, SetOption, emit, guarded

__all__ = ["shift", "launch"]


class TraceFormat(str, Enum):
    """Output formats of ``shift`` and ``launch``."""

    table = "table"
    json = "json"
    csv = "csv"


FormatOption = Annotated[TraceFormat, typer.Option(
    "--format", "-f", help="table (figures), json (figures and traces) or csv (traces).")]
ThrottleOption = Annotated[Optional[str], typer.Option(
    "--throttle", help="Engine throttle, 0 ... 100% or 0 ... 1 (default: the file's [engine] throttle).")]
PlotOption = Annotated[Optional[Path], typer.Option(
    "--plot", help="Also draw the test-bench picture (speeds, torques, pressures, slip power) to this "
                   ".png/.svg/.pdf file.")]


def _throttle(text: str | None) -> float | None:
    from ..dynamics import DynamicsError
    from ..errors import EpicyclicError
    from ..io.ranges import parse_tolerance

    if text is None:
        return None
    try:
        value = parse_tolerance(text) if text.strip().endswith("%") else float(text)
    except (ValueError, EpicyclicError):
        raise DynamicsError(f"--throttle: expected 0 ... 100% or 0 ... 1, got {text!r:.40}.") from None
    if not 0.0 <= value <= 1.0:
        raise DynamicsError(f"--throttle: expected 0 ... 100% or 0 ... 1, got {text!r:.40}.")
    return value


def _load(file: Path, overrides):
    from ..io import load_train_file
    from ..io.dynamics_format import dynamics_spec
    from ..io.source import read_source
    from ..transmission import Transmission

    train_file = load_train_file(file, overrides=overrides)
    transmission = Transmission.from_train_file(train_file)
    return transmission, dynamics_spec(read_source(file), str(file), transmission, overrides)


def _emit(result, format: TraceFormat, out, plot) -> None:
    if plot is not None:
        import matplotlib

        matplotlib.use("Agg")
        from ..plotting._common import check_suffix, save_figure

        check_suffix(plot, (".png", ".svg", ".pdf"), "--plot")
        from ..text import terminal_text

        typer.echo(terminal_text(f"wrote {save_figure(result.plot(), plot).resolve()}"), err=True)  # stdout: the data
    if format is TraceFormat.json:
        text = result.to_json()
    elif format is TraceFormat.csv:
        text = result.to_csv()
    else:
        text = result.table()
    emit(text, out)


@guarded
def shift(
    file: Annotated[Path, typer.Argument(help="Train file (.toml) with [transmission], [dynamics], [engine] and "
                                              "the elements' capacity tables.")],
    from_gear: Annotated[str, typer.Option("--from", help="The gear before the shift.")],
    to_gear: Annotated[str, typer.Option("--to", help="The gear after it (one element out, one in).")],
    throttle: ThrottleOption = None,
    format: FormatOption = TraceFormat.table,
    out: OutOption = None,
    plot: PlotOption = None,
    set_: SetOption = None,
) -> None:
    """A shift as it happens: phases, clutch energy and power, temperature, warnings; traces as CSV/JSON."""
    from ..dynamics.shift import simulate_shift

    transmission, spec = _load(file, set_ or ())
    result = simulate_shift(transmission, spec, from_gear, to_gear, throttle=_throttle(throttle))
    _emit(result, format, out, plot)


@guarded
def launch(
    file: Annotated[Path, typer.Argument(help="Train file (.toml) with [transmission], [dynamics], [engine] and "
                                              "the elements' capacity tables.")],
    gear: Annotated[Optional[str], typer.Option("--gear", help="The launch gear (default: the first).")] = None,
    throttle: ThrottleOption = None,
    format: FormatOption = TraceFormat.table,
    out: OutOption = None,
    plot: PlotOption = None,
    set_: SetOption = None,
) -> None:
    """A launch from standstill with the launch element slipping: energy, power, temperature; traces."""
    from ..dynamics.shift import simulate_launch

    transmission, spec = _load(file, set_ or ())
    result = simulate_launch(transmission, spec, gear, throttle=_throttle(throttle))
    _emit(result, format, out, plot)
