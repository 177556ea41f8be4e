"""``epicyclic map FILE``: an efficiency map over input speed × input torque.

``--speed 500..6000:50`` is 50 speeds from 500 to 6000 1/min (``A..B:N``, N
evenly spaced values, ends included; ``A`` alone is one value), likewise
``--torque`` in N·m.  The train file's loss tables (geometry-based mesh
friction, planet bearings, drag) give the losses; ``--gear`` picks a gear of its
``[transmission]``.  ``-o map.png`` (or ``.svg``, ``.pdf``) draws the map,
``-o map.csv`` / ``-o map.json`` writes the numbers; without ``-o`` a summary is
printed.  Exit codes: 0, 2 bad input, 1 internal error.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from ..text import short
from ._common import SetOption, emit, guarded, load, say

__all__ = ["efficiency_map", "parse_axis", "MAX_POINTS"]

#: Largest number of grid points (speed values × torque values) one map may have.
MAX_POINTS = 1_000_000


def parse_axis(text: str, name: str, unit: str):
    """``"500..6000:50"`` → 50 values from 500 to 6000; ``"1500"`` → one value.

    >>> parse_axis("10..50:5", "--torque", "N*m").tolist()
    [10.0, 20.0, 30.0, 40.0, 50.0]
    """
    import numpy as np

    from ..errors import ModelError

    raw = text.strip()
    count = None
    if ":" in raw:
        raw, _, tail = raw.partition(":")
        try:
            count = int(tail)
        except ValueError:
            raise ModelError(f"{name}: the count after ':' must be a whole number, got {short(text)} "
                             f"(e.g. 500..6000:50 for 50 values).") from None
    parts = raw.split("..")
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise ModelError(f"{name}: expected a value or a range A..B:N in {unit}, e.g. 500..6000:50, got "
                         f"{short(text)}.") from None
    if len(values) == 1:
        if count not in (None, 1):
            raise ModelError(f"{name}: a single value takes no count, got {short(text)}.")
        values, count = values * 2, 1
    if len(values) != 2 or not all(np.isfinite(values)) or values[0] <= 0 or values[1] < values[0]:
        raise ModelError(f"{name}: expected 0 < A <= B in A..B:N ({unit}), got {short(text)}.")
    count = 20 if count is None else count
    if not 1 <= count <= 10_000 or (count == 1 and values[0] != values[1]):
        raise ModelError(f"{name}: the number of values N must lie in 2..10000 for a range, got {short(text)}.")
    return np.linspace(values[0], values[1], count)


@guarded
def efficiency_map(
    file: Annotated[Path, typer.Argument(help="Train description (.toml) with loss tables, see docs/losses.md.")],
    speed: Annotated[str, typer.Option("--speed", help="Input speeds A..B:N in 1/min.")] = "500..6000:50",
    torque: Annotated[str, typer.Option("--torque", help="Input torques A..B:N in N*m.")] = "10..500:50",
    gear: Annotated[Optional[str], typer.Option("--gear", "-g", help="Gear of the \\[transmission] schedule.")] = None,
    coast: Annotated[bool, typer.Option("--coast", help="Drive from the output (engine braking).")] = False,
    out: Annotated[Optional[Path], typer.Option(
        "--out", "-o", help="Write the map: .png, .svg, .pdf (figure), .csv or .json.")] = None,
    set_: SetOption = None,
) -> None:
    """Efficiency map of FILE over input speed × torque, with the losses split by source."""
    from ..errors import ModelError
    from ..io.output import atomic_path
    from ..losses.efficiency_map import MAP_SUFFIXES, efficiency_map as compute

    speeds = parse_axis(speed, "--speed", "1/min")
    torques = parse_axis(torque, "--torque", "N*m")
    if speeds.size * torques.size > MAX_POINTS:
        raise ModelError(f"--speed/--torque: {speeds.size} × {torques.size} points exceed the limit of "
                         f"{MAX_POINTS:,}; use fewer values.")
    if out is not None and out.suffix.lower() not in MAP_SUFFIXES:
        raise ModelError(f"--out {str(out)!r}: give a file ending in {', '.join(MAP_SUFFIXES)}.")
    train_file = load(file, gear, set_)
    emap = compute(train_file, speeds, torques, direction="coast" if coast else "drive")
    note = "" if train_file.losses else (
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
