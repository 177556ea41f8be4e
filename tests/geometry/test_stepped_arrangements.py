"""Geometry, assembly and forces of stepped sets with any central gears (sun + ring, two suns, two rings)."""

from __future__ import annotations

from fractions import Fraction

import pytest

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.geometry import SetGeometry, assembly_ticks, check_assembly, check_coaxiality, planetary_forces
from epicyclic.model import Teeth


def _meshes_at(teeth: Teeth, u: Fraction) -> bool:
    """Whether a planet copy at carrier angle u (turns) can mesh with both unmoved central gears.

    Direct condition: some planet rotation v (turns, relative to the carrier) with
    u z_a − σ_a v z_b and u z_d − σ_d v z_c both whole numbers (σ = +1 internal, −1 external).
    """
    za, zd = teeth.sun, teeth.ring
    zb, zc = teeth.planet
    sa = 1 if teeth.sun_internal else -1
    sd = 1 if teeth.ring_internal else -1
    for whole in range(zb * zc + 1):  # v = sa (u za - whole)/zb, periodic in whole with period zb·zc
        v = Fraction(sa) * (u * za - whole) / zb
        if (u * zd - sd * v * zc).denominator == 1:
            return True
    return False


@pytest.mark.parametrize(
    ("sun_internal", "ring_internal", "counts"),
    [
        (False, True, (20, 68, (30, 18))),
        (False, False, (50, 42, (24, 30))),
        (True, True, (81, 78, (27, 24))),
        (True, False, (60, 15, (24, 21))),
    ],
)
def test_assembly_ticks_from_the_meshing_condition(sun_internal, ring_internal, counts):
    zs, zr, planet = counts
    teeth = Teeth("stepped", zs, zr, planet, ring_internal, sun_internal)
    ticks = assembly_ticks(teeth)
    assert _meshes_at(teeth, Fraction(1, ticks))
    # no smaller angle works: every solution is a multiple of 1/ticks
    g = 1
    for j in range(1, 4 * ticks):
        if _meshes_at(teeth, Fraction(j, 4 * ticks)):
            g = j
            break
    assert Fraction(g, 4 * ticks) == Fraction(1, ticks)


def _wolfrom(module_ratio=1.0):
    return PlanetarySet.two_rings("W", first="r1", second="out", carrier="c", z_first=81, z_planet_first=27,
                                  z_planet_second=24, z_second=78, planets=3, stationary_efficiency=0.97)


def test_wolfrom_geometry_is_coaxial_and_assembles():
    g = SetGeometry.create(_wolfrom(), module=2.0)
    assert g.gears["sun"].internal and g.gears["ring"].internal
    assert [m.name for m in g.meshes] == ["first-planet_first", "planet_second-second"]  # the file's names
    assert g.carrier_radius == pytest.approx(2.0 * (81 - 27) / 2)  # a = m (z_r1 - z_p1)/2
    assert check_coaxiality(g).passed
    # T = |z_r1 z_p2 - z_r2 z_p1| / gcd(z_p1, z_p2) = |1944 - 2106| / 3 = 54
    assembly = check_assembly(g, 3)
    assert assembly.ticks == 54 and assembly.passed and assembly.equally_spaced


def test_wolfrom_forces_balance_the_solver_torques():
    simple = PlanetarySet.simple("S", sun="in", ring="r1", carrier="c", z_sun=27, z_planet=27, z_ring=81,
                                 stationary_efficiency=0.97)
    wolfrom = _wolfrom()
    sol = solve(GearTrain([simple, wolfrom, Brake("B", "r1")]),
                OperatingPoint(speeds={"in": 3000.0}, torques={"in": 20.0}, drives=["in"], loads=["out"]))
    g = SetGeometry.create(wolfrom, module=2.0)
    forces = planetary_forces(sol, "W", g)
    torques = sol.elements["W"].torques
    # pin forces × radii plus the friction moments give the solver's carrier torque
    assert forces.carrier_torque_from_forces == pytest.approx(torques["carrier"], rel=1e-9)
    for body in forces.bodies:  # each planet in equilibrium with its pin
        fx = sum(m.force_on_planet[0] for m in body.meshes) + body.pin_force[0]
        fy = sum(m.force_on_planet[1] for m in body.meshes) + body.pin_force[1]
        assert (fx, fy) == pytest.approx((0.0, 0.0), abs=1e-9)
    # the internal first ring pushes the planet inward: radial force toward the axis
    first = forces.bodies[0].meshes[0]
    assert first.point[0] * first.force_on_planet[0] + first.point[1] * first.force_on_planet[1] < 0
    assert sum(forces.central_forces["carrier"]) == pytest.approx(0.0, abs=1e-8)
