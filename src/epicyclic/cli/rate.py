"""``epicyclic rate FILE``: the ISO 6336 tooth load capacity of every mesh.

Needs a ``[rating]`` table (material, roughness, lubricant viscosity; see
docs/rating.md) and ``geometry`` tables with face widths.  ``--gear G`` rates in gear G of
the schedule, ``--gear all`` in every gear; ``--explain MESH`` prints the worked rating of
one mesh (``P1:sun-planet``, the gear after a second colon: ``P1:sun-planet:planet``).
Formats: table, json (``epicyclic-rating/1``), markdown, html.  A mesh below its
minimum safety is marked (``!``, red in HTML) and named on stderr.  Values outside the
standard's range of validity are warned about on stderr with the clause.  ``--rating
RATING.toml`` takes the ``[rating]`` (and ``[lubricant]``) table of a side file, over what a
REXS model's standard attributes give (a model without rating inputs is rated this way).
Inputs given but not used although they change a safety (a REXS file's crowning, ...) are
listed under the report and in the JSON's ``inputs.ignored``.
"""

from __future__ import annotations

import json
import warnings
from pathlib import Path
from typing import Annotated

import typer

from ._common import (
    FormatOption,
    OutOption,
    OutputFormat,
    SetOption,
    check_finite,
    emit,
    guarded,
    load,
    report_title,
    solved,
)

__all__ = ["rate", "rate_file"]


def _spec(train_file, file):
    from ..rating.errors import RatingError

    if train_file.rating is None:
        given = dict(getattr(train_file.exchange, "rating_inputs", None) or {})
        rexs = (f" (the REXS model gives {', '.join(k for k in given if k not in ('ignored', 'notes')) or 'none'} "
                "of them)") if train_file.exchange is not None else ""
        raise RatingError(f"{file}: the file has no [rating] table{rexs}; add one with material, flank_roughness, "
                          "root_roughness and the lubricant's viscosity_40 (see docs/rating.md), or give them in a "
                          f"side file: epicyclic rate {file} --rating RATING.toml.")
    if not train_file.geometry:
        raise RatingError(f"{file}: no element has a geometry table; the rating needs module, face width and "
                          "tooth counts (see docs/file-format.md).")
    return train_file.rating


def rate_file(train_file, file, gears, planned=None):
    """[(gear, TrainRating)] of ``train_file`` in each of ``gears`` (None: the file's operating gear).

    Parameters
    ----------
    train_file : TrainFile
        With a ``[rating]`` table and geometry.
    file : Path or str
        For messages.
    gears : list of str or None
        Gears of the schedule, or [None] for the file's own operating point.
    planned : tuple, optional
        :func:`~epicyclic.rating.train.mesh_inputs` of the file already built.

    Returns
    -------
    list of (str or None, TrainRating)

    Raises
    ------
    RatingError
        No [rating] table, no geometry, a required rating input missing.

    References
    ----------
    ISO 6336-1:2019, -2:2019, -3:2019.
    """
    from dataclasses import replace

    from ..rating.train import mesh_inputs, rate_solution

    spec = _spec(train_file, file)
    planned = planned if planned is not None else mesh_inputs(train_file.geometry, spec)
    out = []
    for gear in gears:
        current = train_file if gear is None else replace(train_file, gear=gear)
        solution = solved(current, file)
        used, plan = spec, planned
        if train_file.elastic is not None and train_file.elastic.rating:  # K_γ, K_Hβ from the elastic model
            from ..rating.elastic_factors import with_elastic_factors

            used = with_elastic_factors(spec, current.geometry, train_file.elastic, solution, train_file.elastic.rating)
            plan = mesh_inputs(current.geometry, used)
        out.append((current.gear, rate_solution(solution, current.geometry, used, gear=current.gear, planned=plan)))
    return out


def _planned(train_file, file):
    from ..rating.train import mesh_inputs

    return mesh_inputs(train_file.geometry, _spec(train_file, file))


def _explain(ratings, which: str) -> str:
    from ..rating.errors import RatingError

    parts = which.split(":")
    if len(parts) < 2:
        raise RatingError(f"--explain: expected ELEMENT:MESH[:GEAR], e.g. P1:sun-planet:planet, got {which!r}.")
    out = []
    for gear, rating in ratings:
        mesh = rating.mesh(parts[0], parts[1])
        index = 0
        if len(parts) > 2:
            names = [g.gear for g in mesh.gears]
            if parts[2] not in names:
                raise RatingError(f"--explain: mesh {parts[1]!r} has the gears {', '.join(names)}, not {parts[2]!r}.")
            index = names.index(parts[2])
        out.append((f"gear {gear}: " if gear else "") + mesh.explain(index))
    return "\n".join(out)


