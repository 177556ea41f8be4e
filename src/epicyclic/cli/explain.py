"""``epicyclic explain FILE``: the worked solution, equation by equation.

``--lang de`` gives the German terms of the sources (Steg, Sonnenrad, Hohlrad,
Standübersetzung, Wälzleistung, Kupplungsleistung, Wirkungsgrad).
"""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ._common import SetOption, emit, guarded, load, report_title, solved

__all__ = ["Language", "ExplainFormat", "explain"]


class Language(str, Enum):
    """Languages of the worked solution."""

    en = "en"
    de = "de"


class ExplainFormat(str, Enum):
    """Output formats of ``explain``."""

    text = "text"
    markdown = "markdown"


@guarded
def explain(
    file: Annotated[Path, typer.Argument(help="Train description (.toml), see docs/file-format.md.")],
    lang: Annotated[Language, typer.Option("--lang", "-l", help="Language: en or de.")] = Language.en,
    format: Annotated[ExplainFormat, typer.Option("--format", "-f", help="Output format.")] = ExplainFormat.text,
    out: Annotated[Optional[Path], typer.Option("--out", "-o", help="Write to this file instead of stdout.")] = None,
    gear: Annotated[Optional[str], typer.Option(
        "--gear", "-g", help="Solve in this gear of the [transmission] schedule.")] = None,
    set_: SetOption = None,
) -> None:
    """Show the worked solution of FILE: Willis, loss rule, torque balance, results, with numbers."""
    from ..explain import explain as worked_solution  # imported here: other commands start faster

    train_file = load(file, gear, set_)
    solution = solved(train_file, file)
    spec = train_file.transmission
    result = worked_solution(solution, train_file.units, lang=lang.value, title=report_title(train_file),
                             losses=train_file.losses, spin=train_file.spin, gear=train_file.gear,
                             input=None if spec is None else spec.input)
    emit(result.markdown() if format is ExplainFormat.markdown else result.text(), out)
