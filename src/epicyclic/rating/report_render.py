"""One path that renders the sections of a rating report as text, Markdown and HTML.

A report is a list of :class:`Section` s — a heading, a table (head and rows of cells) and notes.
The rows are built once (:mod:`~epicyclic.rating.report`, :mod:`~epicyclic.rating.input_echo`,
:mod:`~epicyclic.rating.mode_results`); :func:`render_text`, :func:`render_markdown` and
:func:`render_html` only lay them out.  A safety cell below its minimum ends in ``" !"``: kept in
text and Markdown, red in HTML (class ``below``).  Symbols and units are written as ISO 6336-1
clause 4 and SI write them (:func:`iso_symbol`, :func:`iso_unit`, :func:`iso_text` for notes: σ_H,
K_Hβ, µm, N/mm²); the JSON of the results keeps its ASCII keys.

The HTML document (:func:`html_page`) prints cleanly: an ``@media print`` style sheet with A4
pages, a header with the file name and the date (also in the document's title, which a browser
prints at the top of every page), a page break before each mesh, table heads repeated on each page
and rows never split.

References
----------
ISO 6336-1:2019, clause 4 (symbols); ISO 80000-1:2009 (symbols of units); W3C, *CSS Paged Media
Module Level 3* and *CSS Fragmentation Module Level 3* (``@page``, ``break-before``,
``break-inside``).
"""

from __future__ import annotations

import html
import re
from collections.abc import Sequence
from dataclasses import dataclass

__all__ = ["Section", "html_page", "iso_symbol", "iso_text", "iso_unit", "render_html", "render_markdown",
           "render_text"]

_GREEK = (("epsilon", "ε"), ("lambda", "λ"), ("alpha", "α"), ("beta", "β"), ("gamma", "γ"), ("delta", "δ"),
          ("sigma", "σ"), ("theta", "ϑ"), ("rho", "ρ"), ("nu", "ν"), ("eta", "η"), ("mu", "µ"))
_UNITS = (("sqrt(N/mm^2)", "√(N/mm²)"), ("N/mm^2", "N/mm²"), ("mm*um", "mm·µm"), ("mm*µm", "mm·µm"),
          ("mm^2/s", "mm²/s"), ("degC", "°C"), ("um", "µm"))
#: A symbol in running text: one letter or a Greek letter's name, an underscore, its index.
_SYMBOL = re.compile(r"(?<![.\w])(?:[A-Za-z]|" + "|".join(w for w, _ in _GREEK) + r")_[A-Za-z0-9_]*[A-Za-z0-9*]")
_GREEK_WORD = re.compile(r"\b(" + "|".join(w for w, _ in _GREEK) + r")\b(?=[ =(])")
_MICRO = re.compile(r"(?<=[\d ])um\b|\bum(?=[ ,;)])")
_POWER = re.compile(r"(?<=m)\^([23])\b")


def iso_symbol(symbol: str) -> str:
    """An ASCII symbol of the results (``sigma_HP``, ``K_Hbeta``, ``c_gamma_alpha``) as ISO writes it.

    Parameters
    ----------
    symbol : str

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4 (symbols).

    Examples
    --------
    >>> [iso_symbol(s) for s in ("sigma_HP", "K_Hbeta", "c_gamma_alpha", "Y_deltarelT", "epsilon_alpha", "c_prime")]
    ['σ_HP', 'K_Hβ', 'c_γα', 'Y_δrelT', 'ε_α', "c'"]
    """
    if symbol == "c_prime":
        return "c'"
    for word, letter in _GREEK:
        symbol = symbol.replace(word, letter)
    base, _, rest = symbol.partition("_")
    return base + ("_" + rest.replace("_", "") if rest else "")


def iso_unit(unit: str) -> str:
    """A unit of the results (``N/mm^2``, ``um``) as SI writes it (``N/mm²``, ``µm``).

    Parameters
    ----------
    unit : str

    Returns
    -------
    str

    References
    ----------
    ISO 80000-1:2009 (symbols of units).

    Examples
    --------
    >>> iso_unit("N/mm^2"), iso_unit("N/(mm*um)"), iso_unit("um"), iso_unit("N*s/m^2")
    ('N/mm²', 'N/(mm·µm)', 'µm', 'N·s/m²')
    """
    for ascii_, si in _UNITS:
        unit = unit.replace(ascii_, si)
    return _POWER.sub(lambda m: "²³"[int(m.group(1)) - 2], unit).replace("*", "·")


