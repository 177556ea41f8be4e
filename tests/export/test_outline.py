"""Gear outlines (issue 31): B-splines within the stated tolerance of the ISO 21771 involute, closed, the right circles."""

from __future__ import annotations

import math

import numpy as np
import pytest

from epicyclic.export.outline import Arc, Spline, gear_outline
from epicyclic.geometry.errors import GeometryError
from epicyclic.geometry.gear import BasicRack, GearGeometry
from epicyclic.geometry.involute import inv
from epicyclic.geometry.tooth_generation import PinionCutter, generate_profile

CASES = [GearGeometry(20, BasicRack(3.0), 0.6, thickness_allowance=-0.06),
         GearGeometry(37, BasicRack(3.0), 0.3),
         GearGeometry(17, BasicRack(2.0, helix_angle=15.0), 0.2),
         GearGeometry(97, BasicRack(3.0), 0.3173, internal=True, thickness_allowance=-0.06)]


def _profile(gear):
    return generate_profile(gear, PinionCutter(37) if gear.internal else None)


def _half_angle(gear, radius):
    """ψ(r) of ISO 21771: half the tooth's angle at radius r (generating shift x_E), rad."""
    rack = gear.rack
    d = gear.reference_diameter
    s_t = rack.transverse_module * (math.pi / 2 + 2 * gear.generating_profile_shift * math.tan(rack.alpha_n))
    a_r = np.arccos(np.minimum(1.0, gear.base_diameter / (2 * radius)))
    return s_t / d - inv(rack.alpha_t) + inv(a_r) if gear.internal else s_t / d + inv(rack.alpha_t) - inv(a_r)


@pytest.mark.parametrize("gear", CASES, ids=lambda g: f"z{g.teeth}{'i' if g.internal else ''}")
def test_involute_splines_lie_on_the_iso_21771_involute(gear):
    # the involute as B-spline within the tolerance: distance of spline samples from the closed-form flank
    outline = gear_outline(_profile(gear), "g", tolerance=1e-4)
    involutes = [c for c in outline.curves[:len(outline.curves) // gear.teeth] if isinstance(c, Spline)
                 and c.segment == "involute"]
    assert len(involutes) == 2
    for curve in involutes:
        pts = curve.points(400)
        radius = np.hypot(*pts.T)
        off = np.abs(np.abs(np.arctan2(pts[:, 0], pts[:, 1])) - _half_angle(gear, radius))
        normal = radius * off * (gear.base_diameter / (2 * radius))  # arc offset times cos α_y: along the normal
        assert normal.max() < 1.5e-4
        assert len(curve.fit_points) < 60  # a spline, not the polyline of the dense profile


@pytest.mark.parametrize("gear", CASES, ids=lambda g: f"z{g.teeth}{'i' if g.internal else ''}")
def test_outline_is_closed_with_the_gear_circles(gear):
    outline = gear_outline(_profile(gear), "g")
    ends = [(c.points(2)[0], c.points(2)[-1]) for c in outline.curves]
    for i, here in enumerate(ends):
        after = ends[(i + 1) % len(ends)]
        assert min(np.hypot(*(a - b)) for a in here for b in after) < 1e-9
    radii = np.hypot(*outline.polygon().T)
    lo, hi = sorted((outline.root_diameter / 2, outline.tip_diameter / 2))
    assert radii.min() == pytest.approx(lo, abs=1e-6) and radii.max() == pytest.approx(hi, abs=1e-6)
    assert outline.tip_diameter == pytest.approx(gear.tip_diameter)
    arcs = [c for c in outline.curves if isinstance(c, Arc)]
    assert {round(a.radius, 6) for a in arcs} == {round(lo, 6), round(hi, 6)}
    assert outline.max_deviation <= 1e-4


def test_tooth_thickness_of_the_outline_at_the_reference_circle():
    # ISO 21771: the generated tooth is s_n (with the allowance) thick at d
    gear = CASES[0]
    outline = gear_outline(_profile(gear), "g")
    pts = outline.dense_polygon(0.001)
    r = np.hypot(*pts.T)
    near = np.abs(r - gear.reference_diameter / 2) < 0.002
    angles = np.arctan2(pts[near, 0], pts[near, 1])
    tooth0 = angles[np.abs(angles) < math.pi / gear.teeth]
    s_t = (tooth0.max() - tooth0.min()) * gear.reference_diameter / 2
    expected = gear.rack.module * (math.pi / 2 + 2 * gear.generating_profile_shift * math.tan(gear.rack.alpha_n))
    assert s_t == pytest.approx(expected, abs=2e-3)


def test_bad_tolerance():
    with pytest.raises(GeometryError, match="tolerance"):
        gear_outline(_profile(CASES[1]), "g", tolerance=0.0)
