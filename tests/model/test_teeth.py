"""Tooth-count forms of every arrangement: simple, double, stepped, two suns, two rings (Wolfrom)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, ToothCountError, solve
from epicyclic.model import Teeth


def wolfrom_train(zs=27, zp1=27, zr1=81, zp2=24, zr2=78, eta=1.0):
    """Sun → stepped planets → ring 1 (held) and ring 2 (output); one carrier (the 3K Wolfrom drive)."""
    return GearTrain([
        PlanetarySet.simple("S", sun="in", ring="r1", carrier="c", z_sun=zs, z_planet=zp1, z_ring=zr1,
                            stationary_efficiency=eta),
        PlanetarySet.two_rings("W", first="r1", second="out", carrier="c", z_first=zr1, z_planet_first=zp1,
                               z_planet_second=zp2, z_second=zr2, stationary_efficiency=eta),
        Brake("B", "r1"),
    ])


def test_two_rings_ratio_is_a_plus_set():
    # Both meshes internal keep the sense of rotation relative to the carrier (Brandenberger 1952, eq. 1
    # with no sign change): i0 = (n_r1 - n_c)/(n_r2 - n_c) = (z_r2 z_p1)/(z_r1 z_p2).
    w = PlanetarySet.two_rings("W", first="a", second="b", carrier="c", z_first=81, z_planet_first=27,
                               z_planet_second=24, z_second=78)
    assert w.stationary_ratio == pytest.approx(78 * 27 / (81 * 24), rel=1e-15)
    assert w.is_plus_set and w.teeth.arrangement == "two rings"
    assert w.teeth.planet_factors == pytest.approx((81 / 27,))  # internal mesh: planet turns with the ring


def test_wolfrom_drive_ratio_closed_form():
    # Wolfrom drive, ring 1 held: i = n_sun/n_ring2 = (1 + z_r1/z_s) · z_p1 z_r2 / (z_p1 z_r2 − z_p2 z_r1)
    # (independent closed form from the two Willis equations).
    zs, zp1, zr1, zp2, zr2 = 27, 27, 81, 24, 78
    expected = (1 + zr1 / zs) * zp1 * zr2 / (zp1 * zr2 - zp2 * zr1)
    sol = solve(wolfrom_train(), OperatingPoint(speeds={"in": 5200.0}, torques={"in": 10.0},
                                                drives=["in"], loads=["out"]))
    assert expected == pytest.approx(52.0)
    assert sol.ratio == pytest.approx(expected, rel=1e-12)
    # the old reading of the same counts as a sun+ring stepped set is a different (minus) set
    wrong = PlanetarySet.stepped("W", sun="a", ring="b", carrier="c", z_sun=81, z_planet_sun=27,
                                 z_planet_ring=24, z_ring=78)
    assert wrong.stationary_ratio < 0 < PlanetarySet.two_rings(
        "W", first="a", second="b", carrier="c", z_first=81, z_planet_first=27, z_planet_second=24,
        z_second=78).stationary_ratio


def test_wolfrom_planet_speed_from_the_internal_mesh():
    sol = solve(wolfrom_train(), OperatingPoint(speeds={"in": 5200.0}, torques={"in": 10.0},
                                                drives=["in"], loads=["out"]))
    n_c = sol.speed("c")
    # planet turns at n_p - n_c = -(z_s/z_p1)(n_s - n_c) through the sun and (z_r1/z_p1)(n_r1 - n_c)
    # through ring 1: both sets must agree on the stepped planet's speed.
    via_sun = sol.elements["S"].planet_speeds_relative[0]
    via_ring = sol.elements["W"].planet_speeds_relative[0]
    assert via_sun == pytest.approx(-(27 / 27) * (5200.0 - n_c))
    assert via_ring == pytest.approx(via_sun, rel=1e-12)


def test_two_suns_equals_stepped_with_external_ring():
    a = PlanetarySet.two_suns("B", first="I", second="II", carrier="III", z_first=50, z_planet_first=24,
                              z_planet_second=30, z_second=42)
    b = PlanetarySet.stepped("B", sun="I", ring="II", carrier="III", z_sun=50, z_planet_sun=24,
                             z_planet_ring=30, z_ring=42, ring_internal=False)
    assert a == b and a.teeth.arrangement == "two suns"


@pytest.mark.parametrize(
    ("factory", "match"),
    [
        # not coaxial with equal modules: 81 - 27 = 54 but 78 - 16 = 62, more than profile shift closes (6)
        (lambda: PlanetarySet.two_rings("W", first="a", second="b", carrier="c", z_first=81, z_planet_first=27,
                                        z_planet_second=16, z_second=78),
         r"cannot be coaxial: z_first - z_planet_first = 81 - 27 = 54 .* mismatch of 8 teeth .*module_ratio = 0\.870968"),
        (lambda: PlanetarySet.two_suns("B", first="a", second="b", carrier="c", z_first=50, z_planet_first=24,
                                       z_planet_second=20, z_second=42),
         r"cannot be coaxial: z_first \+ z_planet_first = 50 \+ 24 = 74"),
        (lambda: PlanetarySet.stepped("S", sun="s", ring="r", carrier="c", z_sun=20, z_planet_sun=30,
                                      z_planet_ring=18, z_ring=86, module_ratio=1.0),
         r"cannot be coaxial: z_sun \+ z_planet_sun = 20 \+ 30 = 50 but .*\(86 - 18\) = 68"),
        # i0 = 1: the set would be locked
        (lambda: PlanetarySet.two_rings("W", first="a", second="b", carrier="c", z_first=80, z_planet_first=20,
                                        z_planet_second=20, z_second=80),
         r"with two rings, .* i0 = 1 and the set is locked"),
        (lambda: PlanetarySet.two_rings("W", first="a", second="b", carrier="c", z_first=30, z_planet_first=30,
                                        z_planet_second=24, z_second=78),
         r"an internal gear must have more teeth than the planet gear meshing it, got z_first=30"),
        (lambda: PlanetarySet.stepped("S", sun="s", ring="r", carrier="c", z_sun=20, z_planet_sun=30,
                                      z_planet_ring=18, z_ring=68, module_ratio=0.0),
         r"module_ratio must be a positive number"),
        # double planets: the triangle a1 = 24, a2 = 10, a12 = 44 misses a1 + a2 = 34 by 10 modules
        (lambda: PlanetarySet.double_planet("D", sun="s", ring="r", carrier="c", z_sun=30, z_planet_sun=18,
                                            z_planet_ring=70, z_ring=90),
         r"double planets cannot be placed: .* must lie between"),
        (lambda: PlanetarySet.stepped("S", sun="s", ring="r", carrier="c", z_sun=20, z_planet_sun=30,
                                      z_planet_ring=18, z_ring=68, sun_internal="no"),
         r"sun_internal must be True or False"),
    ],
)
def test_tooth_count_errors(factory, match):
    with pytest.raises(ToothCountError, match=match):
        factory()


def test_module_ratio_makes_stepped_counts_coaxial():
    # 20 + 30 = 50 and 86 - 18 = 68: coaxial with m2/m1 = 50/68
    s = PlanetarySet.stepped("S", sun="s", ring="r", carrier="c", z_sun=20, z_planet_sun=30,
                             z_planet_ring=18, z_ring=86, module_ratio=50 / 68)
    assert s.stationary_ratio == pytest.approx(-86 * 30 / (20 * 18))
    w = PlanetarySet.two_rings("W", first="a", second="b", carrier="c", z_first=81, z_planet_first=27,
                               z_planet_second=20, z_second=78, module_ratio=54 / 58)
    assert w.stationary_ratio == pytest.approx(78 * 27 / (81 * 20))


@settings(max_examples=60, deadline=None)
@given(st.integers(3, 60), st.integers(3, 60), st.integers(3, 60), st.integers(3, 60),
       st.booleans(), st.booleans())
def test_stepped_ratio_is_the_product_of_mesh_ratios(zs, zb, zc, zr, sun_internal, ring_internal):
    # i0 = Π over meshes of (∓ z_driven... ): relative to the carrier each mesh turns the next gear by
    # -z_a/z_b (external) or +z_a/z_b (internal); two meshes give i0 = n_a/n_d.
    teeth = Teeth("stepped", zs, zr, (zb, zc), ring_internal, sun_internal)
    sign_s = 1.0 if sun_internal else -1.0
    sign_r = 1.0 if ring_internal else -1.0
    n_a = 1.0
    n_planet = sign_s * n_a * zs / zb
    n_d = sign_r * n_planet * zc / zr
    assert teeth.stationary_ratio == pytest.approx(n_a / n_d, rel=1e-12)
    assert teeth.planet_factors[0] == pytest.approx(n_planet / n_a)
    assert math.copysign(1.0, teeth.stationary_ratio) == sign_s * sign_r
