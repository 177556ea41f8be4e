"""``epicyclic duty FILE``: the train over its duty cycle — energies, losses by source, bearing lives.

Solves every ``[[duty_cycle.case]]`` of the file (vectorised: one batch solve per
gear) with the file's loss models and prints, per case and for the cycle, the
energy in, out and lost by source, the cycle efficiency Σ E_out / Σ E_in, the
energy lost by element and source, and the ISO 281 rating life of every bearing
that the sets' ``bearings`` tables rate.  ``--format json`` gives every number
with its unit (an infinite life is ``null``).  Every case and every sum below its
minimum — a case's S_H or S_F below S_Hmin/S_Fmin, a damage sum D >= 1, a bearing
life below the required life (the cycle's hours, else ``[rating] life``) — is
marked ``!`` and named on stderr.  Exit codes: 0, 2 bad input, 1 internal error,
3 with ``--strict`` when something is below its minimum.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated

import typer

from ._common import (
    EXIT_BELOW_MINIMUM,
    FormatOption,
    OutOption,
    OutputFormat,
    SetOption,
    check_finite,
    emit,
    guarded,
    load,
)

__all__ = ["duty"]


@guarded
def duty(
    file: Annotated[Path, typer.Argument(help="Train description (.toml) with a [duty_cycle] table.")],
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    strict: Annotated[bool, typer.Option(
        "--strict", help="Exit with code 3 when a case or a sum is below its minimum (marked !).")] = False,
    set_: SetOption = None,
) -> None:
    """Energies per load case and over the duty cycle, losses by element and source, bearing lives (ISO 281)."""
    from ..io.duty_format import analyse_file_duty_cycle
    from ..text import terminal_text

    result = analyse_file_duty_cycle(load(file, None, set_))
    data = result.to_dict()
    check_finite(data, file)
    if format is OutputFormat.json:
        text = json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False) + "\n"
    elif format is OutputFormat.markdown:
        text = result.markdown()
    elif format is OutputFormat.html:
        text = result.html() + "\n"
    else:
        text = result.table() + "\n"
    emit(text, out)
    missed = result.shortfalls
    for shortfall in missed:
        typer.echo(terminal_text(shortfall.text()), err=True)
    if result.bearings and result.required_life is None:
        typer.echo("note: no required life (give [duty_cycle] hours or [rating] life): the bearing lives are not "
                   "checked.", err=True)
    if strict and missed:
        raise typer.Exit(EXIT_BELOW_MINIMUM)
