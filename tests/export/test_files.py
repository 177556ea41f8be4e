"""Exported files read back by independent readers (issue 31): DXF by ezdxf, SVG as XML, STEP by the CAD kernel."""

from __future__ import annotations

import math
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from epicyclic.export import ExportError, export_file, gear_drawing, set_drawing
from epicyclic.export.dxf import write_dxf
from epicyclic.export.svg import svg_text

from .test_layout import industrial

ROOT = Path(__file__).resolve().parents[2]
INDUSTRIAL = """title = "industrial stage 20/37/97"
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
teeth = { sun = 20, planet = 37, ring = 97 }
planets = 3
[planetary.geometry]
module = 3
profile_shift = { sun = 0.6, planet = 0.3, ring = 0.3173 }
center_distance = 87.96
thickness_allowance = -0.06
face_width = 30
[[brake]]
name = "B"
shaft = "ring"
"""


def _chains(entities) -> list[list]:
    """Group curve end points into chains; each closed chain is one closed outline (tolerance 1e-6 mm)."""
    ends = []
    for e in entities:
        if e.dxftype() == "ARC":
            ends.append((np.array(e.start_point)[:2], np.array(e.end_point)[:2]))
        elif e.dxftype() == "SPLINE":
            pts = np.array(e.control_points)[:, :2]
            ends.append((pts[0], pts[-1]))
    points = np.array([p for pair in ends for p in pair])
    # every end point meets exactly one other end point: the outlines are closed
    from scipy.spatial import cKDTree

    tree = cKDTree(points)
    counts = [len(tree.query_ball_point(p, 1e-6)) for p in points]
    return counts


def test_dxf_reads_back_with_closed_outlines_and_the_right_extents(tmp_path):
    import ezdxf
    from ezdxf import bbox

    drawing = set_drawing(industrial())
    path = write_dxf(drawing, tmp_path / "set.dxf")
    doc = ezdxf.readfile(path)
    assert doc.header["$INSUNITS"] == 4
    msp = doc.modelspace()
    layers = {e.dxf.layer for e in msp}
    assert {"SUN", "PLANET_1", "PLANET_2", "PLANET_3", "RING", "CENTRES", "PITCH"} <= layers
    for gear in drawing.gears:
        layer = gear.name.replace(" ", "_").upper()
        curves = [e for e in msp.query(f'*[layer=="{layer}"]')]
        assert {e.dxftype() for e in curves} == {"SPLINE", "ARC"}
        assert len(curves) == len(gear.curves)
        assert set(_chains(curves)) == {2}  # each end meets one other end: closed
        box = bbox.extents(curves)
        reach = max(gear.tip_diameter, gear.root_diameter) / 2
        assert box.extmax.x == pytest.approx(gear.centre[0] + reach, abs=0.05)
        assert box.extmin.y == pytest.approx(gear.centre[1] - reach, abs=0.05)
    overall = bbox.extents(msp)
    assert overall.extmax.x == pytest.approx(industrial().gears["ring"].root_diameter / 2, abs=0.05)


