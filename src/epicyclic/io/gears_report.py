"""The ``gears -f html`` report: one self-contained page per transmission, styled like ``analyze``.

Sections: the summary table of every gear (ratio, step, efficiency drive and
coast, circulating power, most loaded shift element, rolling sets) with
spread and mean step; the speed chart across gears; then per gear its detail
(every shift element's torque or slip, every set's state, rolling power and
loss, as multiples of the input) and its lever diagram.  Inline CSS and SVG,
no scripts, no links to anything outside the file.

Examples
--------
>>> from epicyclic.transmission import Transmission
>>> t = Transmission.from_file("examples/simpson_c4_3speed.toml")
>>> page = gears_html(t, t.analyze_all(), figures=False)
>>> page.startswith("<!DOCTYPE html>") and "<script" not in page and "Gear R" in page
True
"""

from __future__ import annotations

import html
from datetime import datetime, timezone
from typing import Any

from ..units import Units
from .html_report import _CSS
from ..transmission.results import efficiency_text
from .tables import html_table

__all__ = ["gears_html"]


def _figures(transmission: Any, analysis: Any, units: Units, title: str) -> tuple[str, dict[str, str], str | None]:
    """(speed chart SVG, lever SVG per gear, note) from :mod:`epicyclic.plotting`, if it can draw them."""
    try:
        from ..plotting import FigureContext, figure_svg, lever_diagram, speed_chart
    except ImportError:
        return "", {}, "figures need epicyclic.plotting, which is not available"
    try:
        context = FigureContext(title=title, units=units)
        chart = figure_svg(speed_chart(transmission, context=context).plot())
        levers = {}
        for g in analysis.gears:
            from dataclasses import replace

            diagram = lever_diagram(g.drive, transmission=transmission, gear=g.gear, context=replace(context, gear=g.gear))
            levers[g.gear] = figure_svg(diagram.plot())
        return chart, levers, None
    except Exception as exc:  # a figure must not cost the user the whole report
        return "", {}, f"figures could not be drawn ({type(exc).__name__}: {exc})"


def _num(value: float, spec: str) -> str:
    """``value`` formatted by ``spec``; a value that rounds to zero is shown as 0, never as −0."""
    text = format(value, spec)
    return format(0.0, spec.replace("+", "")) if float(text) == 0 else text


def _detail(g: Any) -> str:
    rows = []
    for name, t in g.element_torques.items():
        note = " (indeterminate split)" if name in g.indeterminate else ""
        rows.append((name, "engaged", f"{_num(t, '+.4f')} × T_in{note}", "—"))
    for name, slip in g.slip_speeds.items():
        rows.append((name, "open", "—", f"{_num(slip, '+.4f')} × n_in"))
    shift = html_table("Clutches and brakes", ("element", "state", "torque", "slip speed"), rows)
    sets = html_table("Planetary sets", ("set", "state", "rolling power", "loss"),
                      [(name, status, f"{_num(g.rolling_power[name], '+.4f')} × P_in",
                        f"{_num(g.set_losses[name], '.4f')} × P_in") for name, status in g.set_status.items()])
    coast, drive = efficiency_text(g.efficiency_coast, g.coast), efficiency_text(g.efficiency_drive, g.drive)
    kpi = [("ratio", f"{g.ratio:.4f}"), ("η drive", drive), ("η coast", coast),
           ("circulating power", "indeterminate" if g.circulating_power_ratio is None
            else f"{g.circulating_power_ratio:.3f} × P_in")]
    return ("<div class='kpi'>" + "".join(f"<div>{html.escape(k)}<b>{html.escape(v)}</b></div>" for k, v in kpi)
            + "</div>" + shift + sets)


def gears_html(transmission: Any, analysis: Any, units: Units | None = None, *, title: str | None = None,
               source: str | None = None, figures: bool = True) -> str:
    """The per-gear report of a transmission as one self-contained HTML document.

    Parameters
    ----------
    transmission : epicyclic.transmission.Transmission
    analysis : TransmissionAnalysis
        ``transmission.analyze_all()``.
    units : Units, optional
        Units of the figures (the file's ``[units]``).
    title, source : str, optional
        Heading (default: the transmission's name) and the input file.
    figures : bool, default True
        Include the speed chart and every gear's lever diagram.
    """
    units = units or Units()
    name = title or analysis.name
    esc = html.escape
    from .. import __version__

    meta = [f"epicyclic {__version__}", datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            f"input {analysis.input!r}, output {analysis.output!r}",
            "torques, slips, powers and losses as multiples of the input (drive at the input, coast at the output)"]
    if source:
        meta.insert(0, f"file: {source}")
    parts = ["<!DOCTYPE html>", "<html lang='en'><head><meta charset='utf-8'>",
             "<meta name='viewport' content='width=device-width, initial-scale=1'>",
             f"<title>{esc(name)} — epicyclic gears</title><style>{_CSS}</style></head><body>",
             f"<h1>{esc(name)}</h1>", f"<p class='meta'>{esc(' · '.join(meta))}</p>",
             "<h2>Gears</h2>", html_table("Every gear of the schedule", analysis.HEADER, analysis._rows()),
             f"<p>{esc(analysis._footer())}</p>"]
    chart, levers, note = _figures(transmission, analysis, units, name) if figures else ("", {}, None)
    if chart:
        parts += ["<h2>Speed chart</h2>", f"<figure><figcaption>Every shaft's speed and every open clutch's slip "
                                          f"per input speed, gear by gear</figcaption>{chart}</figure>"]
    elif note:
        parts.append(f"<p class='meta'>{esc(note)}.</p>")
    parts.append("<h2>Gear by gear</h2>")
    for g in analysis.gears:
        parts.append(f"<h3>Gear {esc(g.gear)} ({esc(g.kind)}): {esc(' + '.join(g.engaged) or 'nothing')} engaged</h3>")
        parts.append(_detail(g))
        if g.gear in levers:
            parts.append(f"<figure><figcaption>Lever diagram, gear {esc(g.gear)}</figcaption>{levers[g.gear]}</figure>")
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"
