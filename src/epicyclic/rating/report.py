"""Rating reports: a summary per mesh and the full factor table per mesh (text, Markdown, HTML).

The full table follows the layout of commercial calculation reports (KISSsoft,
FVA-Workbench): one row per quantity with its name, ISO symbol, unit, the values of
gear 1 and gear 2 (one value where the quantity belongs to the mesh), whether a factor
is given or computed, and the clause of ISO 6336 it comes from; each safety has its
minimum beside it.  Symbols and units are written as ISO 6336-1 clause 4 writes them
(σ_H, K_Hβ, µm, N/mm²; the JSON keeps the ASCII keys).  A safety below its minimum is
marked: ``!`` in text and Markdown, red in HTML (class ``below``).  Values over several
load cases show as ``min … max``.

References
----------
ISO 6336-1:2019, clause 4 (symbols); KISSsoft AG, *KISSsoft calculation report of a cylindrical
gear pair* (report layout, factors with their source).
"""

from __future__ import annotations

import html

import numpy as np

from .given_factors import GIVEN
from .report_render import Section, html_page, iso_symbol, iso_unit, render_html, render_markdown, render_text

__all__ = [
    "FACTOR_HEAD",
    "SUMMARY_HEAD",
    "html_document",
    "html_section",
    "iso_symbol",
    "iso_unit",
    "markdown_report",
    "mesh_rows",
    "report_sections",
    "modes_rows",
    "summary_rows",
    "text_report",
]

SUMMARY_HEAD = ["element", "mesh", "gear", "σ_H [N/mm²]", "σ_HP [N/mm²]", "S_H", "S_Hmin", "σ_F [N/mm²]",
                "σ_FP [N/mm²]", "S_F", "S_Fmin", "ok"]
FACTOR_HEAD = ["quantity", "symbol", "unit", "gear 1", "gear 2", "given / computed", "clause"]
MODES_HEAD = ["element", "mesh", "failure mode", "safety", "value", "minimum", "method"]
_SAFETY_SUMMARY, _SAFETY_FACTORS = (5, 9), (3, 4)  # columns that may end in " !"

def _source(factor) -> str:
    """The factor's source (``given``, ``computed``, ...; :class:`~epicyclic.rating.results.Factor`)."""
    return factor.source


def _fmt(value) -> str:
    array = np.asarray(value, dtype=float)
    if array.ndim and array.size > 1:
        low, high = float(np.min(array)), float(np.max(array))
        return f"{_fmt(low)} … {_fmt(high)}"
    number = float(array.reshape(-1)[0]) if array.ndim else float(array)
    if not np.isfinite(number):
        return "unbounded"
    if number == 0 or 1e-3 <= abs(number) < 1000:
        return f"{number:.4f}".rstrip("0").rstrip(".") or "0"
    if 1000 <= abs(number) < 1e7:
        return f"{number:.1f}"
    return f"{number:.4g}"


def _below(value, minimum) -> bool:
    return bool(np.any(np.asarray(value, dtype=float) < minimum))


def summary_rows(rating) -> list[list[str]]:
    """One row per gear of every mesh: stresses, permissible stresses, safeties, ok.

    Parameters
    ----------
    rating : TrainRating

    Returns
    -------
    list of list of str
        Cells in the order of :data:`SUMMARY_HEAD`; a safety below its minimum ends in ``!``.

    References
    ----------
    ISO 6336-2:2019, eq. (4); ISO 6336-3:2019, eq. (5).
    """
    rows = []
    for m in rating.meshes:
        for g in m.gears:
            s_h = _fmt(g.S_H) + (" !" if _below(g.S_H, g.S_Hmin) else "")
            s_f = _fmt(g.S_F) + (" !" if _below(g.S_F, g.S_Fmin) else "")
            rows.append([m.element, m.mesh, g.gear, _fmt(g["sigma_H"]), _fmt(g["sigma_HP"]), s_h, _fmt(g.S_Hmin),
                         _fmt(g["sigma_F"]), _fmt(g["sigma_FP"]), s_f, _fmt(g.S_Fmin), "yes" if g.ok else "NO"])
    return rows


def modes_rows(rating) -> list[list[str]]:
    """One row per failure mode rated beyond pitting and root (micropitting ...) of every mesh.

    Parameters
    ----------
    rating : TrainRating

    Returns
    -------
    list of list of str
        Cells of :data:`MODES_HEAD`; a safety below its minimum ends in ``!``.

    References
    ----------
    ISO/TS 6336-22:2018, eq. (1) (S_λ).
    """
    return [[m.element, m.mesh, x.title, x.safety, _fmt(x.value) + ("" if x.ok else " !"), f"{x.minimum:g}",
             x.standard] for m in rating.meshes for x in m.modes]


