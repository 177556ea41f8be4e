"""``epicyclic analyze FILE``: solve a train description and report it.

Formats: ``table`` (terminal), ``json`` (schema ``epicyclic-report/3``),
``markdown`` and ``html`` (one self-contained file).  Numbers are in the
file's ``[units]`` (core units 1/min, N·m, W otherwise).  Elements with a
``geometry`` table add their gears, fitting and forces (mm, N); a ``[rating]`` table
with materials adds the ISO 6336 safeties of every mesh (``epicyclic rate`` gives all factors).
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
        "--gear", "-g", help="Solve in this gear of the [transmission] schedule.")] = None,
    lang: Annotated[str, typer.Option(help="Language of the worked solution in HTML reports: en or de.")] = "en",
    set_: SetOption = None,
) -> None:
    """Solve FILE: speeds, torques, powers, losses, efficiency, self-locking, circulating power."""
    train_file = load(file, gear, set_)
    solution = solved(train_file, file)
    units, title, source = train_file.units, report_title(train_file), str(file)
    sections = _GeometrySections(train_file.geometry, solution, train_file.losses)
    rating = _rating(train_file, solution)
    if format is OutputFormat.json:
        text = json_report(solution, units, title=title, source=source, geometry=sections.json())
        if rating is not None:  # the safeties of every mesh (ISO 6336), docs/rating.md
            import json

            data = json.loads(text)
            data["rating"] = rating.to_dict()
            text = json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False) + "\n"
    elif format is OutputFormat.markdown:
        text = markdown_report(solution, units, title=title) + sections.markdown() + (
            "\n" + _report().markdown_report(rating, details=False) if rating is not None else "")
    elif format is OutputFormat.html:
        text = html_report(solution, units, title=title, source=source, description=train_file.description,
                           lang=lang, sections=sections.html() + (_report().html_section(rating) if rating else ""),
                           geometry=train_file.geometry, losses=train_file.losses, spin=train_file.spin)
    else:
        text = text_report(solution, units, title=title) + sections.text() + (
            "\n\n" + _report().text_report(rating, details=False) if rating is not None else "")
    emit(text, out)


def _report():
    from ..rating import report

    return report


def _rating(train_file, solution):
    """The rating of every mesh when the file gives materials in its [rating] table (else None)."""
    spec = train_file.rating
    if spec is None or spec.material is None or not train_file.geometry:
        return None
    from ..rating.train import rate_solution

    return rate_solution(solution, train_file.geometry, spec, gear=train_file.gear)


class _GeometrySections:
    """The geometry part of the report (fitting and forces), empty for a file without geometry tables.

    The geometry package is imported only for a file that has geometry, so that a plain file starts fast.
    """

    def __init__(self, geometry, solution, losses=None):
        self.results = None
        if geometry:
            from ..io import geometry_report

            self.report = geometry_report
            self.results = geometry_report.geometry_results(geometry, solution, losses=losses)

    def json(self):
        return self.report.geometry_dict(self.results) if self.results else None

    def markdown(self) -> str:
        return "\n" + self.report.geometry_markdown(self.results) if self.results else ""

    def html(self):
        return self.report.geometry_html(self.results) if self.results else ""

    def text(self) -> str:
        return "\n\n" + self.report.geometry_text(self.results) if self.results else ""
