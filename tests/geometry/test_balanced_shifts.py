"""Profile shifts for coaxiality and balanced specific sliding (geometry/balanced_shifts.py).

No published worked example of balanced specific sliding for a planetary set was reachable; the checks are
closed forms: both meshes run at the a_w the shift sums give (ISO 21771:2007, inv α_wt = inv α_t +
2 tan α_n Σx/z_Σ, a_w = a cos α_t / cos α_wt), a pair of equal gears slides alike at both roots (symmetry),
and every set found passes the fitting conditions of ``epicyclic fit``.
"""

from __future__ import annotations

import math

import pytest

from epicyclic import PlanetarySet
from epicyclic.geometry import BasicRack, GearGeometry, MeshGeometry, SetGeometry, check_fitting
from epicyclic.geometry.balanced_shifts import BALANCE_STEP, balanced_shifts, root_sliding
from epicyclic.geometry.errors import GeometryError


def _set(zs, zp, zr, planets=3):
    return PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=zs, z_planet=zp, z_ring=zr, planets=planets)


def test_equal_gears_slide_alike_at_both_roots():
    rack = BasicRack(2.0, 20.0, 0.0)
    mesh = MeshGeometry(GearGeometry(25, rack, 0.2), GearGeometry(25, rack, 0.2))
    z1, z2 = root_sliding(mesh)
    assert z1 == pytest.approx(z2, rel=1e-12) and z1 < 0


def test_root_sliding_closed_form_of_a_standard_pair():
    # x = 0, no tip shortening: rho at the tips sqrt(r_a^2 - r_b^2), T1T2 = a sin(alpha)
    rack = BasicRack(1.0, 20.0, 0.0)
    mesh = MeshGeometry(GearGeometry(20, rack, 0.0), GearGeometry(40, rack, 0.0))
    a, alpha = 30.0, math.radians(20.0)
    rho_a1 = math.sqrt(11.0 ** 2 - (10.0 * math.cos(alpha)) ** 2)
    rho_a2 = math.sqrt(21.0 ** 2 - (20.0 * math.cos(alpha)) ** 2)
    g = a * math.sin(alpha)
    expected = (1 - rho_a2 / (g - rho_a2) * 20 / 40, 1 - rho_a1 / (g - rho_a1) * 40 / 20)
    assert root_sliding(mesh) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("teeth", [(19, 17, 56), (21, 39, 99), (30, 24, 78), (12, 18, 48)])
def test_every_choice_is_coaxial_buildable_and_balanced(teeth):
    zs, zp, zr = teeth
    try:
        choice = balanced_shifts(_set(zs, zp, zr))
    except GeometryError:  # a grid without any buildable point says so; these sets all have one
        pytest.fail(f"{teeth}: no shifts found")
    shape = SetGeometry.create(_set(zs, zp, zr), 3.0, x_sun=choice.x_sun, x_planet=choice.x_planet,
                               x_ring=choice.x_ring)
    assert check_fitting(shape).passed
    assert [m.center_distance for m in shape.meshes] == pytest.approx([3.0 * choice.center_distance] * 2, rel=1e-7)
    z1, z2 = root_sliding(shape.sun_mesh)
    assert abs(z1 - z2) <= BALANCE_STEP * 1.5 and (z1, z2) == pytest.approx(choice.sliding, abs=1e-4)


def test_the_bound_is_stated_and_a_set_without_a_buildable_point_is_refused():
    with pytest.raises(GeometryError, match=r"grid a_w/m_n .* x x_planet -0\.6 \.\.\. \+1\.2"):
        balanced_shifts(_set(40, 12, 64, planets=7))  # seven planets of a 40/12/64 set cannot be assembled
    choice = balanced_shifts(_set(19, 17, 56))
    assert "41 points" in choice.bound and choice.tried > choice.passed > 0
