"""``epicyclic datasheet FILE``: the manufacturing data sheet of every gear with geometry.

Per gear the test dimensions with their allowances (span W_k over k teeth, dimension
over/between balls M_d, chordal thickness), per mesh the normal backlash range
(:mod:`epicyclic.geometry.datasheet`).  Lengths in mm, allowances and backlash in µm.
Exit codes: 0, 2 bad input, 1 internal error.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated, Optional

import typer

from ._common import FormatOption, OutOption, OutputFormat, SetOption, emit, guarded

__all__ = ["datasheet", "parse_per_gear"]


def parse_per_gear(values: list[str] | None, option: str) -> float | dict[str, float] | None:
    """``["0.05"]`` → 0.05 (every gear); ``["sun=0.05", "ring=0.08"]`` → per gear (mm).

    >>> parse_per_gear(["sun=0.05", "ring=0.08"], "--thickness-tolerance")
    {'sun': 0.05, 'ring': 0.08}
    """
    import math

    from ..errors import ModelError

    if not values:
        return None
    out: dict[str, float] = {}
    for text in values:
        name, _, number = text.rpartition("=")
        try:
            value = float(number)
        except ValueError:
            value = math.nan
        if not math.isfinite(value):
            raise ModelError(f"{option}: expected a number of mm or GEAR=mm (e.g. {option} sun=0.05), got {text!r:.60}.")
        if not name:
            if len(values) > 1:
                raise ModelError(f"{option}: give one number for every gear or GEAR=mm values, not both.")
            return value
        out[name.strip()] = value
    return out


@guarded
def datasheet(
    file: Annotated[Path, typer.Argument(help="Train description (.toml or REXS) with geometry tables.")],
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    thickness_tolerance: Annotated[Optional[list[str]], typer.Option(
        "--thickness-tolerance", metavar="[GEAR=]MM",
        help="Tooth-thickness tolerance T_sn (A_sni = A_sne - T_sn), mm: one for all gears or GEAR=mm (repeatable).")
    ] = None,
    pin_diameter: Annotated[Optional[list[str]], typer.Option(
        "--pin-diameter", metavar="[GEAR=]MM",
        help="Ball diameter D_M for M_d, mm (default the ball touching on d + 2 x m_n); one or GEAR=mm.")] = None,
    element: Annotated[Optional[str], typer.Option(help="Only this element (default every one with geometry).")
                       ] = None,
    accuracy_grade: Annotated[Optional[int], typer.Option(
        "--accuracy-grade", help="ISO 1328-1 accuracy grade of every gear: its flank tolerances are listed.")] = None,
    accuracy_edition: Annotated[str, typer.Option(
        "--accuracy-edition", help="ISO 1328-1 edition: 2013 (classes 1-11) or 1995 (grades 0-12).")] = "2013",
    set_: SetOption = None,
) -> None:
    """Manufacturing data sheet: W_k and k, M_d, chordal thickness with allowances per gear; backlash per mesh.

    With --accuracy-grade also each gear's ISO 1328-1 flank tolerances (f_pt, F_p, F_alpha, ..., F_r).
    """
    from ..errors import ModelError
    from ..geometry.datasheet import data_sheet
    from ._common import check_finite
    from .geometry import _load

    tolerance = parse_per_gear(thickness_tolerance, "--thickness-tolerance")
    pins = parse_per_gear(pin_diameter, "--pin-diameter")
    train_file = _load(file, None, set_)
    geometry = dict(train_file.geometry)
    if element is not None:
        if element not in geometry:
            raise ModelError(f"--element: no element {element!r:.40} with geometry; elements are "
                             f"{', '.join(repr(n) for n in geometry)}.")
        geometry = {element: geometry[element]}
    sheets = [data_sheet(shape, name, thickness_tolerance=tolerance, pin_diameter=pins,
                         accuracy_grade=accuracy_grade, accuracy_edition=accuracy_edition)
              for name, shape in geometry.items()]
    title = f"data sheet of {train_file.title or train_file.train.name}"
    data = {"title": title, "datasheets": [s.to_dict() for s in sheets]}
    check_finite(data, file, "datasheet")
    if format is OutputFormat.json:
        text = json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False) + "\n"
    elif format is OutputFormat.markdown:
        text = f"# {title}\n\n" + "\n".join(s.markdown() for s in sheets)
    elif format is OutputFormat.html:
        import html

        text = ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>" + html.escape(title)
                + f"</title></head><body><h1>{html.escape(title)}</h1>"
                + "".join(s._repr_html_() for s in sheets) + "</body></html>\n")
    else:
        text = f"{title}\n{'=' * len(title)}\n\n" + "\n\n".join(s.table() for s in sheets) + "\n"
    emit(text, out)
