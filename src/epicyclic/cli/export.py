"""``epicyclic export FILE --format dxf|svg|step``: a planetary set (or one gear) as a CAD file.

The generated tooth profile (involute and trochoidal root of the tool) as B-splines within
``--tolerance`` and arcs; a set assembled with every gear at a meshing phase
(:mod:`epicyclic.export`).  Exit codes: 0 (warnings of the checks on stderr), 2 bad input
(pointed teeth, a set that does not assemble, STEP without its kernel), 1 internal error.
"""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ._common import guarded, say

__all__ = ["export"]


class ExportFormat(str, Enum):
    """Export formats."""

    dxf = "dxf"
    svg = "svg"
    step = "step"


@guarded
def export(
    file: Annotated[Path, typer.Argument(help="Train description (.toml or REXS) with a planetary geometry table.")],
    format: Annotated[ExportFormat, typer.Option("--format", "-f", help="CAD format.")] = ExportFormat.dxf,
    out: Annotated[Optional[Path], typer.Option("--out", "-o", help="The file to write (default FILE's name with "
                                                                    "the format's suffix, here).")] = None,
    gear: Annotated[Optional[str], typer.Option(
        "--gear", "-g", metavar="ELEMENT[:GEAR]",
        help="The set (P1) or one of its gears (P1:planet, P1:sun, P1:ring); default the file's only set.")] = None,
    phase: Annotated[float, typer.Option(help="Sun turn with the carrier held, degrees (planets and ring follow).")
                     ] = 0.0,
    tolerance: Annotated[float, typer.Option(help="Largest spline deviation from the generated profile, mm.")
                         ] = 1e-4,
    cutter_teeth: Annotated[Optional[int], typer.Option(
        help="Teeth z0 of the ring's pinion-type cutter (default the planet's).", min=8, max=400)] = None,
    face_width: Annotated[Optional[float], typer.Option(help="STEP: face width where the file gives none, mm.")
                          ] = None,
) -> None:
    """Export a planetary set or one gear as DXF, SVG or STEP (STEP needs pip install 'epicyclic[step]')."""
    import math

    from ..errors import ModelError
    from ..export import FORMATS, export_file
    from ..text import terminal_text
    from ._common import _NOTES, load

    for key, value in (("--phase", phase), ("--tolerance", tolerance), ("--face-width", face_width)):
        if value is not None and not math.isfinite(value):
            raise ModelError(f"{key}: expected a finite number, got {value!r}.")
    if not 1e-7 <= tolerance <= 0.1:
        raise ModelError(f"--tolerance: expected 1e-7 … 0.1 mm (the largest spline deviation), got {tolerance!r}.")
    if face_width is not None and face_width <= 0:
        raise ModelError(f"--face-width: expected a positive number of mm, got {face_width!r}.")
    target = out if out is not None else Path(file.stem + FORMATS[format.value])
    if target.resolve() == file.resolve():
        raise ModelError(f"--out: {target} is the input file; give another name.")
    result = export_file(load(file), target, format.value, gear, phase=phase, tolerance=tolerance,
                         cutter_teeth=cutter_teeth, face_width=face_width)
    _NOTES.extend(" ".join(terminal_text(f"warning: {w}").split()) for w in result.warnings)  # stderr, after
    say(str(result))
