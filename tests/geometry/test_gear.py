"""Gear and mesh geometry against published worked examples."""

from __future__ import annotations

import dataclasses
import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from epicyclic.geometry.errors import GeometryError
from epicyclic.geometry.gear import BasicRack, GearGeometry, MeshGeometry, iso_profile_shift
from epicyclic.geometry.involute import (
    inv,
    inv_inverse,
    operating_pressure_angle,
    profile_shift_sum,
)


def test_profile_shifted_external_pair_khk():
    # KHK / SDP-SI profile-shifted spur gear example, as reproduced at
    # bolsover.com/utilitiesforalibre/profile-shifted-external-spur-gears.html:
    # m = 3, z = 12/24, x = 0.6/0.36 -> a = 56.500, alpha_w = 26.0888 deg, y = 0.83333,
    # d = 36/72, d_b = 33.8289/67.6579, d_w = 37.667/75.333, d_a = 44.840/79.400,
    # d_f = 32.100/66.660, contact ratio 1.202.  Tolerance: the printed digits.
    rack = BasicRack(3)
    mesh = MeshGeometry(GearGeometry(12, rack, 0.6), GearGeometry(24, rack, 0.36)).with_tip_shortening()
    assert mesh.center_distance == pytest.approx(56.5, abs=5e-4)
    assert mesh.operating_pressure_angle == pytest.approx(26.0888, abs=5e-4)
    assert mesh.center_distance_modification == pytest.approx(0.83333, abs=5e-4)
    g1, g2 = mesh.gear1, mesh.gear2
    assert (g1.reference_diameter, g2.reference_diameter) == pytest.approx((36.0, 72.0))
    assert (g1.base_diameter, g2.base_diameter) == pytest.approx((33.8289, 67.6579), abs=5e-5)
    assert mesh.operating_pitch_diameters == pytest.approx((37.667, 75.333), abs=5e-4)
    assert (g1.tip_diameter, g2.tip_diameter) == pytest.approx((44.840, 79.400), abs=5e-4)
    assert (g1.root_diameter, g2.root_diameter) == pytest.approx((32.100, 66.660), abs=5e-4)
    assert mesh.contact_ratio == pytest.approx(1.202, abs=5e-4)


@pytest.mark.parametrize(
    ("z1", "z2", "m", "x1", "x2", "internal", "alpha_w", "a_w"),
    [
        # scribd.com/doc/92821234 "Centre distance of profile shifted gear calc" (printed to 4 decimals)
        (17, 96, 14, 0.2, 0.5, True, 21.1251, 557.0887),
        (30, 78, 16, 0.0, 0.05, False, 20.1446, 864.7972),
        # scribd.com/doc/210760271 (same worksheet, second external case)
        (22, 118, 8, 0.0, 0.5, False, 21.0617, 563.8999),
    ],
)
def test_operating_centre_distance_published(z1, z2, m, x1, x2, internal, alpha_w, a_w):
    # the worksheet writes the internal gear's shift in the KHK sign (x2 - x1 = 0.3 widens a_w)
    rack = BasicRack(m)
    x2 = iso_profile_shift(x2, internal, "khk")
    mesh = MeshGeometry(GearGeometry(z1, rack, x1), GearGeometry(z2, rack, x2, internal=internal))
    assert mesh.operating_pressure_angle == pytest.approx(alpha_w, abs=5e-5)
    assert mesh.center_distance == pytest.approx(a_w, abs=5e-5)


def test_helical_mesh_at_given_centre_distance():
    # Drivetrain Hub, Strength / Force Analysis: z = 15/45, m_n = 2.5, alpha_n = beta = 20 deg,
    # a = 80 mm -> d_w1 = 40 mm, alpha_tw = 21.515 deg.
    mesh = MeshGeometry.at_center_distance(15, 45, BasicRack(2.5, helix_angle=20), 80.0)
    assert mesh.center_distance == pytest.approx(80.0, abs=1e-9)
    assert mesh.operating_pitch_diameters[0] == pytest.approx(40.0, abs=1e-9)
    assert mesh.operating_pressure_angle == pytest.approx(21.515, abs=5e-4)


def test_involute_inverse_roundtrip_and_published_value():
    # inv 20 deg = 0.014904 and inv^-1(0.034317) = 26.0888 deg (KHK example above).
    assert inv(math.radians(20)) == pytest.approx(0.014904, abs=5e-7)
    assert math.degrees(inv_inverse(0.034317)) == pytest.approx(26.0888, abs=5e-4)
    assert profile_shift_sum(56.5, 36, 3.0, math.radians(20)) == pytest.approx(0.96, abs=5e-4)


@settings(max_examples=60, deadline=None)
@given(st.floats(0.01, 1.2))
def test_inv_inverse_is_inverse(alpha):
    assert inv_inverse(inv(alpha)) == pytest.approx(alpha, rel=1e-10)


