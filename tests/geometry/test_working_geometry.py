"""Working geometry as built and the checks reviews make (issue 19): backlash, tip thickness, contact ratios."""

from __future__ import annotations

import math

import pytest

from epicyclic import PlanetarySet
from epicyclic.geometry import SetGeometry, check_fitting
from epicyclic.geometry.gear import BasicRack, GearGeometry, MeshGeometry
from epicyclic.geometry.working import (check_contact_ratio, check_tip_thickness, overlap_ratio,
                                        pointed_tip_diameter, tip_thickness, tooth_thickness)


def test_helical_pair_at_given_centre_distance_iso_21771_worksheet():
    # "Gear Generating Profile Shift Calculations" (scribd 376176518), ISO 21771:2007 eqs. 62-63:
    # z = 31/30, m_n = 3.5, alpha_n = 20°, beta = 21° (a = 114.3447280708 mm), a_w = 116.5 mm ->
    # alpha_wt = 23.8707609654°, alpha_t = 21.2990642859°, sum x = 0.651877131252; with j_bn = 0.03 mm the
    # generating sum x_E = 0.639346541; pinion x = 0.291.
    rack = BasicRack(3.5, helix_angle=21.0)
    assert rack.transverse_pressure_angle == pytest.approx(21.2990642859, abs=5e-11)
    sum_x = 0.651877131252
    free = MeshGeometry(GearGeometry(31, rack, 0.291), GearGeometry(30, rack, sum_x - 0.291))
    assert free.reference_center_distance == pytest.approx(114.3447280708, abs=5e-11)
    assert free.center_distance == pytest.approx(116.5, abs=1e-9)
    assert free.operating_pressure_angle == pytest.approx(23.8707609654, abs=5e-10)
    assert free.backlash == pytest.approx(0.0, abs=1e-12)
    # the backlash comes from thinner teeth: A_sn1 + A_sn2 = -j_bn / cos alpha_n
    allowance = -0.03 / math.cos(rack.alpha_n) / 2
    built = MeshGeometry(GearGeometry(31, rack, 0.291, thickness_allowance=allowance),
                         GearGeometry(30, rack, sum_x - 0.291, thickness_allowance=allowance),
                         working_center_distance=116.5)
    assert built.backlash == pytest.approx(0.03, abs=1e-10)  # sum x printed to 12 digits
    x_e = built.gear1.generating_profile_shift + built.gear2.generating_profile_shift
    assert x_e == pytest.approx(0.639346541, abs=5e-10)
    assert built.operating_pressure_angle == pytest.approx(23.8707609654, abs=5e-10)


def test_given_centre_distance_wider_than_the_shifts_gives_backlash_and_narrower_jams():
    p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78, planets=3)
    free = SetGeometry.create(p, module=2.0)
    assert free.sun_mesh.center_distance == 54.0
    wide = SetGeometry.create(p, module=2.0, center_distance=54.05)
    sun, ring = wide.meshes
    assert sun.center_distance == ring.center_distance == 54.05
    # first-order closed form: j_bn = 2 da sin(alpha_w) (error of order da/a); a wider internal mesh jams
    assert sun.backlash == pytest.approx(2 * 0.05 * math.sin(sun.alpha_wt), rel=5e-3)
    assert ring.backlash == pytest.approx(-2 * 0.05 * math.sin(ring.alpha_wt), rel=5e-3)
    report = check_fitting(wide)
    failing = {c.condition for c in report.failures}
    assert not report.passed and failing == {"backlash"}
    assert "planet-ring: the teeth jam at a_w = 54.0500 mm (given)" in report.table()


def test_planet_shift_and_allowances_make_a_given_distance_run():
    p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78, planets=3)
    g = SetGeometry.create(p, module=2.0, center_distance=54.0, thickness_allowance=-0.05)
    report = check_fitting(g)
    backlash = [c for c in report.checks if c.condition == "backlash"]
    # each mesh: j_bn = -(A_sn1 + A_sn2) cos alpha_n = 0.1 cos 20°
    assert [c.backlash for c in backlash] == pytest.approx([0.1 * math.cos(math.radians(20))] * 2, abs=1e-12)
    assert report.passed


def _involute_half_angle_at(gear: GearGeometry, diameter: float) -> float:
    """Half tooth angle at d_y from the rolled involute (parametric, no inv formula), external spur gear."""
    r_b, r_y = gear.base_diameter / 2, diameter / 2
    t = math.sqrt((r_y / r_b) ** 2 - 1)  # roll angle of the point at r_y
    polar = t - math.atan(t)  # the involute point's polar angle from its base-circle start
    r = gear.reference_diameter / 2
    t_ref = math.sqrt((r / r_b) ** 2 - 1)
    half_ref = (math.pi / 2 + 2 * gear.profile_shift * math.tan(gear.rack.alpha_n)) / gear.teeth
    start = half_ref + (t_ref - math.atan(t_ref))  # where the flank leaves the base circle
    return start - polar