def mesh_rows(mesh) -> list[list[str]]:
    """The full factor table of one mesh (cells of :data:`FACTOR_HEAD`).

    Parameters
    ----------
    mesh : MeshRating

    Returns
    -------
    list of list of str

    References
    ----------
    ISO 6336-1:2019, -2:2019, -3:2019 (the clauses in the last column).
    """
    rows = []
    for symbol, f in mesh.factors.items():
        rows.append([f.name, iso_symbol(symbol), iso_unit(f.unit), _fmt(f.value), "", _source(f), f.clause])
    g1, g2 = mesh.gears
    for symbol, f in g1.factors.items():
        other = g2.factors.get(symbol) or g2.factors.get({"Z_B": "Z_D"}.get(symbol, symbol))
        label = "Z_B / Z_D" if symbol == "Z_B" else iso_symbol(symbol)
        cells = [_fmt(f.value), _fmt(other.value) if other is not None else ""]
        source = _source(f) if other is None or _source(other) == _source(f) else f"{_source(f)} / {_source(other)}"
        if symbol in ("S_H", "S_F"):
            minimum = g1.S_Hmin if symbol == "S_H" else g1.S_Fmin
            cells = [c + (" !" if _below(g.factors[symbol].value, minimum) else "") for c, g in zip(cells, (g1, g2))]
        rows.append([f.name, label, iso_unit(f.unit), *cells, source, f.clause])
        if symbol in ("S_H", "S_F"):  # the minimum beside each safety
            kind = symbol + "min"
            rows.append([f"minimum {f.name}", kind, "1", _fmt(getattr(g1, kind)), _fmt(getattr(g2, kind)), GIVEN,
                         "ISO 6336-1:2019, 4 (agreed between customer and supplier)"])
    return rows


def _title(mesh) -> str:
    g1, g2 = mesh.gears
    state = "meets S_Hmin and S_Fmin" if mesh.ok else "BELOW its minimum safety"
    return (f"{mesh.element}: {mesh.mesh} ({g1.gear} / {g2.gear}{', internal' if mesh.internal else ''}) — "
            f"{mesh.standard}, method {mesh.method}: {state}")


def report_sections(rating, *, details: bool = True, inputs=()) -> list[Section]:
    """The sections of the rating report, for every format: inputs, summary, failure modes, meshes.

    Parameters
    ----------
    rating : TrainRating
    details : bool, default True
        With every mesh's factor table and its failure modes (each mesh on a new printed page).
    inputs : sequence of Section, optional
        The input echo (:func:`~epicyclic.rating.input_echo.echo_sections`), first.

    Returns
    -------
    list of Section

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    head = (f"Tooth load capacity, {rating.standard} method B" + (f", gear {rating.gear}" if rating.gear else "")
            + f", required life {rating.life_hours:g} h")
    out = list(inputs)
    out.append(Section(head, SUMMARY_HEAD, summary_rows(rating), _SAFETY_SUMMARY, level=2,
                       ok=all(m.ok for m in rating.meshes)))
    if any(m.modes for m in rating.meshes):
        out.append(Section("Failure modes beyond pitting and root", MODES_HEAD, modes_rows(rating), (4,)))
    if details:
        for m in rating.meshes:
            out.append(Section(_title(m), FACTOR_HEAD, mesh_rows(m), _SAFETY_FACTORS, tuple(m.notes), level=3,
                               page_break=True, ok=m.ok))
            out.extend(mode.section() for mode in m.modes)
    if rating.skipped:
        out.append(Section("Not rated", (), (), notes=tuple(f"{k}: {v}" for k, v in rating.skipped.items()),
                           level=3))
    return out


def text_report(rating, *, details: bool = True, inputs=()) -> str:
    """The rating as plain text: the summary and, with ``details``, every mesh's factor table.

    Parameters
    ----------
    rating : TrainRating
    details : bool, default True
    inputs : sequence of Section, optional
        The input echo, printed first.

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    return render_text(report_sections(rating, details=details, inputs=inputs))


def markdown_report(rating, *, details: bool = True, inputs=()) -> str:
    """The rating as Markdown (safeties below their minimum end in ``!``).

    Parameters
    ----------
    rating : TrainRating
    details : bool, default True
    inputs : sequence of Section, optional
        The input echo, first.

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    return render_markdown(report_sections(rating, details=details, inputs=inputs))


def html_section(rating, *, details: bool = True, inputs=()) -> str:
    """The rating as an HTML fragment (tables; safeties below their minimum in red).

    Parameters
    ----------
    rating : TrainRating
    details : bool, default True
    inputs : sequence of Section, optional
        The input echo, first.

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    return f"<section class='rating'>{render_html(report_sections(rating, details=details, inputs=inputs))}</section>"


def html_document(ratings, title: str, *, source: str = "", date: str | None = None, inputs=()) -> str:
    """A self-contained HTML document of one rating or several (one per gear) that prints to PDF cleanly.

    Parameters
    ----------
    ratings : TrainRating or sequence of TrainRating
    title : str
    source : str, optional
        The rated file, in the header of every printed page.
    date : str, optional
        ISO 8601 date of the header; default today (UTC).
    inputs : sequence of Section, optional
        The input echo, once before the ratings.

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4; W3C, *CSS Paged Media Module Level 3*.
    """
    import datetime

    ratings = [ratings] if hasattr(ratings, "meshes") else list(ratings)
    if date is None:
        date = datetime.datetime.now(datetime.timezone.utc).date().isoformat()
    body = render_html(list(inputs)) + "".join(html_section(r) for r in ratings)
    return html_page(title, body, source=source, date=date)