@settings(max_examples=60, deadline=None)
@given(st.integers(8, 60), st.integers(8, 120), st.floats(-0.4, 0.8), st.floats(-0.4, 0.8), st.floats(0, 30))
def test_operating_pitch_circles_add_up(z1, z2, x1, x2, beta):
    # Invariants: d_w1 + d_w2 = 2 a_w; d_w2/d_w1 = z2/z1; no shift -> a_w = a.
    rack = BasicRack(2.0, helix_angle=beta)
    try:
        mesh = MeshGeometry(GearGeometry(z1, rack, x1), GearGeometry(z2, rack, x2))
    except GeometryError as exc:  # strongly negative shift sums have no operating angle
        assert "gives no operating pressure angle" in str(exc)
        assume(False)
    dw1, dw2 = mesh.operating_pitch_diameters
    assert dw1 + dw2 == pytest.approx(2 * mesh.center_distance)
    assert dw2 / dw1 == pytest.approx(z2 / z1)
    plain = MeshGeometry(GearGeometry(z1, rack), GearGeometry(z2, rack))
    assert plain.center_distance == pytest.approx(plain.reference_center_distance)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"module": 0}, "module must be a positive number"),
        ({"module": 2, "pressure_angle": 50}, "pressure_angle must lie in"),
        ({"module": 2, "helix_angle": -5}, "helix_angle must lie in"),
        ({"module": 2, "addendum": -1}, "addendum must be a positive"),
    ],
)
def test_rack_errors(kwargs, match):
    with pytest.raises(GeometryError, match=match):
        BasicRack(**kwargs)


def test_gear_and_mesh_errors():
    rack = BasicRack(2)
    with pytest.raises(GeometryError, match="teeth must be a whole number"):
        GearGeometry(2, rack)
    with pytest.raises(GeometryError, match="profile_shift must be a number"):
        GearGeometry(20, rack, 5.0)
    with pytest.raises(GeometryError, match="tip_shortening must be"):
        GearGeometry(20, rack, 0.0, tip_shortening=-1)
    with pytest.raises(GeometryError, match="gear1 must be the external"):
        MeshGeometry(GearGeometry(60, rack, internal=True), GearGeometry(20, rack))
    with pytest.raises(GeometryError, match="share module"):
        MeshGeometry(GearGeometry(20, rack), GearGeometry(30, BasicRack(3)))
    with pytest.raises(GeometryError, match="more teeth than its pinion"):
        MeshGeometry(GearGeometry(40, rack), GearGeometry(30, rack, internal=True))
    with pytest.raises(GeometryError, match="gives no operating pressure angle"):
        MeshGeometry(GearGeometry(8, rack, 0.0), GearGeometry(8, rack, -0.5))
    with pytest.raises(GeometryError, match="cannot be reached"):
        MeshGeometry.at_center_distance(20, 30, rack, 10.0)


def test_internal_shift_sign_is_iso_21771():
    # ISO 21771 / DIN 3960: an internal gear's negative x enlarges its tip circle and the centre distance
    # (inv a_wt = inv a_t + 2 tan a_n (x1 + x2)/(z1 + z2) with z2 < 0); KHK writes the opposite sign.
    rack = BasicRack(2)
    ring = GearGeometry(78, rack, -0.3, internal=True)
    assert ring.tip_diameter == pytest.approx(156 - 2 * 2 * (1 - 0.3))
    assert ring.root_diameter == pytest.approx(156 + 2 * 2 * (1.25 + 0.3))
    iso = MeshGeometry(GearGeometry(24, rack, 0.1), ring)
    khk = MeshGeometry(GearGeometry(24, rack, 0.1), GearGeometry(78, rack, iso_profile_shift(0.3, True, "khk"),
                                                                  internal=True))
    assert iso.center_distance == khk.center_distance > iso.reference_center_distance
    z_sum = -78 + 24  # ISO writes the internal gear with z < 0
    inv_w = inv(rack.alpha_t) + 2 * math.tan(rack.alpha_n) * (0.1 - 0.3) / z_sum
    assert iso.alpha_wt == pytest.approx(inv_inverse(inv_w), abs=1e-12)
    with pytest.raises(GeometryError, match="internal_shift_convention must be one of 'iso', 'khk'"):
        iso_profile_shift(0.3, True, "din")


def test_alpha_wt_is_computed_once_and_follows_every_new_pair():
    # α_wt is held from construction (a pure function of the frozen gears): it equals the ISO 21771
    # inverse involute of the pair, a replaced pair gets its own, and equality and repr ignore it.
    rack = BasicRack(3)
    mesh = MeshGeometry(GearGeometry(12, rack, 0.6), GearGeometry(24, rack, 0.36))
    assert mesh.alpha_wt == float(operating_pressure_angle(0.96, 36, rack.alpha_n, rack.alpha_t))
    assert math.degrees(mesh.alpha_wt) == pytest.approx(26.0886, abs=1e-4)  # KHK / SDP-SI z = 12/24
    other = dataclasses.replace(mesh, gear2=GearGeometry(24, rack, 0.0))
    assert other.alpha_wt == float(operating_pressure_angle(0.6, 36, rack.alpha_n, rack.alpha_t))
    assert other.alpha_wt < mesh.alpha_wt
    assert mesh == MeshGeometry(GearGeometry(12, rack, 0.6), GearGeometry(24, rack, 0.36))
    assert "_alpha_wt" not in repr(mesh) and "_alpha_wt" not in mesh.to_dict()
    with pytest.raises(dataclasses.FrozenInstanceError):
        mesh._alpha_wt = 0.5