def iso_text(text: str) -> str:
    """Running text (a note, a title) with its symbols and units as ISO and SI write them.

    Symbols are a letter or a Greek letter's name with an index (``sigma_H``, ``rho_fP*``,
    ``K_Hbeta``); a lone Greek name before ``=`` or a bracket (``lambda (...)``) becomes the letter;
    ``um`` after a number becomes ``µm``, ``N/mm^2`` ``N/mm²``.  A key of the input file
    (``rating.K_Hbeta``) stays as it is.

    Parameters
    ----------
    text : str

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4; ISO 80000-1:2009.

    Examples
    --------
    >>> iso_text("K_Hbeta by method C (f_Hbeta = 9.5 um), rho_fP* = 0.25, sigma_H in N/mm^2")
    'K_Hβ by method C (f_Hβ = 9.5 µm), ρ_fP* = 0.25, σ_H in N/mm²'
    """
    text = _SYMBOL.sub(lambda m: iso_symbol(m.group(0)), text)
    text = _GREEK_WORD.sub(lambda m: dict(_GREEK)[m.group(1)], text)
    text = _MICRO.sub("µm", text)
    for ascii_, si in _UNITS[:-1]:
        text = text.replace(ascii_, si)
    return _POWER.sub(lambda m: "²³"[int(m.group(1)) - 2], text)


@dataclass(frozen=True)
class Section:
    """One section of a report: a heading, a table and its notes.

    Parameters
    ----------
    title : str
        The heading (ISO symbols written by the renderers).
    head : sequence of str
        Column heads.
    rows : sequence of sequence of str
        Cells; a safety below its minimum ends in ``" !"``.
    safety_columns : tuple of int
        Columns whose ``" !"`` marks a safety below its minimum (red in HTML).
    notes : tuple of str
    level : int, default 3
        Heading level (2 report, 3 mesh, 4 failure mode).
    page_break : bool, default False
        Printed on a new page (the first section of each mesh).
    ok : bool, default True
        False: the heading is marked (red in HTML).
    literal : tuple of int, default ()
        Columns written as they are (keys of the input file); the others get ISO symbols
        (:func:`iso_text`).

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """

    title: str
    head: Sequence[str]
    rows: Sequence[Sequence[str]]
    safety_columns: tuple[int, ...] = ()
    notes: tuple[str, ...] = ()
    level: int = 3
    page_break: bool = False
    ok: bool = True
    literal: tuple[int, ...] = ()

    def cells(self) -> tuple[tuple[str, ...], ...]:
        """The rows with symbols and units written as ISO and SI write them (not the literal columns)."""
        return tuple(tuple(c if i in self.literal else iso_text(c) for i, c in enumerate(r)) for r in self.rows)

    def __post_init__(self) -> None:
        object.__setattr__(self, "head", tuple(self.head))
        object.__setattr__(self, "rows", tuple(tuple(str(c) for c in r) for r in self.rows))
        object.__setattr__(self, "notes", tuple(self.notes))
        width = len(self.head)
        for r in self.rows:
            if len(r) != width:
                raise ValueError(f"Section {self.title!r}: a row of {len(r)} cells under {width} column heads.")


def render_text(sections: Sequence[Section]) -> str:
    """The sections as fixed-width text tables, each with its notes (``note: …``).

    Parameters
    ----------
    sections : sequence of Section

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    from ..geometry._render import text_table

    parts = []
    for s in sections:
        title = iso_text(s.title)
        parts.append(text_table([iso_text(h) for h in s.head], s.cells(), title=title) if s.head else title)
        parts.extend(f"note: {iso_text(n)}" for n in s.notes)
    return "\n\n".join(parts)


def _md_table(head, rows) -> str:
    def esc(c: str) -> str:
        return c.replace("|", "\\|")
    lines = ["| " + " | ".join(esc(h) for h in head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(esc(c) for c in r) + " |" for r in rows]
    return "\n".join(lines)


def render_markdown(sections: Sequence[Section]) -> str:
    """The sections as Markdown: a heading of the section's level, a table, notes in italics.

    Parameters
    ----------
    sections : sequence of Section

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    parts = []
    for s in sections:
        parts.append("#" * s.level + " " + iso_text(s.title))
        if s.head:
            parts.append(_md_table([iso_text(h) for h in s.head], s.cells()))
        parts.extend(f"*note: {iso_text(n)}*" for n in s.notes)
    return "\n\n".join(parts) + "\n"