@pytest.mark.parametrize(("z", "x"), [(12, 0.6), (20, 0.0), (30, -0.2), (17, 0.4)])
def test_tip_thickness_against_the_rolled_involute(z, x):
    gear = GearGeometry(z, BasicRack(3.0), x)
    expected = 2 * _involute_half_angle_at(gear, gear.tip_diameter) * gear.tip_diameter / 2
    assert tip_thickness(gear) == pytest.approx(expected, rel=1e-12)
    assert tooth_thickness(gear, pointed_tip_diameter(gear)) == pytest.approx(0.0, abs=1e-9)


def test_pointed_and_thin_tips_are_errors_and_warnings():
    rack = BasicRack(2.0)
    gears = {"pinion": GearGeometry(8, rack, 1.2), "thin": GearGeometry(12, rack, 0.5),
             "fine": GearGeometry(40, rack, 0.0)}
    checks = {c.gear: c for c in check_tip_thickness(gears)}
    assert tip_thickness(gears["pinion"]) <= 0 and checks["pinion"].severity == "error"
    assert "pointed teeth" in checks["pinion"].message
    assert 0.2 <= checks["thin"].tip_thickness / 2.0 < 0.4 and checks["thin"].severity == "warning"
    assert checks["fine"].passed


def test_contact_ratio_below_one_cannot_run():
    rack = BasicRack(3.0)
    short = MeshGeometry(GearGeometry(12, rack, 0.6, tip_shortening=0.5), GearGeometry(24, rack, 0.36,
                                                                                         tip_shortening=0.5))
    (check,) = check_contact_ratio([short])
    assert short.contact_ratio < 1 and not check.passed and check.severity == "error"
    p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78, planets=3)
    cut = SetGeometry.create(p, module=2.0, tip_shortening={"sun": 0.6, "planet": 0.6})
    report = check_fitting(cut)
    assert not report.passed and "contact ratio" in {c.condition for c in report.failures}


def test_helical_overlap_and_total_contact_ratio():
    # eps_beta = b sin(beta) / (pi m_n) (ISO 21771); a narrow helical mesh with eps_alpha < 1 runs on its overlap
    rack = BasicRack(2.0, helix_angle=30.0)
    mesh = MeshGeometry(GearGeometry(20, rack, 0.0, tip_shortening=0.4), GearGeometry(40, rack, 0.0,
                                                                                      tip_shortening=0.4))
    assert mesh.contact_ratio < 1
    assert overlap_ratio(mesh, 20.0) == pytest.approx(20 * 0.5 / (2 * math.pi))
    (wide,) = check_contact_ratio([mesh], [20.0])
    assert wide.total == pytest.approx(mesh.contact_ratio + 20 * 0.5 / (2 * math.pi))
    assert wide.severity == "warning" and not wide.passed  # continuous through the overlap only
    (unknown,) = check_contact_ratio([mesh], [None])
    assert unknown.severity == "error" and "give face_width" in unknown.message


def test_mesh_table_shows_working_helix_angle_and_contact_ratios():
    p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78, planets=3)
    g = SetGeometry.create(p, module=2.0, helix_angle=15.0, face_width=25.0)
    text = g.table()
    assert "beta_w [deg]" in text and "eps_gamma" in text and "j_bn [um]" in text


def test_undercut_message_compares_the_shift_with_the_least():
    p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=12, z_planet=33, z_ring=78, planets=3)
    report = check_fitting(SetGeometry.create(p, module=2.0))
    (sun,) = [c for c in report.failures if c.condition == "undercut"]
    # machinecalcs.com: a 12-tooth 20° pinion needs x_min = 0.298
    assert "x = +0.0000 is below the least x_min = h_a* (z_g - z)/z_g = +0.2981" in sun.message
    assert sun.min_profile_shift == pytest.approx(0.298, abs=5e-4)


STAGE = """
[[gear]]
name = "G"
first = "a"
second = "b"
meshes = [[20, 31], [31, 40]]
[gear.geometry]
module = 2
face_width = 20
profile_shift = [[0.5, {x2}], [{x3}, 0.0]]
{extra}
"""


def test_idler_keeps_one_geometry_in_both_meshes():
    from epicyclic.geometry.working import check_stage
    from epicyclic.errors import EpicyclicError
    from epicyclic.io import InputFileError, loads_train_file

    g = loads_train_file(STAGE.format(x2=0.2, x3=0.2, extra="idlers = [1]")).geometry["G"]
    first, second = g.meshes
    idler_a, idler_b = first.gear2, second.gear1
    assert idler_a.teeth == idler_b.teeth == 31 and idler_a.profile_shift == idler_b.profile_shift == 0.2
    assert idler_a.tip_diameter == idler_b.tip_diameter  # the larger tip shortening of its two meshes on both
    assert idler_a.tip_shortening == max(first.tip_shortening, second.tip_shortening) > 0
    report = check_stage(g)
    names = [c.gear for c in report.checks if c.condition == "tip thickness"]
    assert names == ["mesh 1 driving (z = 20)", "mesh 1 driven (z = 31) idler", "mesh 2 driven (z = 40)"]
    assert report.passed
    with pytest.raises(EpicyclicError, match=r"'G', table 'geometry'.*idler of meshes 1 and 2 is one gear with one"):
        loads_train_file(STAGE.format(x2=0.2, x3=0.1, extra="idlers = [1]"))
    with pytest.raises(InputFileError, match=r"key 'geometry.idlers': expected a list of mesh numbers 1 … 1"):
        loads_train_file(STAGE.format(x2=0.2, x3=0.2, extra="idlers = [2]"))
    # a stage built at a centre distance too small for its shifts jams: fit says so
    jam = loads_train_file(STAGE.format(x2=0.2, x3=0.2, extra="idlers = [1]\ncenter_distance = [52.0, 72.0]"))
    report = check_stage(jam.geometry["G"])
    assert [c.mesh for c in report.failures] == ["mesh 1 (20/31)"]  # 52 mm < what x = 0.5 + 0.2 needs
    assert next(c for c in report.checks if c.condition == "backlash" and c.mesh == "mesh 2 (31/40)").backlash > 0


