"""Test dimensions (issue 31): W_k and k, M_d over/between balls, chordal thickness — published and closed forms."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq, minimize_scalar

from epicyclic.geometry.errors import GeometryError
from epicyclic.geometry.gear import BasicRack, GearGeometry
from epicyclic.geometry.involute import inv
from epicyclic.geometry.measurement import (base_tangent_length, chordal_measurement, chordal_of_virtual_gear,
                                            chordal_thickness, nominal_thickness, pin_dimension, pin_measurement,
                                            span_measurement, span_teeth, standard_pin_diameter)


def test_chordal_thickness_spur_sdp_si_d785_table_10_1():
    # SDP/SI, Elements of Metric Gear Technology (D785), Table 10-1: m = 10, alpha = 20°, z = 12, x = +0.3:
    # h_a = 13.000, s = 17.8918, theta = 8.54270°, s_j = 17.8256, h_j = 13.6657.
    gear = GearGeometry(12, BasicRack(10.0), 0.3)
    s = nominal_thickness(gear)
    assert s == pytest.approx(17.8918, abs=5e-5)
    assert math.degrees(s / gear.reference_diameter) == pytest.approx(8.54270, abs=5e-6)
    chord, height = chordal_thickness(gear)
    assert (gear.tip_diameter - gear.reference_diameter) / 2 == pytest.approx(13.0)
    assert chord == pytest.approx(17.8256, abs=5e-5)
    assert height == pytest.approx(13.6657, abs=5e-5)


def test_chordal_thickness_helical_sdp_si_d785_table_10_3_on_its_virtual_gear():
    # D785 Table 10-3 (normal system helical): m_n = 5, alpha_n = 20°, beta = 25°, z = 16, x_n = +0.2:
    # h_a = 6.0000, s_n = 8.5819, z_v = z / cos^3 beta = 21.4928, psi_v = 4.57556°, s_j = 8.5728, h_j = 6.1712.
    gear = GearGeometry(16, BasicRack(5.0, helix_angle=25.0), 0.2)
    s_n = nominal_thickness(gear)
    assert s_n == pytest.approx(8.5819, abs=5e-5)
    z_v = 16 / math.cos(math.radians(25.0)) ** 3
    assert z_v == pytest.approx(21.4928, abs=5e-5)
    assert math.degrees(s_n / (z_v * 5.0)) == pytest.approx(4.57556, abs=5e-6)
    chord, height = chordal_of_virtual_gear(s_n, z_v * 5.0, 6.0)
    assert chord == pytest.approx(8.5728, abs=5e-5)
    assert height == pytest.approx(6.1712, abs=5e-5)
    # the library's own helical chord uses ISO 21771's virtual gear d_n = d / cos^2 beta_b (z_n = 20.96, not 21.49)
    cos_bb = math.sqrt(1 - (math.sin(math.radians(25)) * math.cos(math.radians(20))) ** 2)
    d_n = gear.reference_diameter / cos_bb ** 2
    assert chordal_thickness(gear) == pytest.approx(chordal_of_virtual_gear(s_n, d_n, 6.0), abs=1e-12)


def test_span_machinecalcs_spur_example():
    # machinecalcs.com "Span Measurement Over Teeth Calculator", default case: m = 2, z = 20, alpha = 20°,
    # x = 0: k = 3, W = 15.321 mm, base pitch 5.904 mm.
    gear = GearGeometry(20, BasicRack(2.0))
    assert span_teeth(gear) == 3
    assert base_tangent_length(gear) == pytest.approx(15.321, abs=5e-4)
    assert base_tangent_length(gear, 4) - base_tangent_length(gear, 3) == pytest.approx(5.904, abs=5e-4)


@settings(max_examples=60, deadline=None)
@given(z=st.integers(10, 150), x=st.floats(-0.4, 0.8), m=st.sampled_from([1.0, 2.5, 6.0]), k=st.integers(1, 8),
       alpha=st.sampled_from([15.0, 20.0, 25.0]))
def test_span_spur_closed_form(z, x, m, k, alpha):
    # ISO 21771:2007, clause 5: W_k = m cos alpha [(k - 0.5) pi + z inv alpha + 2 x tan alpha] (spur)
    gear = GearGeometry(z, BasicRack(m, pressure_angle=alpha), x)
    a = math.radians(alpha)
    closed = m * math.cos(a) * ((k - 0.5) * math.pi + z * inv(a) + 2 * x * math.tan(a))
    assert base_tangent_length(gear, min(k, z - 1)) == pytest.approx(
        m * math.cos(a) * ((min(k, z - 1) - 0.5) * math.pi + z * inv(a) + 2 * x * math.tan(a)), rel=1e-12)
    assert closed > 0


@pytest.mark.parametrize("z, x, beta", [(20, 0.0, 0.0), (31, 0.291, 21.0), (57, -0.2, 12.0), (103, 0.5, 30.0)])
def test_span_rule_puts_the_anvils_on_the_middle_of_the_tooth(z, x, beta):
    # DIN 3960 rule for k: the (unrounded) k makes the measuring circle sqrt(d_b^2 + (W cos beta_b)^2) = d + 2 x m_n;
    # the rounded k lies within half a tooth of it.
    rack = BasicRack(3.0, helix_angle=beta)
    gear = GearGeometry(z, rack, x)
    cos_bb = math.sqrt(1 - (math.sin(rack.beta) * math.cos(rack.alpha_n)) ** 2)
    d_m = gear.reference_diameter + 2 * x * 3.0
    alpha_m = math.acos(gear.base_diameter / d_m)
    k_th = z / math.pi * (math.tan(alpha_m) / cos_bb ** 2 - 2 * x * math.tan(rack.alpha_n) / z
                          - inv(rack.alpha_t)) + 0.5
    w = 3.0 * math.cos(rack.alpha_n) * ((k_th - 0.5) * math.pi + z * inv(rack.alpha_t)) \
        + 2 * x * 3.0 * math.sin(rack.alpha_n)
    assert math.hypot(gear.base_diameter, w * cos_bb) == pytest.approx(d_m, rel=1e-12)
    assert abs(span_teeth(gear) - k_th) <= 0.5


def _flank_distance(point, half_angle, r_lo, r_hi):
    """Least distance from a point to the flank r -> (r cos psi(r), r sin psi(r)), r in [r_lo, r_hi]."""
    def dist(r):
        psi = half_angle(r)
        return math.hypot(point[0] - r * math.cos(psi), point[1] - r * math.sin(psi))
    res = minimize_scalar(dist, bounds=(r_lo, r_hi), method="bounded", options={"xatol": 1e-13})
    return res.fun, res.x


def _numeric_pin(gear: GearGeometry, pin: float) -> tuple[float, float]:
    """M_d and the contact radius of a spur gear from the flank curve itself (no inv alpha_M formula)."""
    z, d, r_b = gear.teeth, gear.reference_diameter, gear.base_diameter / 2
    s_t = nominal_thickness(gear)
    a_t = gear.rack.alpha_t

    def psi(r):  # half angle of tooth 0 at radius r (ISO 21771 s_y)
        a_r = math.acos(min(1.0, r_b / r))
        return s_t / d + inv(a_t) - inv(a_r) if not gear.internal else s_t / d - inv(a_t) + inv(a_r)

    phi = math.pi / z  # the space centre

    def miss(radius):
        centre = (radius * math.cos(phi), radius * math.sin(phi))
        return _flank_distance(centre, psi, r_b, 3 * r_b)[0] - pin / 2

    radius = brentq(miss, r_b * (1 + 1e-9), d / 2 + 2 * pin, xtol=1e-13)
    centre = (radius * math.cos(phi), radius * math.sin(phi))
    contact = _flank_distance(centre, psi, r_b, 3 * r_b)[1]
    span = 2 * radius if z % 2 == 0 else 2 * radius * math.cos(math.pi / (2 * z))
    return (span - pin if gear.internal else span + pin), contact


@pytest.mark.parametrize("z, x, internal, pin", [
    (20, 0.0, False, 1.728), (21, 0.0, False, 1.728), (13, 0.45, False, 1.9), (40, -0.3, False, 1.6),
    (60, 0.0, True, 1.6), (61, 0.0, True, 1.65), (97, 0.3173, True, 1.5), (80, -0.4, True, 1.7),
])
def test_pin_dimension_against_the_flank_curve(z, x, internal, pin):
    # Independent check: the ball centre placed where it is pin/2 from the involute flank itself
    # (ISO 21771 s_y, a numerical least distance), against DIN 3960's inv alpha_Mt closed form.
    gear = GearGeometry(z, BasicRack(1.0), x, internal=internal)
    numeric, _ = _numeric_pin(gear, pin)
    assert pin_dimension(gear, pin) == pytest.approx(numeric, abs=1e-7)


@pytest.mark.parametrize("z, x, internal", [(20, 0.0, False), (17, 0.4, False), (60, 0.0, True), (90, 0.25, True)])
def test_standard_pin_touches_on_d_plus_2xm(z, x, internal):
    gear = GearGeometry(z, BasicRack(2.0), x, internal=internal)
    pin = standard_pin_diameter(gear)
    _, contact = _numeric_pin(gear, pin)
    target = gear.reference_diameter + (-2 if internal else 2) * x * 2.0
    assert 2 * contact == pytest.approx(target, abs=1e-5)
    # the handbooks' rule of thumb: about 1.65-1.75 m for alpha = 20° (tandwiel.info, "Tooth thickness measurement
    # with pins or balls": 1.75 m external, 1.65 m internal gears)
    if x == 0:
        assert 1.6 < pin / 2.0 < 1.8


def test_helical_ball_dimension_tends_to_spur_and_grows_with_thickness():
    spur = GearGeometry(24, BasicRack(2.0), 0.2)
    nearly = GearGeometry(24, BasicRack(2.0, helix_angle=1e-6), 0.2)
    assert pin_dimension(nearly, 3.5) == pytest.approx(pin_dimension(spur, 3.5), rel=1e-9)
    helical = GearGeometry(24, BasicRack(2.0, helix_angle=20.0), 0.2)
    s = nominal_thickness(helical)
    assert pin_dimension(helical, 3.5, s + 0.01) > pin_dimension(helical, 3.5, s)
    ring = GearGeometry(80, BasicRack(2.0, helix_angle=20.0), 0.0, internal=True)
    s = nominal_thickness(ring)
    assert pin_dimension(ring, 3.3, s + 0.01) < pin_dimension(ring, 3.3, s)


@pytest.mark.parametrize("beta", [0.0, 15.0])
def test_allowances_of_the_test_dimensions(beta):
    # A_Wk = A_sn cos alpha_n exactly (W_k is linear in s_n; DIN 3960); M_d limits are M_d at s_n + A_sn.
    gear = GearGeometry(31, BasicRack(3.0, helix_angle=beta), 0.25, thickness_allowance=-0.05)
    span = span_measurement(gear, lower_allowance=-0.12)
    cos_a = math.cos(gear.rack.alpha_n)
    assert span.allowances == pytest.approx((-0.05 * cos_a, -0.12 * cos_a), abs=1e-12)
    pins = pin_measurement(gear, 5.5, -0.12)
    s = nominal_thickness(gear)
    assert pins.upper == pytest.approx(pin_dimension(gear, 5.5, s - 0.05), abs=1e-12)
    assert pins.nominal > pins.upper > pins.lower
    chord = chordal_measurement(gear, -0.12)
    assert chord.nominal > chord.upper > chord.lower
    assert chord.constant_chord == pytest.approx(s * cos_a ** 2)


def test_bad_input_is_refused_with_the_key():
    ring = GearGeometry(80, BasicRack(2.0), internal=True)
    with pytest.raises(GeometryError, match="external gears only"):
        base_tangent_length(ring)
    gear = GearGeometry(20, BasicRack(2.0), thickness_allowance=-0.05)
    with pytest.raises(GeometryError, match="k \\(teeth spanned\\)"):
        base_tangent_length(gear, 0)
    with pytest.raises(GeometryError, match="A_sni"):
        span_measurement(gear, lower_allowance=0.0)
    with pytest.raises(GeometryError, match="pin_diameter"):
        pin_dimension(gear, float("nan"))
    with pytest.raises(GeometryError, match="larger pin_diameter"):
        pin_dimension(gear, 0.1)
    with pytest.raises(GeometryError, match="smaller pin_diameter"):
        pin_dimension(ring, 30.0)
