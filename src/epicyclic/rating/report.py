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

__all__ = [
    "FACTOR_HEAD",
    "SUMMARY_HEAD",
    "html_document",
    "html_section",
    "iso_symbol",
    "iso_unit",
    "markdown_report",
    "mesh_rows",
    "summary_rows",
    "text_report",
]

SUMMARY_HEAD = ["element", "mesh", "gear", "σ_H [N/mm²]", "σ_HP [N/mm²]", "S_H", "S_Hmin", "σ_F [N/mm²]",
                "σ_FP [N/mm²]", "S_F", "S_Fmin", "ok"]
FACTOR_HEAD = ["quantity", "symbol", "unit", "gear 1", "gear 2", "given / computed", "clause"]
_SAFETY_SUMMARY, _SAFETY_FACTORS = (5, 9), (3, 4)  # columns that may end in " !"

_GREEK = (("epsilon", "ε"), ("lambda", "λ"), ("alpha", "α"), ("beta", "β"), ("gamma", "γ"), ("delta", "δ"),
          ("sigma", "σ"), ("theta", "ϑ"), ("rho", "ρ"), ("nu", "ν"), ("eta", "η"), ("mu", "µ"))
_UNITS = (("sqrt(N/mm^2)", "√(N/mm²)"), ("N/mm^2", "N/mm²"), ("mm*um", "mm·µm"), ("mm*µm", "mm·µm"),
          ("mm^2/s", "mm²/s"), ("um", "µm"))


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


def _source(factor) -> str:
    """The factor's source (``given``, ``computed``, ...; :class:`~epicyclic.rating.results.Factor`)."""
    return factor.source


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
    >>> iso_unit("N/mm^2"), iso_unit("N/(mm*um)"), iso_unit("um")
    ('N/mm²', 'N/(mm·µm)', 'µm')
    """
    for ascii_, si in _UNITS:
        unit = unit.replace(ascii_, si)
    return unit


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


def text_report(rating, *, details: bool = True) -> str:
    """The rating as plain text: the summary and, with ``details``, every mesh's factor table.

    Parameters
    ----------
    rating : TrainRating
    details : bool, default True

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    from ..geometry._render import text_table

    head = (f"Tooth load capacity, {rating.standard} method B"
            + (f", gear {rating.gear}" if rating.gear else "") + f", required life {rating.life_hours:g} h")
    parts = [text_table(SUMMARY_HEAD, summary_rows(rating), title=head)]
    if details:
        for m in rating.meshes:
            parts.append(text_table(FACTOR_HEAD, mesh_rows(m), title=_title(m)))
            parts.extend(f"note: {n}" for n in m.notes)
    parts.extend(f"not rated: {k}: {v}" for k, v in rating.skipped.items())
    return "\n\n".join(parts)


def _md_table(head, rows) -> str:
    def esc(c: str) -> str:
        return c.replace("|", "\\|")
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(esc(c) for c in r) + " |" for r in rows]
    return "\n".join(lines)


def markdown_report(rating, *, details: bool = True) -> str:
    """The rating as Markdown (safeties below their minimum end in ``!``).

    Parameters
    ----------
    rating : TrainRating
    details : bool, default True

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    parts = [f"## Tooth load capacity ({rating.standard}, method B"
             + (f", gear {rating.gear}" if rating.gear else "") + f", life {rating.life_hours:g} h)",
             _md_table(SUMMARY_HEAD, summary_rows(rating))]
    if details:
        for m in rating.meshes:
            parts += [f"### {_title(m)}", _md_table(FACTOR_HEAD, mesh_rows(m))]
    return "\n\n".join(parts) + "\n"


def _html_rows(rows, safety_columns) -> str:
    out = []
    for r in rows:
        cells = []
        for i, c in enumerate(r):
            bad = c.endswith(" !") and i in safety_columns
            text = html.escape(c[:-2] if bad else c)
            cells.append(f"<td class='below' style='{_RED}'>{text}</td>" if bad else f"<td>{text}</td>")
        out.append("<tr>" + "".join(cells) + "</tr>")
    return "".join(out)


def html_section(rating, *, details: bool = True) -> str:
    """The rating as an HTML fragment (tables; safeties below their minimum in red).

    Parameters
    ----------
    rating : TrainRating
    details : bool, default True

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    esc = html.escape
    head = "".join(f"<th>{esc(h)}</th>" for h in SUMMARY_HEAD)
    parts = [f"<section class='rating'><h2>Tooth load capacity — {esc(rating.standard)}, method B"
             + (f", gear {esc(rating.gear)}" if rating.gear else "") + f", life {rating.life_hours:g} h</h2>",
             f"<table><thead><tr>{head}</tr></thead><tbody>{_html_rows(summary_rows(rating), _SAFETY_SUMMARY)}"
             "</tbody></table>"]
    if details:
        fhead = "".join(f"<th>{esc(h)}</th>" for h in FACTOR_HEAD)
        for m in rating.meshes:
            cls = "" if m.ok else f" class='below' style='{_RED}'"
            parts.append(f"<h3{cls}>{esc(_title(m))}</h3><table><thead><tr>{fhead}</tr></thead><tbody>"
                         f"{_html_rows(mesh_rows(m), _SAFETY_FACTORS)}</tbody></table>")
            parts.extend(f"<p class='note'>{esc(n)}</p>" for n in m.notes)
    parts.append("</section>")
    return "".join(parts)


_RED = "color:#b00020;font-weight:bold"  # inline too: the analyze report's style sheet has no .below
_CSS = ("body{font-family:system-ui,sans-serif;margin:2em;color:#222}table{border-collapse:collapse;margin:1em 0}"
        "td,th{border:1px solid #ccc;padding:2px 6px;font-size:90%}th{background:#f3f3f3}"
        ".below{color:#b00020;font-weight:bold}.note{color:#555;font-size:90%}")


def html_document(rating, title: str) -> str:
    """A self-contained HTML document of the rating.

    Parameters
    ----------
    rating : TrainRating
    title : str

    Returns
    -------
    str

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    esc = html.escape
    return (f"<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>{esc(title)} — rating</title>"
            f"<style>{_CSS}</style></head><body><h1>{esc(title)}</h1>{html_section(rating)}</body></html>\n")