RED = "color:#b00020;font-weight:bold"  # inline too: the analyze report's style sheet has no .below


def _html_rows(rows, safety_columns) -> str:
    out = []
    for r in rows:
        cells = []
        for i, c in enumerate(r):
            bad = c.endswith(" !") and i in safety_columns
            text = html.escape(c[:-2] if bad else c)
            cells.append(f"<td class='below' style='{RED}'>{text}</td>" if bad else f"<td>{text}</td>")
        out.append("<tr>" + "".join(cells) + "</tr>")
    return "".join(out)


def render_html(sections: Sequence[Section]) -> str:
    """The sections as an HTML fragment (``<h2>``…``<h4>``, tables, ``<p class='note'>``).

    A section with ``page_break`` opens a ``<div class='mesh'>`` that the print style sheet starts
    on a new page; it holds the sections up to the next one that breaks.

    Parameters
    ----------
    sections : sequence of Section

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4; W3C CSS Fragmentation Module Level 3 (``break-before``).
    """
    esc = html.escape
    parts, open_div = [], False
    for s in sections:
        if s.page_break:
            parts.append("</div>" if open_div else "")
            parts.append("<div class='mesh'>")
            open_div = True
        cls = "" if s.ok else f" class='below' style='{RED}'"
        parts.append(f"<h{s.level}{cls}>{esc(iso_text(s.title))}</h{s.level}>")
        if s.head:
            head = "".join(f"<th>{esc(iso_text(h))}</th>" for h in s.head)
            parts.append(f"<table><thead><tr>{head}</tr></thead><tbody>{_html_rows(s.cells(), s.safety_columns)}"
                         "</tbody></table>")
        parts.extend(f"<p class='note'>{esc(iso_text(n))}</p>" for n in s.notes)
    if open_div:
        parts.append("</div>")
    return "".join(parts)


CSS = ("body{font-family:system-ui,'DejaVu Sans',sans-serif;margin:2em;color:#222}"
       "table{border-collapse:collapse;margin:0.6em 0 1em}"
       "td,th{border:1px solid #ccc;padding:2px 6px;font-size:90%;vertical-align:top}th{background:#f3f3f3}"
       "td:nth-child(2),td:nth-child(3),th:nth-child(2),th:nth-child(3){white-space:nowrap}"
       ".below{color:#b00020;font-weight:bold}.note{color:#555;font-size:85%;margin:0.2em 0}"
       "header.page{display:flex;justify-content:space-between;border-bottom:1px solid #999;color:#555;"
       "font-size:85%;padding-bottom:2px;margin-bottom:1em}"
       "@page{size:A4;margin:18mm 12mm 14mm 12mm}"
       "@media print{body{margin:0;font-size:8.5pt}"
       "h1{font-size:14pt;margin:0 0 0.5em}h2{font-size:12pt}h3{font-size:10.5pt}h4{font-size:9.5pt}"
       "h2,h3,h4{break-after:avoid;page-break-after:avoid}"
       "table{width:100%;table-layout:auto}td,th{font-size:7.5pt;padding:1px 3px}"
       "thead{display:table-header-group}tr,td,th{break-inside:avoid;page-break-inside:avoid}"
       "div.mesh,section.rating{break-before:page;page-break-before:always}"
       ".note{break-inside:avoid;font-size:7pt}"
       "th{background:#eee;-webkit-print-color-adjust:exact;print-color-adjust:exact}}")


def html_page(title: str, body: str, *, source: str = "", date: str = "") -> str:
    """A self-contained, printable HTML document: a header with the file name and the date, the body.

    Parameters
    ----------
    title : str
        The document's title (``<title>`` and ``<h1>``).
    body : str
        HTML of the sections (:func:`render_html`).
    source : str, optional
        The rated file (in the header of every printed page).
    date : str, optional
        The date of the report (ISO 8601).

    Returns
    -------
    str

    References
    ----------
    W3C, *CSS Paged Media Module Level 3* (``@page``); ISO 8601-1:2019 (the date).
    """
    esc = html.escape
    header = (f"<header class='page'><span>{esc(source or title)}</span><span>{esc(title)}</span>"
              f"<span>{esc(date)}</span></header>")
    heading = " — ".join(x for x in (source, date, f"{title} — rating") if x)  # a browser cuts a long title's end
    return (f"<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>{esc(heading)}</title>"
            f"<style>{CSS}</style></head><body>{header}<h1>{esc(title)}</h1>{body}</body></html>\n")
