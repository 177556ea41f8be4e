"""``epicyclic analyze FILE``: solve a train description and report it.

Formats: ``table`` (terminal), ``json`` (schema ``epicyclic-report/3``),
``markdown`` and ``html`` (one self-contained file).  Numbers are in the
file's ``[units]`` (core units 1/min, N·m, W otherwise).  Elements with a
``geometry`` table add their gears, fitting and forces (mm, N).
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from ..io.html_report import html_report
from ..io.json_report import json_report
from ..io.tables import markdown_report, text_report
from ._common import FormatOption, OutOption, OutputFormat, SetOption, emit, guarded, load, report_title, solved

__all__ = ["analyze"]


@guarded
def analyze(
    file: Annotated[Path, typer.Argument(help="Train description (.toml), see docs/file-format.md.")],
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    gear: Annotated[Optional[str], typer.Option(
        "--gear", "-g", help="Solve in this gear of the \\[transmission] schedule.")] = None,
    lang: Annotated[str, typer.Option(help="Language of the worked solution in HTML reports: en or de.")] = "en",
    set_: SetOption = None,
) -> None:
    """Solve FILE: speeds, torques, powers, losses, efficiency, self-locking, circulating power."""
    train_file = load(file, gear, set_)
    solution = solved(train_file, file)
    units, title, source = train_file.units, report_title(train_file), str(file)
    sections = _geometry_sections(train_file, solution)
    if format is OutputFormat.json:
        text = json_report(solution, units, title=title, source=source, geometry=sections["json"])
    elif format is OutputFormat.markdown:
        text = markdown_report(solution, units, title=title) + sections["markdown"]
    elif format is OutputFormat.html:
        text = html_report(solution, units, title=title, source=source, description=train_file.description,
                           lang=lang, sections=sections["html"])
    else:
        text = text_report(solution, units, title=title) + sections["text"]
    emit(text, out)


def _geometry_sections(train_file, solution) -> dict:
    """Gears, fitting and forces of the elements with a geometry table, per format (empty without one; the
    geometry package is imported only then)."""
    if not train_file.geometry:
        return {"json": None, "markdown": "", "html": "", "text": ""}
    from ..io.geometry_report import geometry_dict, geometry_html, geometry_markdown, geometry_results, geometry_text

    shapes = geometry_results(train_file.geometry, solution)
    return {"json": geometry_dict(shapes), "markdown": "\n" + geometry_markdown(shapes), "html": geometry_html(shapes),
            "text": "\n\n" + geometry_text(shapes)}
