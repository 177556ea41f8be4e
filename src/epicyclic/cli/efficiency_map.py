"""``epicyclic map FILE``: an efficiency map over input speed × input torque.

``--speed 500..6000:50`` is 50 speeds from 500 to 6000 (``A..B:N``, N
evenly spaced values, ends included; ``A`` alone is one value) in the file's
``[units]`` speed unit (1/min without one), likewise ``--torque``; a unit after
the range overrides it (``--speed "50..600:50 rad/s"``).  Without them the map
spans 500..6000 1/min and 10..500 N·m, 50 values each, shown in the file's
units.  The train file's loss tables (geometry-based mesh
friction, planet bearings, drag) give the losses; ``--gear`` picks a gear of its
``[transmission]``.  ``-o map.png`` (or ``.svg``, ``.pdf``) draws the map,
``-o map.csv`` / ``-o map.json`` writes the numbers; without ``-o`` a summary is
printed.  Exit codes: 0, 2 bad input, 1 internal error.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from ..limits import MAX_MAP_POINTS
from ._common import SetOption, emit, guarded, load, say

__all__ = ["efficiency_map", "parse_axis", "MAX_POINTS"]

#: Largest number of grid points (speed values × torque values) one map may have.
MAX_POINTS = MAX_MAP_POINTS


def parse_axis(text: str, name: str, unit: str):
    """``"500..6000:50"`` → 50 values from 500 to 6000 (:func:`epicyclic.io.ranges.parse_axis`, shared with
    the page).

    >>> parse_axis("10..50:5", "--torque", "N*m").tolist()
    [10.0, 20.0, 30.0, 40.0, 50.0]
    """
    from ..io.ranges import parse_axis as parse

    return parse(text, name, unit)


@guarded
def efficiency_map(
    file: Annotated[Path, typer.Argument(help="Train description (.toml) with loss tables, see docs/losses.md.")],
    speed: Annotated[Optional[str], typer.Option(
        "--speed", help="Input speeds A..B:N in the file's [units] (1/min without one), or with a unit: "
                        "'50..600:50 rad/s'. Default: 500..6000 1/min, 50 values.")] = None,
    torque: Annotated[Optional[str], typer.Option(
        "--torque", help="Input torques A..B:N in the file's [units] (N*m without one), or with a unit: "
                         "'1..50:50 kp*m'. Default: 10..500 N*m, 50 values.")] = None,
    gear: Annotated[Optional[str], typer.Option("--gear", "-g", help="Gear of the [transmission] schedule.")] = None,
    coast: Annotated[bool, typer.Option("--coast", help="Drive from the output (engine braking).")] = False,
    out: Annotated[Optional[Path], typer.Option(
        "--out", "-o", help="Write the map: .png, .svg, .pdf (figure), .csv or .json.")] = None,
    set_: SetOption = None,
) -> None:
    """Efficiency map of FILE over input speed × torque, with the losses split by source."""
    from ..errors import ModelError
    from ..io.output import atomic_path
    from ..losses.efficiency_map import MAP_SUFFIXES, efficiency_map as compute

    from ..io.ranges import map_grid

    if out is not None and out.suffix.lower() not in MAP_SUFFIXES:
        raise ModelError(f"--out {str(out)!r}: give a file ending in {', '.join(MAP_SUFFIXES)}.")
    train_file = load(file, gear, set_)
    speeds, torques = map_grid(speed, torque, units=train_file.units)  # in the file's units
    emap = compute(train_file, speeds, torques, direction="coast" if coast else "drive")
    note = "" if train_file.losses or train_file.spin is not None else (
        "note: the file has no loss tables ([planetary.losses], [gear.losses]): every efficiency comes from the "
        "typed-in stationary efficiencies and is the same at every point (see docs/losses.md).")
    if out is None:
        emit(emap.table() + ("\n" + note if note else "") + "\n", None)
        return
    if out.suffix.lower() in (".png", ".svg", ".pdf"):
        import matplotlib

        matplotlib.use("Agg")
    with atomic_path(out) as temporary:  # the map appears whole or not at all
        emap.save(temporary)
    say(f"wrote {out.resolve()}")
    if note:
        say(note)
