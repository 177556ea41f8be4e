"""Export a train file's set or gear to a file: pick the element and gear, lay out, write DXF/SVG/STEP.

References
----------
See :mod:`epicyclic.export`.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from .layout import ExportError, gear_drawing, set_drawing
from .outline import DEFAULT_TOLERANCE

__all__ = ["FORMATS", "ExportResult", "drawing_of", "export_file"]

#: Output formats and their file suffixes.
FORMATS = {"dxf": ".dxf", "svg": ".svg", "step": ".step"}


@dataclass(frozen=True)
class ExportResult:
    """What was written: the file, the gears, the largest spline deviation (mm) and the checks' warnings."""

    path: Path
    format: str
    gears: tuple[str, ...]
    max_deviation: float
    warnings: tuple[str, ...] = ()

    def __str__(self) -> str:
        return (f"wrote {self.path} ({self.format.upper()}: {', '.join(self.gears)}; splines within "
                f"{self.max_deviation * 1000:.3g} um of the generated profile)")


def drawing_of(geometry_by_element, selection: str | None = None, *, phase: float = 0.0,
               tolerance: float = DEFAULT_TOLERANCE, cutter_teeth: int | None = None):
    """The drawing ``selection`` asks for: ``"P1"`` (the set), ``"P1:planet"`` (one gear) or None (the only set).

    Parameters
    ----------
    geometry_by_element : mapping element → SetGeometry
        ``TrainFile.geometry``.
    selection : str, optional
    phase : float, default 0
        Sun turn with the carrier held, degrees.
    tolerance : float, default 1e-4
        Spline tolerance, mm.
    cutter_teeth : int, optional
        z_0 of an internal gear's pinion-type cutter.

    Returns
    -------
    (Drawing, SetGeometry)

    Raises
    ------
    ExportError
        No such element or gear; a fixed-axis stage; several sets and no selection.

    References
    ----------
    See :mod:`epicyclic.export.layout`.
    """
    from ..geometry import SetGeometry

    sets = {n: g for n, g in geometry_by_element.items() if isinstance(g, SetGeometry)}
    element, _, gear = (selection or "").partition(":")
    if not element:
        if len(sets) != 1:
            raise ExportError(f"--gear: the file has {len(sets)} planetary sets with geometry"
                              + (f" ({', '.join(sets)}); name one, e.g. --gear {next(iter(sets))}" if sets else
                                 "; add a [planetary.geometry] table") + ".")
        element = next(iter(sets))
    if element not in sets:
        other = " (a fixed-axis stage: not exported yet)" if element in geometry_by_element else ""
        raise ExportError(f"--gear: no planetary set {element!r:.40} with geometry{other}; sets are "
                          f"{', '.join(sets) or 'none'}.")
    geometry = sets[element]
    if gear:
        return gear_drawing(geometry, gear, tolerance=tolerance, cutter_teeth=cutter_teeth), geometry
    return set_drawing(geometry, phase=phase, tolerance=tolerance, cutter_teeth=cutter_teeth), geometry


def export_file(train_file, out: str | Path, format: str = "dxf", selection: str | None = None, *,
                phase: float = 0.0, tolerance: float = DEFAULT_TOLERANCE, cutter_teeth: int | None = None,
                face_width: float | None = None) -> ExportResult:
    """Write a set (or one gear) of ``train_file`` as DXF, SVG or STEP.

    Parameters
    ----------
    train_file : TrainFile or str or Path
        A loaded train file, or its path.
    out : str or Path
    format : {"dxf", "svg", "step"}, default "dxf"
    selection : str, optional
        ``"P1"`` or ``"P1:planet"``.
    phase, tolerance, cutter_teeth
        As :func:`drawing_of`.
    face_width : float, optional
        STEP: face width of gears the file gives none, mm.

    Returns
    -------
    ExportResult

    Raises
    ------
    ExportError
        See :func:`drawing_of`; an unknown format; STEP without the kernel or of a helical gear.

    References
    ----------
    See :mod:`epicyclic.export`.
    """
    if format not in FORMATS:
        raise ExportError(f"--format: expected one of {', '.join(FORMATS)}, got {format!r:.20}.")
    if isinstance(train_file, (str, Path)):
        from ..io import load_train_file

        train_file = load_train_file(train_file)
    drawing, geometry = drawing_of(train_file.geometry, selection, phase=phase, tolerance=tolerance,
                                   cutter_teeth=cutter_teeth)
    out = Path(out)
    if format == "dxf":
        from .dxf import write_dxf

        write_dxf(drawing, out)
    elif format == "svg":
        from .svg import write_svg

        write_svg(drawing, out)
    else:
        from .step import write_step

        write_step(drawing, out, geometry.rack.module, geometry.rack.helix_angle, face_width)
    return ExportResult(out, format, tuple(g.name for g in drawing.gears), drawing.max_deviation, drawing.warnings)
