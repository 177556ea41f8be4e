"""The load-capacity rating as the page shows it: the rows of :mod:`epicyclic.rating.report`, typeset.

The command line's report (``epicyclic rate``) writes symbols and units in ASCII
(``sigma_H``, ``N/mm^2``) so that a terminal and a CSV reader show them; the page
writes them as a calculation report does (σ_H, N/mm²), its words left-aligned and
its numbers right-aligned, and names the two wheels of a mesh by their members
(sun, planet, ring), so that "gear 1/2" of a mesh is not read as a gear of the
transmission.  The cells are the report's (:func:`~epicyclic.rating.report.summary_rows`,
:func:`~epicyclic.rating.report.mesh_rows`): the page and the command show the same numbers.

References
----------
ISO 6336-1:2019, clause 4 (symbols: σ_H, σ_F, Z_ε, Y_β …); ISO 80000-1:2009 (units written N/mm²).

Examples
--------
>>> symbol("sigma_HP"), symbol("epsilon_alpha"), symbol("K_Hbeta"), unit("sqrt(N/mm^2)")
('σ_HP', 'ε_α', 'K_Hβ', '√(N/mm²)')
"""

from __future__ import annotations

import html
import re

__all__ = ["symbol", "unit", "rating_html"]

_GREEK = {"alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "rho": "ρ", "sigma": "σ"}
_WORD = re.compile(r"(?<![a-z])(" + "|".join(_GREEK) + r")")
#: Columns of the summary (the report's :data:`~epicyclic.rating.report.SUMMARY_HEAD`, typeset).
SUMMARY_HEAD = ("element", "mesh", "wheel", "σ_H [N/mm²]", "σ_HP [N/mm²]", "S_H", "σ_F [N/mm²]", "σ_FP [N/mm²]",
                "S_F", "ok")
_TEXT_SUMMARY = (0, 1, 2)  # columns of words (left-aligned)
_TEXT_FACTORS = (0, 1, 2, 5)
_RED = "color:#b00020;font-weight:bold"


def symbol(text: str) -> str:
    """An ISO 6336 symbol of the report (``sigma_HP``) with its Greek letters (``σ_HP``)."""
    return _WORD.sub(lambda m: _GREEK[m.group(1)], text)


def unit(text: str) -> str:
    """A unit of the report (``N/mm^2``, ``N/(mm*um)``) as it is printed (``N/mm²``, ``N/(mm·µm)``)."""
    text = text.replace("^2", "²").replace("^3", "³").replace("*", "·").replace("sqrt", "√")
    return re.sub(r"(?<![A-Za-z])um(?![A-Za-z])", "µm", text)


def _rows(rows: list[list[str]], text_columns: tuple[int, ...], safety_columns: tuple[int, ...],
          typeset: dict[int, object]) -> str:
    out = []
    for row in rows:
        cells = []
        for i, cell in enumerate(row):
            below = cell.endswith(" !") and i in safety_columns
            value = cell[:-2] if below else cell
            value = typeset[i](value) if i in typeset else value
            attributes = " class='text'" if i in text_columns else ""
            if below:
                attributes = f" class='below' style='{_RED}'"
            cells.append(f"<td{attributes}>{html.escape(value)}</td>")
        out.append("<tr>" + "".join(cells) + "</tr>")
    return "".join(out)


def _head(columns) -> str:
    return "".join(f"<th>{html.escape(c)}</th>" for c in columns)


def rating_html(rating) -> str:
    """The rating of every mesh as the page's HTML: the summary, then each mesh's factor table.

    Parameters
    ----------
    rating : epicyclic.rating.train.TrainRating

    Returns
    -------
    str
        An HTML fragment (every text escaped); a safety below its minimum in red (class ``below``).

    References
    ----------
    ISO 6336-2:2019, eq. (4); ISO 6336-3:2019, eq. (5) (the safeties).
    """
    from ..rating.report import mesh_rows, summary_rows

    gear = f", transmission gear {html.escape(str(rating.gear))}" if rating.gear else ""
    parts = [f"<section class='rating'><h2>Tooth load capacity — {html.escape(rating.standard)}, method B{gear}, "
             f"life {rating.life_hours:g} h</h2>",
             f"<table class='rating-summary'><thead><tr>{_head(SUMMARY_HEAD)}</tr></thead><tbody>"
             f"{_rows(summary_rows(rating), _TEXT_SUMMARY, (5, 8), {})}</tbody></table>"]
    for mesh in rating.meshes:
        first, second = (g.gear for g in mesh.gears)
        state = "meets S_Hmin and S_Fmin" if mesh.ok else "BELOW its minimum safety"
        title = (f"{mesh.element}: mesh {mesh.mesh} ({first} with {second}"
                 f"{', internal' if mesh.internal else ''}) — {mesh.standard}, method {mesh.method}: {state}")
        css = "" if mesh.ok else f" class='below' style='{_RED}'"
        head = _head(("quantity", "symbol", "unit", first, second, "clause"))
        names = {0: lambda q: q.replace("gear 1", f"the {first}").replace("gear 2", f"the {second}"),
                 1: symbol, 2: unit}
        parts.append(f"<h3{css}>{html.escape(title)}</h3><table class='rating-factors'><thead><tr>{head}</tr>"
                     f"</thead><tbody>{_rows(mesh_rows(mesh), _TEXT_FACTORS, (3, 4), names)}"
                     "</tbody></table>")
        parts.extend(f"<p class='note'>{html.escape(note)}</p>" for note in mesh.notes)
    parts.extend(f"<p class='note'>not rated: {html.escape(str(k))}: {html.escape(str(v))}</p>"
                 for k, v in rating.skipped.items())
    parts.append("</section>")
    return "".join(parts)
