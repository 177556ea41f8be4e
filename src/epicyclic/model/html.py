"""How a planetary set and a gear train show themselves in Jupyter (``_repr_html_``): a schematic and key figures.

The schematic of a planetary set is the front view of a simple set (sun,
planets on the carrier, ring), sized from the tooth counts where the set has
them (pitch radii ∝ z at one module) and else from the stationary ratio
(i0 = −z_ring/z_sun, Willis; the planet fills the gap), with the shaft each
member is joined to; the key figures are i0, η0 and the number of planets.
A gear train is the table of its elements (kind, shafts, ratio, efficiency,
engaged) and its shafts.  Every name is escaped.

References
----------
Willis 1841 (i0 = −z_ring/z_sun of a simple minus set); ISO 21771:2007 (pitch radius r = m·z/2).
"""

from __future__ import annotations

import html
import math
from typing import Any

__all__ = ["planetary_set_html", "train_html"]


def _radii(pset: Any) -> tuple[float, float, float]:
    """(sun, planet, ring) radii of the schematic, ring = 1."""
    teeth = getattr(pset, "teeth", None)
    z_sun, z_ring = getattr(teeth, "sun", None), getattr(teeth, "ring", None)
    if isinstance(z_sun, (int, float)) and isinstance(z_ring, (int, float)) and z_ring > z_sun > 0:
        sun = z_sun / z_ring
    else:
        ratio = abs(pset.stationary_ratio)
        sun = 1.0 / ratio if ratio > 1.05 else 0.4  # a plus set or |i0| <= 1: a schematic proportion
    return sun, (1.0 - sun) / 2.0, 1.0


def planetary_set_html(pset: Any) -> str:
    """A planetary set as HTML: an SVG front view (sun, planets, carrier, ring) and its key figures.

    Parameters
    ----------
    pset : PlanetarySet

    References
    ----------
    Willis 1841 (stationary ratio); ISO 21771:2007 (pitch radii).
    """
    sun, planet, _ = _radii(pset)
    size, scale = 160, 70.0
    centre = size / 2
    count = max(1, int(pset.planets))
    parts = [f'<circle cx="{centre}" cy="{centre}" r="{scale:.1f}" fill="none" stroke="#555" stroke-width="6"/>',
             f'<circle cx="{centre}" cy="{centre}" r="{scale * sun:.1f}" fill="#6a9fd4" stroke="#345"/>']
    orbit = scale * (sun + planet)
    for k in range(count):
        angle = 2 * math.pi * k / count - math.pi / 2
        x, y = centre + orbit * math.cos(angle), centre + orbit * math.sin(angle)
        parts.append(f'<line x1="{centre}" y1="{centre}" x2="{x:.1f}" y2="{y:.1f}" stroke="#2a8a5a" stroke-width="3"/>')
        parts.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{scale * planet * 0.95:.1f}" fill="#e8b3c8" stroke="#634"/>')
    svg = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{size}" height="{size}" viewBox="0 0 {size} {size}" '
           f'role="img" aria-label="planetary set {html.escape(pset.name)}">{"".join(parts)}</svg>')
    esc = html.escape
    teeth = getattr(pset, "teeth", None)
    rows = [("sun", esc(pset.sun)), ("ring", esc(pset.ring)), ("carrier", esc(pset.carrier)),
            ("stationary ratio i0", f"{pset.stationary_ratio:.6g}"),
            ("stationary efficiency η0", f"{pset.stationary_efficiency:.6g}"), ("planets", str(pset.planets))]
    if teeth is not None:
        rows.append(("teeth", esc(str(teeth))))
    table = "".join(f"<tr><th style='text-align:left'>{k}</th><td>{v}</td></tr>" for k, v in rows)
    return (f"<div><b>planetary set {esc(pset.name)}</b><div style='display:flex;gap:1em;align-items:center'>"
            f"{svg}<table>{table}</table></div></div>")


def _element_row(element: Any) -> tuple[str, ...]:
    kind = type(element).__name__
    shafts = ", ".join(getattr(element, "shafts", ()) or ())
    ratio = getattr(element, "stationary_ratio", getattr(element, "ratio", None))
    efficiency = getattr(element, "stationary_efficiency", getattr(element, "efficiency", None))
    engaged = getattr(element, "engaged", None)
    return (element.name, kind, shafts, "—" if ratio is None else f"{ratio:.6g}",
            "—" if efficiency is None else f"{efficiency:.6g}", "—" if engaged is None else ("yes" if engaged else "no"))


def train_html(train: Any) -> str:
    """A gear train as HTML: its elements (kind, shafts, ratio, efficiency, engaged) and its shafts.

    Parameters
    ----------
    train : GearTrain

    References
    ----------
    Brandenberger 1952 (a train of sets and stages joined by shafts).
    """
    esc = html.escape
    head = "".join(f"<th>{h}</th>" for h in ("element", "kind", "shafts", "i0 / ratio", "η0 / η", "engaged"))
    body = "".join("<tr>" + "".join(f"<td>{esc(c)}</td>" for c in _element_row(e)) + "</tr>" for e in train.elements)
    return (f"<div><b>{esc(train.name)}</b>: {len(train.elements)} elements, shafts "
            f"{esc(', '.join(train.shafts))}<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table></div>")
