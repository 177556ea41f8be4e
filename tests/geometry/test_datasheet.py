"""The manufacturing data sheet (issue 31): per-gear test dimensions with allowances and the pair's backlash."""

from __future__ import annotations

import json
import math

import pytest

from epicyclic import PlanetarySet
from epicyclic.geometry import SetGeometry
from epicyclic.geometry.datasheet import data_sheet, mesh_backlash
from epicyclic.geometry.errors import GeometryError
from epicyclic.geometry.gear import BasicRack, GearGeometry, MeshGeometry
from epicyclic.geometry.measurement import base_tangent_length


def _industrial(**kw) -> SetGeometry:
    # docs/geometry.md "industrial stage 20/37/97" (m = 3, x = 0.6/0.3/0.3173 ISO, a = 87.96 mm, js7, A_sn = -60 µm)
    p = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=20, z_planet=37, z_ring=97, planets=3)
    return SetGeometry.create(p, module=3.0, x_sun=0.6, x_planet=0.3, x_ring=0.3173, center_distance=87.96,
                              center_distance_tolerance="js7", thickness_allowance=-0.06, **kw)


def test_backlash_of_thinned_teeth_iso_21771_eq_63():
    # ISO 21771:2007 eq. (63): at the backlash-free distance of the nominal shifts, j_bn = -(A_sn1 + A_sn2) cos alpha_n
    rack = BasicRack(2.0, helix_angle=15.0)
    mesh = MeshGeometry(GearGeometry(23, rack, 0.2, thickness_allowance=-0.04),
                        GearGeometry(51, rack, -0.1, thickness_allowance=-0.07))
    result = mesh_backlash(mesh, -0.09, -0.15)
    cos_a = math.cos(rack.alpha_n)
    assert result.nominal == pytest.approx(0.11 * cos_a, abs=1e-12)
    assert result.least == pytest.approx(0.11 * cos_a, abs=1e-12)
    assert result.largest == pytest.approx(0.24 * cos_a, abs=1e-12)


def test_centre_distance_allowance_widens_the_range_to_first_order():
    # spur external pair: d j_bn / d a_w = 2 sin alpha_wt (j_wt = 2 Δa tan alpha_wt, j_bn = j_wt cos alpha_wt)
    rack = BasicRack(2.0)
    mesh = MeshGeometry(GearGeometry(20, rack), GearGeometry(40, rack), working_center_distance=60.0)
    result = mesh_backlash(mesh, 0.0, 0.0, allowance=1e-4)
    assert result.largest == pytest.approx(2e-4 * math.sin(mesh.alpha_wt), rel=1e-4)
    assert result.least == pytest.approx(-2e-4 * math.sin(mesh.alpha_wt), rel=1e-4)
    assert result.circumferential[1] == pytest.approx(result.largest / math.cos(mesh.alpha_wt))


def test_data_sheet_of_the_industrial_set():
    sheet = data_sheet(_industrial(), thickness_tolerance={"sun": 0.05, "planet": 0.05, "ring": 0.08})
    names = [g.name for g in sheet.gears]
    assert names == ["sun", "planet", "ring"]
    sun = sheet.gears[0]
    assert sun.span is not None and sun.span.nominal == pytest.approx(base_tangent_length(sun.gear, sun.span.teeth_spanned))
    assert sheet.gears[2].span is None  # an internal gear: measured between balls
    ring = sheet.gears[2].pins
    assert ring.internal and ring.lower > ring.upper  # thinner internal teeth: the balls sit further out
    # the nominal backlash is the fitting check's (docs/geometry.md: 115.4 / 110.9 µm) and lies in the range
    assert [round(m.nominal * 1000, 1) for m in sheet.meshes] == [115.4, 110.9]
    for m in sheet.meshes:
        assert m.least <= m.nominal <= m.largest
        assert m.center_distance_allowance == pytest.approx(0.0175)  # js7 of 88 mm: ± 35/2 µm (ISO 286-1)
    data = json.loads(json.dumps(sheet.to_dict(), allow_nan=False))
    assert data["gears"][0]["thickness"]["lower_allowance"] == pytest.approx(-0.11)
    text = sheet.table()
    assert "W_k" in text and "planet-ring" in text
    assert "<table>" in sheet._repr_html_() and sheet.markdown().startswith("### Data sheet of P")


def test_missing_tolerance_is_said_and_bad_input_named():
    sheet = data_sheet(_industrial())
    assert "no tooth-thickness tolerance" in sheet.table()
    with pytest.raises(GeometryError, match="thickness_tolerance of 'sun'"):
        data_sheet(_industrial(), thickness_tolerance=-0.01)
    with pytest.raises(GeometryError, match="no gear 'moon'"):
        data_sheet(_industrial(), pin_diameter={"moon": 5.0})
    with pytest.raises(GeometryError, match="gear 'sun'.*pin_diameter"):
        data_sheet(_industrial(), pin_diameter={"sun": 0.5})


def test_flank_tolerances_of_the_accuracy_grade_come_from_geometry_accuracy():
    from epicyclic.geometry.accuracy import flank_tolerances

    sheet = data_sheet(_industrial(face_width=30.0), accuracy_grade=6)
    sun = sheet.gears[0]
    expected = flank_tolerances(6, sun.gear.reference_diameter, 3.0, 30.0, "2013")
    assert sun.accuracy == expected
    assert "ISO 1328-1:2013" in sheet.table() and sheet.to_dict()["gears"][0]["accuracy"]["f_pt"] == expected.f_pt
    old = data_sheet(_industrial(face_width=30.0), accuracy_grade=7, accuracy_edition="1995")
    assert old.gears[2].accuracy.standard == "ISO 1328-1:1995"
    bare = data_sheet(_industrial(), accuracy_grade=6)
    assert bare.gears[0].accuracy is None and "needs the face width" in bare.table()
