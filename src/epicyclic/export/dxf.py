"""2D DXF of placed gear outlines (``ezdxf``): one layer per gear, B-splines and arcs, closed outlines.

Each gear gets its layer (``SUN``, ``PLANET_1`` …, ``RING``) with its outline: the flanks and
fillets as SPLINE entities (cubic, the control points and knots of
:class:`~epicyclic.export.outline.Spline`, so every CAD program draws the same curve) and the tip
and root runs as ARC entities, end to end; a ``CENTRES`` layer marks the gear centres and, on
layer ``PITCH``, the reference circles are drawn dashed.  Units: mm (``$INSUNITS`` = 4).

References
----------
Autodesk, *DXF Reference* (AutoCAD 2018): SPLINE, ARC, CIRCLE, LAYER, ``$INSUNITS``;
ezdxf 1.x documentation (``Modelspace.add_spline``, ``BSpline``).
"""

from __future__ import annotations

import math
import re
from pathlib import Path

from .outline import Arc

__all__ = ["dxf_document", "write_dxf", "layer_name"]

_COLOURS = {"sun": 1, "planet": 3, "ring": 5}


def layer_name(gear: str) -> str:
    """``"planet 2"`` → ``"PLANET_2"`` (DXF layer names: letters, digits, underscores).

    >>> layer_name("planet 2")
    'PLANET_2'
    """
    return re.sub(r"[^A-Za-z0-9_]+", "_", gear).strip("_").upper() or "GEAR"


def dxf_document(drawing):
    """The ezdxf document of a :class:`~epicyclic.export.layout.Drawing`.

    Parameters
    ----------
    drawing : Drawing

    Returns
    -------
    ezdxf.document.Drawing

    References
    ----------
    Autodesk DXF Reference (SPLINE, ARC); ezdxf 1.x.
    """
    import ezdxf
    from ezdxf.math import BSpline

    doc = ezdxf.new("R2010", setup=True)
    doc.header["$INSUNITS"] = 4  # mm
    msp = doc.modelspace()
    doc.layers.add("CENTRES", color=8)
    doc.layers.add("PITCH", color=8, linetype="DASHED")
    for gear in drawing.gears:
        layer = layer_name(gear.name)
        doc.layers.add(layer, color=_COLOURS.get(gear.name.split()[0], 7))
        attribs = {"layer": layer}
        for curve in gear.world_curves():
            if isinstance(curve, Arc):
                msp.add_arc(curve.centre, curve.radius, math.degrees(curve.start), math.degrees(curve.end),
                            dxfattribs=attribs)
            else:
                spline = msp.add_spline(dxfattribs=attribs)
                spline.apply_construction_tool(BSpline(curve.control_points, order=curve.degree + 1,
                                                       knots=curve.knots))
        cx, cy = gear.centre
        size = gear.reference_diameter * 0.03
        msp.add_line((cx - size, cy), (cx + size, cy), dxfattribs={"layer": "CENTRES"})
        msp.add_line((cx, cy - size), (cx, cy + size), dxfattribs={"layer": "CENTRES"})
        msp.add_circle(gear.centre, gear.reference_diameter / 2, dxfattribs={"layer": "PITCH"})
    return doc


def write_dxf(drawing, path: str | Path) -> Path:
    """Write ``drawing`` as DXF (R2010) to ``path``.

    Parameters
    ----------
    drawing : Drawing
    path : str or Path

    Returns
    -------
    Path

    References
    ----------
    Autodesk DXF Reference; ezdxf 1.x (``Drawing.saveas``).
    """
    path = Path(path)
    dxf_document(drawing).saveas(path)
    return path
