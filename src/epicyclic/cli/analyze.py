"""``epicyclic analyze FILE``: solve a train description and report it.

Formats: ``table`` (terminal), ``json`` (schema ``epicyclic-report/2``),
``markdown`` and ``html`` (one self-contained file).  Numbers are in the
file's ``[units]`` (core units 1/min, N·m, W otherwise).
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
    if format is OutputFormat.json:
        text = json_report(solution, units, title=title, source=source)
    elif format is OutputFormat.markdown:
        text = markdown_report(solution, units, title=title)
    elif format is OutputFormat.html:
        text = html_report(solution, units, title=title, source=source, description=train_file.description,
                           lang=lang)
    else:
        text = text_report(solution, units, title=title)
    emit(text, out)
