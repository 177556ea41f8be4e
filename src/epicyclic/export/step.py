"""3D STEP of placed gears through Open CASCADE (``cadquery-ocp``, the optional ``step`` extra).

Each gear's outline becomes one planar face bounded by exact curves — the flanks and fillets as
Geom_BSplineCurve with the poles and knots of :class:`~epicyclic.export.outline.Spline` (the
involute is a B-spline within the outline's tolerance, not a polyline), the tip and root runs as
circle arcs — and a spur gear is that face extruded by its face width along z
(BRepPrimAPI_MakePrism).  An internal spur gear is a ring: a disc of the root diameter plus a rim
of :data:`RIM_FACTOR` × m_n with the toothed outline as the hole of its face.  An external helical
gear is a loft (BRepOffsetAPI_ThruSections) through exact transverse sections turned along the
helix, φ(z) = ±2 z tan β / d (right hand; a set's planets left hand), one per 2° of twist and at least five: exact in those
sections, interpolated between them.  Helical internal gears are refused (not built yet).  The
shapes are written as one STEP AP214 file (a compound for a set).

References
----------
Open CASCADE Technology 7/8 reference: Geom_BSplineCurve, BRepBuilderAPI_MakeEdge/MakeWire/MakeFace,
BRepPrimAPI_MakePrism, BRepOffsetAPI_ThruSections, BRepCheck_Analyzer, BRepGProp (volume), STEPControl_Writer/Reader;
ISO 10303-214 (STEP AP214).
"""

from __future__ import annotations

import os
import sys
from contextlib import contextmanager
from pathlib import Path

import numpy as np

from .layout import ExportError
from .outline import Arc

__all__ = ["step_shapes", "write_step", "read_step_volume", "step_available", "RIM_FACTOR"]

#: Rim of an internal gear beyond its root circle, in normal modules.
RIM_FACTOR = 3.0


@contextmanager
def _quiet():
    """Send file descriptor 1 to /dev/null for the duration (the kernel's own printing)."""
    sys.stdout.flush()
    saved = os.dup(1)
    try:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), 1)
            yield
    finally:
        os.dup2(saved, 1)
        os.close(saved)


def step_available() -> bool:
    """Whether the CAD kernel binding (``cadquery-ocp``) is installed."""
    try:
        import OCP.BRepPrimAPI  # noqa: F401
    except ImportError:
        return False
    return True


def _kernel():
    try:
        from OCP import OCP as kernel  # the compiled module holds every package
    except ImportError:
        raise ExportError("STEP export needs the CAD kernel binding: pip install 'epicyclic[step]' "
                          "(cadquery-ocp).") from None
    return kernel


def _edge(curve, k):
    if isinstance(curve, Arc):
        axis = k.gp.gp_Ax2(k.gp.gp_Pnt(curve.centre[0], curve.centre[1], 0.0), k.gp.gp_Dir(0.0, 0.0, 1.0))
        return k.BRepBuilderAPI.BRepBuilderAPI_MakeEdge(k.gp.gp_Circ(axis, curve.radius), curve.start,
                                                       curve.end).Edge()
    poles = k.collections.Array1_gp_Pnt(1, len(curve.control_points))
    for i, (x, y) in enumerate(curve.control_points, 1):
        poles.SetValue(i, k.gp.gp_Pnt(float(x), float(y), 0.0))
    distinct, counts = np.unique(np.round(np.asarray(curve.knots, dtype=float), 14), return_counts=True)
    knots = k.collections.Array1_double(1, len(distinct))
    mults = k.collections.Array1_int(1, len(distinct))
    for i, (u, c) in enumerate(zip(distinct, counts), 1):
        knots.SetValue(i, float(u))
        mults.SetValue(i, int(c))
    spline = k.Geom.Geom_BSplineCurve(poles, knots, mults, curve.degree)
    return k.BRepBuilderAPI.BRepBuilderAPI_MakeEdge(spline).Edge()


def _wire(curves, k):
    maker = k.BRepBuilderAPI.BRepBuilderAPI_MakeWire()
    for curve in curves:
        maker.Add(_edge(curve, k))
        if not maker.IsDone():
            raise ExportError("STEP: the gear's outline does not close (an edge does not join the last one).")
    return maker.Wire()


#: Largest twist between two lofted sections of a helical gear, rad (2°).
SECTION_TWIST = 0.035


def _helical_solid(gear, width: float, helix_angle: float, k):
    """An external helical gear: a loft through exact transverse sections turned along the helix.

    The transverse section at height z is the outline turned by φ(z) = ±2 z tan β / d (right hand; the
    planets of a set left hand, as they mesh the sun);
    BRepOffsetAPI_ThruSections interpolates a smooth surface through them, one section per 2° of twist
    and at least five.
    """
    if gear.internal:
        raise ExportError(f"STEP: helical internal gears ({gear.name!r}) are not built yet; export DXF/SVG of "
                          "the transverse section instead.")
    import math

    hand = -1.0 if gear.name.startswith("planet") else 1.0  # a planet meshes the (right-hand) sun: left hand
    twist = hand * 2.0 * width * math.tan(math.radians(helix_angle)) / gear.reference_diameter
    count = max(5, int(math.ceil(abs(twist) / SECTION_TWIST)) + 1)
    loft = k.BRepOffsetAPI.BRepOffsetAPI_ThruSections(True, False, 1e-6)
    for i in range(count):
        z = width * i / (count - 1)
        section = gear.placed(gear.centre, gear.rotation + twist * i / (count - 1))
        move = k.gp.gp_Trsf()
        move.SetTranslation(k.gp.gp_Vec(0.0, 0.0, z))
        lifted = k.BRepBuilderAPI.BRepBuilderAPI_Transform(_wire(section.world_curves(), k), move, True).Shape()
        loft.AddWire(k.TopoDS.TopoDS.Wire(lifted))
    loft.CheckCompatibility(False)
    loft.Build()
    return loft.Shape()