def test_set_file_keys_as_built():
    from epicyclic.io import InputFileError, loads_train_file

    text = """
[[planetary]]
name = "P"
sun = "in"
ring = "housing"
carrier = "out"
teeth = { sun = 30, planet = 24, ring = 78 }
[planetary.geometry]
module = 2
%s
"""
    g = loads_train_file(text % "center_distance = 54.0\nthickness_allowance = { sun = -0.05, planet = -0.04 }\n"
                                "tip_shortening = { sun = 0.1 }").geometry["P"]
    assert [m.working_center_distance for m in g.meshes] == [54.0, 54.0]
    assert g.gears["sun"].thickness_allowance == -0.05 and g.gears["ring"].thickness_allowance == 0.0
    assert g.gears["sun"].tip_shortening == 0.1 and g.gears["planet"].tip_shortening == 0.0
    assert g.sun_mesh.backlash == pytest.approx(0.09 * math.cos(math.radians(20)), abs=1e-12)
    for bad, says in (("thickness_allowance = 0.1", "expected a tooth-thickness allowance A_sn in \\[-m_n, 0\\]"),
                      ("center_distance = -54", "geometry.center_distance': expected a positive number"),
                      ("tip_shortening = { sun = -0.1 }", "tip-shortening coefficient k >= 0 for sun")):
        with pytest.raises(InputFileError, match=says):
            loads_train_file(text % bad)


@pytest.mark.parametrize("x_iso", [0.0, -0.4, 0.25])
def test_internal_tooth_is_the_space_of_the_external_gear_with_the_opposite_shift(x_iso):
    # an internal gear (ISO sign) is the negative of the external gear with x_ext = -x_iso: its tooth
    # thickness at any diameter is the pitch there minus that gear's tooth (ISO 21771, z < 0)
    rack = BasicRack(2.5)
    ring = GearGeometry(78, rack, x_iso, internal=True)
    external = GearGeometry(78, rack, -x_iso)
    for d_y in (ring.tip_diameter, ring.reference_diameter, ring.reference_diameter + 3.0):
        pitch = math.pi * d_y / 78
        assert tooth_thickness(ring, d_y) == pytest.approx(pitch - tooth_thickness(external, d_y), rel=1e-12)
    assert tip_thickness(ring) < tooth_thickness(ring, ring.reference_diameter)  # thinner toward its tip


def test_given_centre_distance_out_of_reach_is_refused():
    from epicyclic.geometry.errors import GeometryError

    rack = BasicRack(2.0)
    with pytest.raises(GeometryError, match=r"lies 5e\+299 modules from the reference a = 54.0000 mm"):
        MeshGeometry(GearGeometry(30, rack), GearGeometry(24, rack), working_center_distance=1e300)
    with pytest.raises(GeometryError, match=r"below a cos α_t = 50.7434 mm"):
        MeshGeometry(GearGeometry(30, rack), GearGeometry(24, rack), working_center_distance=50.0)


from hypothesis import assume, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from epicyclic.geometry.errors import GeometryError  # noqa: E402


@settings(max_examples=25, deadline=None)
@given(st.integers(14, 60), st.integers(14, 120), st.floats(-0.3, 0.8), st.floats(-0.3, 0.8),
       st.floats(-0.2, 0.0), st.floats(-0.2, 0.0), st.booleans())
def test_backlash_is_the_allowances_at_the_free_distance(z1, z2, x1, x2, a1, a2, internal):
    # ISO 21771: at the backlash-free centre distance of the nominal shifts, j_bn = -(A_sn1 + A_sn2) cos alpha_n
    assume(not internal or z2 - z1 >= 10)
    rack = BasicRack(2.0)
    try:
        mesh = MeshGeometry(GearGeometry(z1, rack, x1, thickness_allowance=a1),
                            GearGeometry(z2, rack, x2, internal=internal, thickness_allowance=a2))
    except GeometryError:  # shifts without an operating pressure angle
        assume(False)
    assert mesh.backlash == pytest.approx(-(a1 + a2) * math.cos(rack.alpha_n), abs=1e-9)
    assert mesh.backlash >= -1e-12
