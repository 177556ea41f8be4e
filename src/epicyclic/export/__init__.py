"""CAD export of gears and planetary sets: 2D DXF and SVG, 3D STEP (optional kernel).

The generated tooth profile (:mod:`epicyclic.geometry.tooth_generation`: involute and the
trochoidal root the tool leaves) becomes an outline of exact curves (:mod:`.outline`: B-splines
within a stated tolerance, 0.1 µm by default, and arcs); a set is laid out with each gear turned
to a meshing phase that assembles (:mod:`.layout`); writers: :mod:`.dxf` (ezdxf), :mod:`.svg`,
:mod:`.step` (cadquery-ocp, spur gears).  Lengths in mm.

>>> from epicyclic import PlanetarySet
>>> from epicyclic.geometry import SetGeometry
>>> from epicyclic.export import set_drawing
>>> p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78, planets=4)
>>> d = set_drawing(SetGeometry.create(p, module=2))
>>> [g.name for g in d.gears], d.max_deviation < 1e-4
(['sun', 'planet 1', 'planet 2', 'planet 3', 'planet 4', 'ring'], True)

References
----------
ISO 21771:2007; Litvin & Fuentes, *Gear Geometry and Applied Theory*, 2004; Piegl & Tiller,
*The NURBS Book*, 1997; Autodesk DXF Reference; W3C SVG 1.1; ISO 10303-214 (STEP).
"""

from .files import FORMATS, ExportResult, drawing_of, export_file
from .layout import Drawing, ExportError, gear_drawing, mesh_phases, set_drawing
from .outline import DEFAULT_TOLERANCE, GearOutline, gear_outline

__all__ = ["DEFAULT_TOLERANCE", "Drawing", "ExportError", "ExportResult", "FORMATS", "GearOutline", "drawing_of",
           "export_file", "gear_drawing", "gear_outline", "mesh_phases", "set_drawing"]
