"""``epicyclic gears FILE`` and ``epicyclic explore FILE``: multi-speed transmissions.

``gears`` prints the per-gear table of a file with a ``[transmission]`` table
(ratio, step, efficiency in drive and coast, circulating power, the most
loaded shift element, rolling sets; then spread and mean step), with
``--detail`` also every shift element's torque and slip per gear.  Every gear
is analysed at one input point, stated in every output: ``--speed``/``--torque``
(with units), else the file's ``[operating_point]``, else 1000 1/min and
100 N·m (:mod:`epicyclic.transmission.input_point`).
``explore`` lists every combination of the file's clutches and brakes that
gives a one-degree-of-freedom drive between input and output.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Optional

import typer

from ..errors import EpicyclicError
from ..io.located import located
from ._common import FormatOption, OutOption, OutputFormat, SetOption, check_finite, emit, guarded, note_rexs

if TYPE_CHECKING:  # pragma: no cover
    from ..transmission import Transmission

__all__ = ["gears", "explore"]


def _render(result, format: OutputFormat, detail_text: str = "") -> str:
    if format is OutputFormat.json:
        return json.dumps(result.to_dict(), indent=2, ensure_ascii=False)
    if format is OutputFormat.markdown:
        return result.markdown()
    if format is OutputFormat.html:
        return ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>epicyclic</title></head><body>"
                + result._repr_html_() + "</body></html>")
    return result.table() + (("\n\n" + detail_text) if detail_text else "")


def _failing_gear(transmission: Transmission, point) -> str:
    """The first gear whose analysis fails (called only after analyze_all failed)."""
    for gear in transmission.gears:
        try:
            transmission.analyze(gear, input_speed=point.speed, input_torque=point.torque)
        except EpicyclicError:
            return gear
    return "?"


@guarded
def gears(
    file: Annotated[Path, typer.Argument(help="Train description (.toml) with a [transmission] table.")],
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    detail: Annotated[bool, typer.Option("--detail", help="Also list every shift element and set per gear.")] = False,
    speed: Annotated[Optional[str], typer.Option(
        "--speed", help="Input speed of every gear, in the file's [units] or with a unit ('2000 U/min'). "
                        "Default: the [operating_point]'s, else 1000 1/min.")] = None,
    torque: Annotated[Optional[str], typer.Option(
        "--torque", help="Input torque in drive (coast: at the output, x |ratio|), in the file's [units] or "
                         "with a unit ('15 kp*m'). Default: the [operating_point]'s, else 100 N*m.")] = None,
    set_: SetOption = None,
) -> None:
    """Per gear: ratio, step, efficiency drive/coast, shift-element loads, rolling sets; spread.

    Every gear is analysed at one input point, stated in the output: --speed/--torque, else the file's
    [operating_point], else 1000 1/min and 100 N*m.  With ``-f html``: one self-contained page styled like
    ``analyze -f html``, with every gear's detail, its lever diagram and the speed chart across gears.
    """
    from ..io import load_train_file
    from ..transmission import Transmission  # imported here: other commands start faster without it
    from ..transmission.input_point import input_point

    spec = load_train_file(file, overrides=set_ or ())  # read once: the transmission and the report share it
    transmission = Transmission.from_train_file(spec)
    note_rexs(file)
    point = input_point(transmission.input, spec.operating_point, speed=speed, torque=torque, units=spec.units)
    try:
        analysis = transmission.analyze_all(point=point)
    except EpicyclicError as exc:  # name the gear, and the option that set the point where one did
        gear = _failing_gear(transmission, point)
        options = [o for o, source in (("--speed", point.speed_source), ("--torque", point.torque_source))
                   if source == o]
        if options:
            from .options import OptionError

            raise OptionError(" and ".join(options), f"in gear {gear} at {point.describe()}: {exc}") from None
        raise located(exc, str(file), f"[transmission], key {f'schedule.{gear}'!r}") from None
    check_finite(analysis.to_dict(), file)
    if format is OutputFormat.html:
        emit(_gears_html(file, spec, transmission, analysis), out)
        return
    detail_text = "\n\n".join(g.table() for g in analysis.gears) if detail else ""
    emit(_render(analysis, format, detail_text), out)


def _gears_html(file: Path, spec, transmission, analysis) -> str:
    import matplotlib

    from ..io.gears_report import gears_html

    matplotlib.use("Agg")  # files only: no display needed
    return gears_html(transmission, analysis, spec.units, title=spec.title or None, source=str(file))


@guarded
def explore(
    file: Annotated[Path, typer.Argument(help="Train description (.toml) with a [transmission] table.")],
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    redundant: Annotated[bool, typer.Option("--redundant", help="Also list states with a redundant element.")] = False,
    set_: SetOption = None,
) -> None:
    """Every combination of the file's clutches and brakes that drives the output: ratio and kind."""
    from ..transmission import Transmission, explore as _explore

    transmission = Transmission.from_file(file, overrides=set_ or ())
    note_rexs(file)
    states = _explore(transmission, include_redundant=redundant)
    check_finite(states.to_dict(), file)
    emit(_render(states, format), out)