def test_dxf_renders(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import ezdxf
    from ezdxf.addons.drawing import matplotlib as dxf_matplotlib

    path = write_dxf(gear_drawing(industrial(), "sun"), tmp_path / "sun.dxf")
    dxf_matplotlib.qsave(ezdxf.readfile(path).modelspace(), str(tmp_path / "sun.png"), dpi=40)
    assert (tmp_path / "sun.png").stat().st_size > 1000


def test_svg_is_one_closed_path_per_gear():
    drawing = set_drawing(industrial())
    root = ET.fromstring(svg_text(drawing))
    paths = root.findall(".//{http://www.w3.org/2000/svg}path")
    assert len(paths) == len(drawing.gears)
    for path, gear in zip(paths, drawing.gears):
        d = path.get("d")
        assert d.startswith("M") and d.endswith("Z")
        splines = sum(1 for c in gear.curves if c.__class__.__name__ == "Spline")
        assert d.count("A") == len(gear.curves) - splines and d.count("C") >= splines


def test_export_file_and_bad_selection(tmp_path):
    source = tmp_path / "set.toml"
    source.write_text(INDUSTRIAL, encoding="utf-8")
    result = export_file(source, tmp_path / "planet.svg", "svg", "P:planet")
    assert result.gears == ("planet",) and result.max_deviation <= 1e-4
    with pytest.raises(ExportError, match="no gear 'moon'"):
        export_file(source, tmp_path / "x.dxf", "dxf", "P:moon")
    with pytest.raises(ExportError, match="no planetary set 'Q'"):
        export_file(source, tmp_path / "x.dxf", "dxf", "Q")
    with pytest.raises(ExportError, match="--format"):
        export_file(source, tmp_path / "x.dwg", "dwg")


def test_cli_export(tmp_path):
    source = tmp_path / "set.toml"
    source.write_text(INDUSTRIAL, encoding="utf-8")
    run = [sys.executable, "-m", "epicyclic", "export", str(source)]
    done = subprocess.run(run + ["--format", "dxf", "--out", str(tmp_path / "s.dxf")], capture_output=True, text=True,
                          cwd=ROOT, timeout=300)
    assert done.returncode == 0, done.stderr
    assert "wrote" in done.stdout and (tmp_path / "s.dxf").exists()
    bad = subprocess.run(run + ["--gear", "P:moon"], capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert bad.returncode == 2 and "no gear 'moon'" in bad.stderr and "Traceback" not in bad.stderr


def test_step_is_a_valid_solid_of_the_outline_area_times_the_face_width(tmp_path):
    pytest.importorskip("OCP", reason="STEP needs the optional [step] extra (cadquery-ocp)")
    from epicyclic.export.step import read_step_volume, write_step

    for name in ("sun", "ring"):
        drawing = gear_drawing(industrial(), name)
        path = write_step(drawing, tmp_path / f"{name}.step", 3.0)
        count, volume, valid = read_step_volume(path)
        gear = drawing.gears[0]
        x, y = gear.dense_polygon(0.002).T
        area = 0.5 * abs(np.dot(x, np.roll(y, 1)) - np.dot(y, np.roll(x, 1)))  # shoelace of the outline
        if gear.internal:
            area = math.pi * (gear.root_diameter / 2 + 3 * 3.0) ** 2 - area
        assert (count, valid) == (1, True)
        # the kernel integrates over the B-spline faces by Gauss points: agreement to 1e-5 of the volume
        assert volume == pytest.approx(area * 30.0, rel=1e-5)


def test_helical_step_is_a_valid_solid_whose_volume_is_area_times_width(tmp_path):
    # a twisted extrusion keeps the transverse area: V = A b exactly (Cavalieri)
    pytest.importorskip("OCP", reason="STEP needs the optional [step] extra (cadquery-ocp)")
    import time

    from epicyclic.export.outline import gear_outline
    from epicyclic.export.layout import Drawing
    from epicyclic.export.step import read_step_volume, write_step
    from epicyclic.geometry.gear import BasicRack, GearGeometry
    from epicyclic.geometry.tooth_generation import generate_profile

    gear = GearGeometry(19, BasicRack(2.0, helix_angle=15.0), 0.3)
    outline = gear_outline(generate_profile(gear), "pinion")
    start = time.perf_counter()
    path = write_step(Drawing("helical", (outline,), (), (20.0,)), tmp_path / "helical.step", 2.0, 15.0)
    elapsed = time.perf_counter() - start
    count, volume, valid = read_step_volume(path)
    x, y = outline.dense_polygon(0.002).T
    area = 0.5 * abs(np.dot(x, np.roll(y, 1)) - np.dot(y, np.roll(x, 1)))
    assert (count, valid) == (1, True)
    assert volume == pytest.approx(area * 20.0, rel=2e-5)
    assert elapsed < 60  # the target is 10 s on a quiet machine (benchmarks, docs/performance.md)


def test_step_refuses_helical_rings():
    pytest.importorskip("OCP", reason="STEP needs the optional [step] extra (cadquery-ocp)")
    from epicyclic.export.step import step_shapes

    drawing = gear_drawing(industrial(), "ring")
    with pytest.raises(ExportError, match="helical internal gears"):
        step_shapes(drawing, 3.0, helix_angle=12.0)