@guarded
def rate(
    file: Annotated[Path, typer.Argument(help="Train description (.toml) with [rating] and geometry tables.")],
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    gear: Annotated[str | None, typer.Option(
        "--gear", "-g", help="Rate in this gear of the [transmission] schedule ('all': every gear).")] = None,
    explain: Annotated[str | None, typer.Option(
        "--explain", help="Print the worked rating of one mesh: ELEMENT:MESH[:GEAR], e.g. P1:sun-planet:planet.")]
        = None,
    rating: Annotated[Path | None, typer.Option(
        "--rating", help="A TOML file whose [rating] (and [lubricant]) table gives the rating inputs, over the "
                         "model's own (a REXS model without them).")] = None,
    datasheet: Annotated[bool, typer.Option(
        "--datasheet", help="Append the manufacturing data sheet of every element (epicyclic datasheet, with the "
                            "rating's accuracy grade).")] = False,
    set_: SetOption = None,
) -> None:
    """Rate FILE's meshes by ISO 6336 Method B: safeties S_H (pitting) and S_F (tooth root) of every gear."""
    from ..rating import report

    train_file = load(file, None if gear == "all" else gear, set_)
    if rating is not None:
        from ..io.rating_format import side_rating

        train_file = side_rating(train_file, rating)
    if gear == "all":
        if train_file.transmission is None:
            from ..errors import ModelError

            raise ModelError("--gear all needs a [transmission] table with a schedule in the file.")
        gears = list(train_file.transmission.schedule)
    else:
        gears = [None]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        planned = _planned(train_file, file)
        ratings = rate_file(train_file, file, gears, planned)
        if explain:
            emit(_explain(ratings, explain), out)
            _stderr(caught, ratings)
            return
    title = report_title(train_file) if gear != "all" else (train_file.title or train_file.train.name)
    if format is OutputFormat.json:
        data = {"schema": "epicyclic-rating/1", "source": str(file), "title": title,
                "inputs": train_file.rating.to_dict(), "ratings": [r.to_dict() for _, r in ratings],
                "warnings": sorted({str(w.message) for w in caught})}
        check_finite(data, file, "rating")
        if datasheet:
            data["datasheets"] = [s.to_dict() for s in _sheets(train_file)]
        text = json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False)
    else:
        from ..rating.input_echo import echo_sections
        from ..rating.report_render import render_markdown, render_text

        echo = echo_sections(planned[0], train_file.rating)
        if format is OutputFormat.markdown:
            text = (f"# {title}\n\n*{file}*\n\n" + render_markdown(echo) + "\n"
                    + "\n".join(report.markdown_report(r) for _, r in ratings))
        elif format is OutputFormat.html:
            text = report.html_document([r for _, r in ratings], title, source=str(file), inputs=echo)
        else:
            text = "\n\n".join([render_text(echo)] + [report.text_report(r) for _, r in ratings])
    ignored = train_file.rating.ignored
    if ignored and format is not OutputFormat.json:
        lines = ["Inputs given but not used (they change a safety):", *(f"- {item}" for item in ignored)]
        if format is OutputFormat.html:
            from html import escape

            block = "<section class='ignored'><h2>" + escape(lines[0]) + "</h2><ul>" + "".join(
                f"<li>{escape(i)}</li>" for i in ignored) + "</ul></section>"
            text = text.replace("</body>", block + "</body>", 1) if "</body>" in text else text + block
        else:
            text = text.rstrip("\n") + "\n\n" + "\n".join(lines) + "\n"
    if datasheet and format is not OutputFormat.json:
        text = _with_sheets(text, _sheets(train_file), format)
    emit(text, out)
    _stderr(caught, ratings)


def _sheets(train_file):
    """The data sheet of every element with geometry, at the rating's accuracy grade and edition."""
    from ..geometry.datasheet import data_sheet

    spec = train_file.rating
    return [data_sheet(shape, name, accuracy_grade=spec.accuracy_grade, accuracy_edition=spec.accuracy_standard)
            for name, shape in train_file.geometry.items()]


def _with_sheets(text: str, sheets, format) -> str:
    if format is OutputFormat.markdown:
        return text + "\n\n" + "\n".join(s.markdown() for s in sheets)
    if format is OutputFormat.html:
        return text.replace("</body>", "".join(s._repr_html_() for s in sheets) + "</body>", 1)
    return text + "\n\n" + "\n\n".join(s.table() for s in sheets)


def _stderr(caught, ratings) -> None:
    from ..text import terminal_text

    for message in sorted({str(w.message) for w in caught}):
        typer.echo(terminal_text(f"warning: {message}"), err=True)
    for gear, rating in ratings:
        for m in rating.meshes:
            if not m.ok:
                typer.echo(terminal_text(f"below minimum safety: {m.element} {m.mesh}" + (f" in gear {gear}" if gear
                                                                                         else "")), err=True)