def _solid(gear, width: float, module: float, k, helix_angle: float = 0.0):
    if helix_angle:
        solid = _helical_solid(gear, width, helix_angle, k)
        if not k.BRepCheck.BRepCheck_Analyzer(solid).IsValid():
            raise ExportError(f"STEP: the solid of {gear.name!r} is not valid (BRepCheck_Analyzer).")
        return solid
    wire = _wire(gear.world_curves(), k)
    make_face = k.BRepBuilderAPI.BRepBuilderAPI_MakeFace
    if gear.internal:  # the ring: a disc of the rim's diameter with the toothed outline as its hole
        outer = k.gp.gp_Circ(k.gp.gp_Ax2(k.gp.gp_Pnt(gear.centre[0], gear.centre[1], 0.0),
                                         k.gp.gp_Dir(0.0, 0.0, 1.0)),
                             gear.root_diameter / 2 + RIM_FACTOR * module)
        rim = k.BRepBuilderAPI.BRepBuilderAPI_MakeWire(k.BRepBuilderAPI.BRepBuilderAPI_MakeEdge(outer).Edge()).Wire()
        maker = make_face(rim)
        maker.Add(k.TopoDS.TopoDS.Wire(wire.Reversed()))  # a hole runs against the outer boundary
        face = maker.Face()
    else:
        face = make_face(wire).Face()
    solid = k.BRepPrimAPI.BRepPrimAPI_MakePrism(face, k.gp.gp_Vec(0.0, 0.0, float(width))).Shape()
    if not k.BRepCheck.BRepCheck_Analyzer(solid).IsValid():
        raise ExportError(f"STEP: the solid of {gear.name!r} is not valid (BRepCheck_Analyzer).")
    return solid


def step_shapes(drawing, module: float, helix_angle: float = 0.0, face_width: float | None = None):
    """The solids of a drawing's gears (OCP shapes), in drawing order.

    Parameters
    ----------
    drawing : Drawing
    module : float
        m_n, mm (an internal gear's rim).
    helix_angle : float, default 0
        β, degrees: external helical gears are lofted through transverse sections (right hand);
        helical internal gears are refused.
    face_width : float, optional
        b for gears without their own, mm.

    Returns
    -------
    list

    Raises
    ------
    ExportError
        No kernel, a helical internal gear, no face width, an invalid solid.

    References
    ----------
    OCCT BRepPrimAPI_MakePrism, BRepCheck_Analyzer.
    """
    k = _kernel()
    shapes = []
    for gear, width in zip(drawing.gears, drawing.face_widths or (None,) * len(drawing.gears)):
        b = width if width is not None else face_width
        if b is None:
            raise ExportError(f"STEP: {gear.name!r} has no face width; give face_width in the geometry table "
                              "(or --face-width).")
        shapes.append(_solid(gear, b, module, k, helix_angle))
    return shapes


def write_step(drawing, path: str | Path, module: float, helix_angle: float = 0.0,
               face_width: float | None = None) -> Path:
    """Write the drawing's gears as one STEP AP214 file.

    Parameters
    ----------
    drawing : Drawing
    path : str or Path
    module : float
        m_n, mm.
    helix_angle : float, default 0
    face_width : float, optional

    Returns
    -------
    Path

    References
    ----------
    ISO 10303-214; OCCT STEPControl_Writer.
    """
    k = _kernel()
    shapes = step_shapes(drawing, module, helix_angle, face_width)
    if len(shapes) == 1:
        shape = shapes[0]
    else:
        builder, shape = k.BRep.BRep_Builder(), k.TopoDS.TopoDS_Compound()
        builder.MakeCompound(shape)
        for s in shapes:
            builder.Add(shape, s)
    writer = k.STEPControl.STEPControl_Writer()
    path = Path(path)
    with _quiet():  # OCCT prints its transfer statistics on the C++ stdout
        writer.Transfer(shape, k.STEPControl.STEPControl_StepModelType.STEPControl_AsIs)
        status = writer.Write(str(path))
    if status != k.IFSelect.IFSelect_ReturnStatus.IFSelect_RetDone:
        raise ExportError(f"STEP: could not write {path}.")
    return path


def read_step_volume(path: str | Path) -> tuple[int, float, bool]:
    """Read a STEP file back: (number of solids, total volume mm³, every solid valid).

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    (int, float, bool)

    References
    ----------
    OCCT STEPControl_Reader, BRepGProp.VolumeProperties, BRepCheck_Analyzer.
    """
    k = _kernel()
    reader = k.STEPControl.STEPControl_Reader()
    with _quiet():
        status = reader.ReadFile(str(path))
        if status == k.IFSelect.IFSelect_ReturnStatus.IFSelect_RetDone:
            reader.TransferRoots()
    if status != k.IFSelect.IFSelect_ReturnStatus.IFSelect_RetDone:
        raise ExportError(f"STEP: {path} cannot be read.")
    shape = reader.OneShape()
    explorer = k.TopExp.TopExp_Explorer(shape, k.TopAbs.TopAbs_ShapeEnum.TopAbs_SOLID)
    count, volume, valid = 0, 0.0, True
    while explorer.More():
        solid = explorer.Current()
        props = k.GProp.GProp_GProps()
        k.BRepGProp.BRepGProp.VolumeProperties_s(solid, props)
        volume += props.Mass()
        valid = valid and k.BRepCheck.BRepCheck_Analyzer(solid).IsValid()
        count += 1
        explorer.Next()
    return count, volume, valid
