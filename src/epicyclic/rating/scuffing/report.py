"""The scuffing section of a rating report: text, Markdown and HTML.

A summary row per mesh (θ_int, θ_intS, S_intS, S_SL, θ_B,max, θ_S, S_B) and, with ``details``,
every quantity of both methods with its symbol, unit and clause, in the layout of the
ISO 6336 tables (:mod:`epicyclic.rating.report`).  A safety below its minimum is marked: ``!``
in text and Markdown, red in HTML.

References
----------
ISO/TS 6336-20:2017, ISO/TS 6336-21:2017 (symbols); KISSsoft AG, calculation report of a
cylindrical gear pair, section "Scuffing load capacity" (layout).
"""

from __future__ import annotations

import html
import math

import numpy as np

from ..report import _RED, _below, _fmt, _html_rows, _md_table

__all__ = ["SCUFFING_HEAD", "detail_rows", "html_section", "markdown_section", "summary_rows", "text_section"]

SCUFFING_HEAD = ["element", "mesh", "theta_int [°C]", "theta_intS [°C]", "S_intS", "S_SL",
                 "theta_Bmax [°C]", "theta_S [°C]", "S_B", "ok"]
DETAIL_HEAD = ["quantity", "symbol", "unit", "value", "clause"]
_TITLE = "Scuffing: integral temperature and flash temperature methods"


def _cell(value) -> str:
    array = np.asarray(value, dtype=float)
    if array.size == 1 and math.isnan(float(array.reshape(-1)[0])):
        return "-"
    return _fmt(value)


def summary_rows(ratings) -> list[list[str]]:
    """One row per mesh in the order of :data:`SCUFFING_HEAD` (a safety below its minimum ends in ``!``).

    Parameters
    ----------
    ratings : sequence of ScuffingRating

    Returns
    -------
    list of list of str

    References
    ----------
    ISO/TS 6336-21:2017 (S_intS, S_SL); ISO/TS 6336-20:2017 (S_B).
    """
    rows = []
    for r in ratings:
        s_int = _cell(r.S_intS) + (" !" if _below(r.S_intS, r.S_Smin) else "")
        s_b = _cell(r.S_B) + (" !" if _below(r.S_B, r.S_Bmin) else "")
        rows.append([r.element, r.mesh, _cell(r.integral["theta_int"].value), _cell(r.integral["theta_intS"].value),
                     s_int, _cell(r.S_SL), _cell(r.flash["theta_Bmax"].value), _cell(r.flash["theta_S"].value), s_b,
                     "yes" if r.ok else "NO"])
    return rows


def detail_rows(rating) -> list[list[str]]:
    """Every quantity of both methods of one mesh (cells of the detail table).

    Parameters
    ----------
    rating : ScuffingRating

    Returns
    -------
    list of list of str

    References
    ----------
    ISO/TS 6336-20:2017; ISO/TS 6336-21:2017 (the clauses in the last column).
    """
    rows = []
    for group, minimum_of in ((rating.integral, {"S_intS": rating.S_Smin}), (rating.flash, {"S_B": rating.S_Bmin})):
        for symbol, f in group.items():
            cell = _cell(f.value)
            if symbol in minimum_of and _below(f.value, minimum_of[symbol]):
                cell += " !"
            rows.append([f.name, symbol, f.unit, cell, f.clause])
    return rows


def _mesh_title(r) -> str:
    state = "meets S_Smin and S_Bmin" if r.ok else "BELOW its minimum safety"
    return (f"{r.element}: {r.mesh} ({r.gears[0]} / {r.gears[1]}) - scuffing, {r.integral_method} and "
            f"{r.flash_method}: {state} (S_Smin {r.S_Smin:g}, S_Bmin {r.S_Bmin:g})")


def text_section(ratings, *, details: bool = True) -> str:
    """The scuffing section as plain text.

    Parameters
    ----------
    ratings : sequence of ScuffingRating
    details : bool, default True

    Returns
    -------
    str

    References
    ----------
    ISO/TS 6336-20:2017; ISO/TS 6336-21:2017.
    """
    from ...geometry._render import text_table

    parts = [text_table(SCUFFING_HEAD, summary_rows(ratings), title=_TITLE)]
    if details:
        for r in ratings:
            parts.append(text_table(DETAIL_HEAD, detail_rows(r), title=_mesh_title(r)))
            parts.append("\n".join(f"note: {n}" for n in r.notes))
    return "\n\n".join(parts)


def markdown_section(ratings, *, details: bool = True) -> str:
    """The scuffing section as Markdown.

    Parameters
    ----------
    ratings : sequence of ScuffingRating
    details : bool, default True

    Returns
    -------
    str

    References
    ----------
    ISO/TS 6336-20:2017; ISO/TS 6336-21:2017.
    """
    parts = [f"## {_TITLE}", _md_table(SCUFFING_HEAD, summary_rows(ratings))]
    if details:
        for r in ratings:
            parts += [f"### {_mesh_title(r)}", _md_table(DETAIL_HEAD, detail_rows(r))]
            parts += [f"* {n}" for n in r.notes]
    return "\n\n".join(parts) + "\n"


def html_section(ratings, *, details: bool = True) -> str:
    """The scuffing section as an HTML fragment (safeties below their minimum in red).

    Parameters
    ----------
    ratings : sequence of ScuffingRating
    details : bool, default True

    Returns
    -------
    str

    References
    ----------
    ISO/TS 6336-20:2017; ISO/TS 6336-21:2017.
    """
    esc = html.escape
    head = "".join(f"<th>{esc(h)}</th>" for h in SCUFFING_HEAD)
    parts = [f"<section class='scuffing'><h2>{esc(_TITLE)}</h2><table><thead><tr>{head}</tr></thead><tbody>"
             f"{_html_rows(summary_rows(ratings), (4, 8))}</tbody></table>"]
    if details:
        dhead = "".join(f"<th>{esc(h)}</th>" for h in DETAIL_HEAD)
        for r in ratings:
            cls = "" if r.ok else f" class='below' style='{_RED}'"
            parts.append(f"<h3{cls}>{esc(_mesh_title(r))}</h3><table><thead><tr>{dhead}</tr></thead><tbody>"
                         f"{_html_rows(detail_rows(r), (3,))}</tbody></table>")
            parts.extend(f"<p class='note'>{esc(n)}</p>" for n in r.notes)
    parts.append("</section>")
    return "".join(parts)
