"""A single, self-contained HTML report that opens offline.

One file: inline CSS, no scripts, no links to anything outside it.  It holds
the summary (efficiency, powers, self-locking, circulating power, warnings),
the shaft and element tables in the user's units, the diagrams of
:func:`epicyclic.plotting.report_figures` (inline SVG) when that module is
installed, and the worked solution of :func:`epicyclic.explain.explain`.

Examples
--------
>>> from epicyclic.demo import brandenberger_1952
>>> from epicyclic import solve
>>> page = html_report(solve(*brandenberger_1952()), figures=False)
>>> page.startswith("<!DOCTYPE html>") and "<link" not in page and "<script" not in page
True
"""

from __future__ import annotations

import html
from typing import Any
from datetime import datetime, timezone

from ..results.solution import Solution
from ..units import Units
from .tables import report_tables, summary_lines

__all__ = ["html_report", "report_figures"]

_CSS = """
body{font-family:system-ui,-apple-system,"Segoe UI",Helvetica,Arial,sans-serif;margin:2rem auto;max-width:72rem;
padding:0 1rem;color:#1d2330;line-height:1.45}
h1{font-size:1.6rem;margin-bottom:.2rem}h2{font-size:1.2rem;margin-top:2rem;border-bottom:1px solid #d0d5de}
h3{font-size:1rem;margin-bottom:.3rem}.meta{color:#5a6272;font-size:.9rem}
table{border-collapse:collapse;margin:.6rem 0 1.2rem;font-size:.92rem}
caption{text-align:left;font-weight:600;padding:.3rem 0}
th,td{border:1px solid #d0d5de;padding:.3rem .6rem}th{background:#eef1f6;text-align:left}
td{text-align:right;font-variant-numeric:tabular-nums}td:first-child{text-align:left}
.kpi{display:flex;flex-wrap:wrap;gap:1rem;margin:1rem 0}
.kpi div{border:1px solid #d0d5de;border-radius:6px;padding:.6rem 1rem;min-width:10rem}
.kpi b{display:block;font-size:1.3rem}.lock{background:#fdecec;border:1px solid #e0a0a0;padding:.8rem;
border-radius:6px}.warn{background:#fff7e0;border:1px solid #e6cf8b;padding:.5rem .8rem;border-radius:6px}
pre{background:#f6f8fa;padding:.8rem;overflow-x:auto;font-size:.85rem}figure{margin:1rem 0}
figcaption{font-weight:600;margin-bottom:.3rem}svg{max-width:100%;height:auto}
"""


def report_figures(solution: Solution, units: Units | None = None, title: str | None = None,
                   geometry: Any = None) -> tuple[list[tuple[str, str]], str | None]:
    """Diagrams from :mod:`epicyclic.plotting` if available.

    Returns
    -------
    figures : list of (title, inline SVG text)
    note : str or None
        Why there are no diagrams, if there are none.
    """
    try:
        from ..plotting import report_figures as make_figures
    except ImportError:
        return [], "diagrams need epicyclic.plotting.report_figures, which is not available"
    try:
        return list(make_figures(solution, units=units, title=title, geometry=geometry)), None
    except Exception as exc:  # a diagram must not cost the user the whole report
        return [], f"diagrams could not be drawn ({type(exc).__name__}: {exc})"


def html_report(
    solution: Solution,
    units: Units | None = None,
    *,
    title: str | None = None,
    source: str | None = None,
    description: str = "",
    figures: bool = True,
    explanation: bool = True,
    lang: str = "en",
    sections: str = "",
    geometry: Any = None,
    losses: Any = None,
    spin: Any = None,
) -> str:
    """The report as one self-contained HTML document.

    Parameters
    ----------
    solution : Solution
    units : Units, optional
        Units of the tables (core units by default).
    title, source, description : str, optional
        Heading (default: the train's name), input file and a free text.
    figures : bool, default True
        Include the diagrams of :mod:`epicyclic.plotting` when available.
    explanation : bool, default True
        Include the worked solution.
    lang : {"en", "de"}
        Language of the worked solution.
    sections : str, optional
        Further HTML (escaped, self-contained) placed after the tables, e.g. the
        geometry, fitting and forces of :mod:`epicyclic.io.geometry_report`.
    geometry : mapping set name → SetGeometry, optional
        The file's gear geometry (``TrainFile.geometry``): the speed plan draws
        those sets at their operating pitch radii.
    losses, spin : optional
        The file's loss models (``TrainFile.losses``, ``TrainFile.spin``): the worked solution writes
        out η0 at the point, μ and H_V per mesh and every loss source.

    Returns
    -------
    str
        ``<!DOCTYPE html>`` … ``</html>``, UTF-8 text without external resources.
    """
    units = units or Units()
    name = title or solution.train.name
    esc = html.escape
    shafts, elements = report_tables(solution, units)
    summary = summary_lines(solution, units)
    values = dict(summary)

    parts = [
        "<!DOCTYPE html>",
        "<html lang='en'><head><meta charset='utf-8'>",
        "<meta name='viewport' content='width=device-width, initial-scale=1'>",
        f"<title>{esc(name)} — epicyclic report</title><style>{_CSS}</style></head><body>",
        f"<h1>{esc(name)}</h1>",
    ]
    from .. import __version__

    meta = [f"epicyclic {__version__}", datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            f"units: speed {units.speed}, torque {units.torque}, power {units.power}"]
    if source:
        meta.insert(0, f"file: {source}")
    parts.append(f"<p class='meta'>{esc(' · '.join(meta))}</p>")
    if description:
        parts.append(f"<p>{esc(description)}</p>")

    kpis = [("efficiency", values.get("efficiency", "—")), ("input power", values["input power"]),
            ("output power", values["output power"]), ("total loss", values["total loss"]),
            ("circulating power", values["circulating power"])]
    parts.append("<div class='kpi'>" + "".join(f"<div>{esc(k)}<b>{esc(v)}</b></div>" for k, v in kpis) + "</div>")
    if solution.self_locking is not None:
        parts.append(f"<p class='lock'><strong>Self-locking.</strong> {esc(solution.self_locking.message)}</p>")
    for warning in solution.warnings:
        parts.append(f"<p class='warn'>Warning: {esc(warning)}</p>")

    parts.append("<h2>Shafts and elements</h2>")
    parts.append(shafts.html())
    parts.append(elements.html())
    parts.append("<table><caption>Summary</caption><tbody>" + "".join(
        f"<tr><th>{esc(k)}</th><td>{esc(v)}</td></tr>" for k, v in summary) + "</tbody></table>")
    if sections:
        parts.append(sections)

    if figures:
        found, note = report_figures(solution, units, name, geometry)
        if found:
            parts.append("<h2>Diagrams</h2>")
            for caption, svg in found:
                parts.append(f"<figure><figcaption>{esc(caption)}</figcaption>{svg}</figure>")
        elif note:
            parts.append(f"<p class='meta'>{esc(note)}.</p>")

    if explanation:
        from ..explain import explain

        parts.append("<h2>Worked solution</h2>")
        parts.append(explain(solution, units, lang=lang, title=name, losses=losses, spin=spin).html())
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"
