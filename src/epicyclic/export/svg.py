"""SVG of placed gear outlines: each gear one closed ``<path>``, its B-splines as exact cubic Béziers.

A cubic B-spline is a chain of cubic Bézier segments (knot insertion to full multiplicity), which
SVG draws natively (``C``); the tip and root arcs become ``A`` commands.  The picture is in mm
(``viewBox`` in mm, y up as in the DXF: the group is mirrored), one ``<g>`` per gear with its name.

References
----------
W3C, *Scalable Vector Graphics (SVG) 1.1*, section 8.3 (path data: C, A, Z); Piegl & Tiller 1997,
section 5.4 (decomposition of a B-spline into Bézier segments).
"""

from __future__ import annotations

import html
import math
from pathlib import Path

from .outline import Arc

__all__ = ["svg_text", "write_svg"]

_COLOURS = {"sun": "#c0392b", "planet": "#27ae60", "ring": "#2c3e8f"}


def _path(gear) -> str:
    from ezdxf.math import BSpline

    out, first = [], True
    for curve in gear.world_curves():
        if isinstance(curve, Arc):
            pts = [(curve.centre[0] + curve.radius * math.cos(a), curve.centre[1] + curve.radius * math.sin(a))
                   for a in (curve.start, curve.end)]
            # the outline runs clockwise; arcs are stored counter-clockwise: draw from end to start
            start, end = pts[1], pts[0]
            if first:
                out.append(f"M{start[0]:.6f},{start[1]:.6f}")
                first = False
            large = 1 if curve.end - curve.start > math.pi else 0
            out.append(f"A{curve.radius:.6f},{curve.radius:.6f} 0 {large} 0 {end[0]:.6f},{end[1]:.6f}")
        else:
            spline = BSpline(curve.control_points, order=curve.degree + 1, knots=curve.knots)
            for k, bezier in enumerate(spline.bezier_decomposition()):
                p = [(v.x, v.y) for v in bezier]
                if first and k == 0:
                    out.append(f"M{p[0][0]:.6f},{p[0][1]:.6f}")
                    first = False
                out.append("C" + " ".join(f"{x:.6f},{y:.6f}" for x, y in p[1:]))
    return " ".join(out) + " Z"


def svg_text(drawing, margin: float = 5.0) -> str:
    """The SVG document of a :class:`~epicyclic.export.layout.Drawing` (mm).

    Parameters
    ----------
    drawing : Drawing
    margin : float, default 5
        Space around the gears, mm.

    Returns
    -------
    str

    References
    ----------
    W3C SVG 1.1, section 8.3.
    """
    reach = [(g.centre[0], g.centre[1], max(g.tip_diameter, g.root_diameter) / 2) for g in drawing.gears]
    x0 = min(x - r for x, _, r in reach) - margin
    x1 = max(x + r for x, _, r in reach) + margin
    y0 = min(y - r for _, y, r in reach) - margin
    y1 = max(y + r for _, y, r in reach) + margin
    width, height = x1 - x0, y1 - y0
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.3f}mm" height="{height:.3f}mm" '
             f'viewBox="{x0:.6f} {-y1:.6f} {width:.6f} {height:.6f}">',
             f"<title>{html.escape(drawing.title)}</title>", '<g transform="scale(1,-1)" fill="none" '
             'stroke-width="0.15">']
    for gear in drawing.gears:
        colour = _COLOURS.get(gear.name.split()[0], "#333333")
        parts.append(f'<g id="{html.escape(gear.name.replace(" ", "_"))}" stroke="{colour}">'
                     f'<path d="{_path(gear)}"/></g>')
    parts.append("</g></svg>")
    return "\n".join(parts) + "\n"


def write_svg(drawing, path: str | Path) -> Path:
    """Write ``drawing`` as SVG to ``path``.

    Parameters
    ----------
    drawing : Drawing
    path : str or Path

    Returns
    -------
    Path

    References
    ----------
    W3C SVG 1.1.
    """
    path = Path(path)
    path.write_text(svg_text(drawing), encoding="utf-8")
    return path
