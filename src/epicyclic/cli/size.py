"""``epicyclic size FILE``: the smallest module, the face width and the profile shifts of a set.

Sizes one planetary set of FILE (``--element``; default the file's one simple set with tooth
counts) for the file's operating point and ``[rating]`` (material, roughness, lubricant,
life, minimum safeties): the smallest ISO 54 module between ``--min-module`` and
``--max-module`` whose set can be built — coaxiality, assembly, neighbours, undercut, tip
thickness and ε_α of ``epicyclic fit`` — and meets S_Hmin and S_Fmin in every mesh
(:func:`~epicyclic.rating.smallest_module`).  The face width is ``--face-width`` (mm) or
``--face-width-ratio`` × the sun's reference diameter (default 0.5).  ``--shifts given``
keeps the geometry table's profile shifts (default 0), ``--shifts balanced`` finds coaxial
ones with balanced specific sliding.  The search bound is printed on stderr before the search
runs.  Formats: table, json (``epicyclic-size/1``), markdown, html.  Exit codes: 0, 2 bad
input or no module that can be built and carries the load, 1 internal error.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated

import typer

from ._common import FormatOption, OutOption, OutputFormat, SetOption, check_finite, emit, guarded, load, solved

__all__ = ["size"]

#: b / d_sun where neither --face-width nor --face-width-ratio is given (the synthesis' default).
DEFAULT_FACE_WIDTH_RATIO = 0.5


def _element(train_file, name: str | None):
    from ..errors import ModelError

    sets = [e for e in train_file.train.elements if getattr(e, "teeth", None) is not None]
    if name is None:
        if len(sets) != 1:
            raise ModelError(f"--element: the file has {len(sets)} planetary sets with tooth counts "
                             f"({', '.join(repr(e.name) for e in sets) or 'none'}); name the one to size.")
        return sets[0]
    match = next((e for e in sets if e.name == name), None)
    if match is None:
        raise ModelError(f"--element: no planetary set {name!r:.40} with tooth counts; sets are "
                         f"{', '.join(repr(e.name) for e in sets) or 'none'}.")
    return match


def _geometry_inputs(train_file, element, shifts: str) -> dict:
    """The rack (and, for --shifts given, the profile shifts) of the set's geometry table."""
    shape = train_file.geometry.get(element.name)
    if shape is None:
        return {}
    rack = shape.rack
    out = {"pressure_angle": rack.pressure_angle, "helix_angle": rack.helix_angle, "addendum": rack.addendum,
           "dedendum": rack.dedendum}
    if shifts == "given":
        gears = shape.gears
        out["x_sun"], out["x_ring"] = gears["sun"].profile_shift, gears["ring"].profile_shift
        planets = [gears[n].profile_shift for n in shape.planet_gear_names]
        out["x_planet"] = planets[0] if len(planets) == 1 else planets
    return out


@guarded
def size(
    file: Annotated[Path, typer.Argument(help="Train description with a [rating] table and an operating point.")],
    element: Annotated[str | None, typer.Option("--element", "-e", help="The planetary set to size.")] = None,
    face_width: Annotated[float | None, typer.Option("--face-width", help="Face width b, mm.")] = None,
    face_width_ratio: Annotated[float | None, typer.Option(
        "--face-width-ratio", help="b / d_sun (default 0.5 without --face-width).")] = None,
    shifts: Annotated[str, typer.Option(
        "--shifts", help="'given' (the geometry table's, default 0) or 'balanced' (coaxial, balanced sliding).")]
        = "given",
    min_module: Annotated[float, typer.Option("--min-module", help="Smallest module searched, mm.")] = 0.5,
    max_module: Annotated[float, typer.Option("--max-module", help="Largest module searched, mm.")] = 50.0,
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    set_: SetOption = None,
) -> None:
    """Size a planetary set: the smallest ISO 54 module that can be built and meets S_Hmin and S_Fmin."""
    from ..rating.errors import RatingError
    from ..rating.sizing import ISO_54_MODULES, smallest_module
    from ..text import terminal_text

    if shifts not in ("given", "balanced"):
        raise RatingError(f"--shifts must be 'given' or 'balanced', got {shifts!r:.40} (default 'given').")
    if face_width is not None and face_width_ratio is not None:
        raise RatingError("--face-width and --face-width-ratio: give one of them, not both.")
    train_file = load(file, None, set_)
    if train_file.rating is None:
        raise RatingError(f"{file}: the file has no [rating] table; add one with material, flank_roughness, "
                          "root_roughness and the lubricant's viscosity_40 (see docs/rating.md).")
    target = _element(train_file, element)
    ratio = DEFAULT_FACE_WIDTH_RATIO if face_width is None and face_width_ratio is None else face_width_ratio
    series = [m for m in ISO_54_MODULES if min_module <= m <= max_module]
    width = f"b = {face_width:g} mm" if face_width is not None else f"b = {ratio:g} d_sun"
    typer.echo(terminal_text(f"size: searching {len(series)} ISO 54 modules {min_module:g} ... {max_module:g} mm for "
                             f"set {target.name!r}, {width}, profile shifts {shifts}"
                             + (" (a_w/m_n over the meshes' reference centre distances +- 0.5 x x_planet "
                                "-0.6 ... +1.2)" if shifts == "balanced" else "")), err=True)
    result = smallest_module(solved(train_file, file), target.name, train_file.rating, face_width=face_width,
                             face_width_ratio=ratio, min_module=min_module, max_module=max_module,
                             profile_shifts=shifts, **_geometry_inputs(train_file, target, shifts))
    if format is OutputFormat.json:
        data = {"schema": "epicyclic-size/1", "source": str(file), "element": target.name,
                "search": {"modules": [min_module, max_module], "series": "ISO 54", "face_width": face_width,
                           "face_width_ratio": ratio, "shifts": shifts}, **result.to_dict()}
        check_finite(data, file, "size")
        text = json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False)
    elif format is OutputFormat.markdown:
        text = f"# Sizing of {target.name}\n\n" + result.markdown()
    elif format is OutputFormat.html:
        text = ("<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>sizing</title></head><body>"
                + result._repr_html_() + "</body></html>")
    else:
        text = result.table()
    emit(text, out)
