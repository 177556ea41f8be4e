"""Signs of given torques and powers: at a drive or a load the role sets the sign.

The file format and :class:`~epicyclic.OperatingPoint` document it (the text once said only
"positive with positive speed at a drive", and a user who wrote ``torques = { out = 36 }`` at a
load saw −36 in the report without being told why).  At a shaft that is neither drive nor load
the given sign counts.
"""

from __future__ import annotations

import pytest

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve

TRAIN = GearTrain([
    PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=30, z_planet=24, z_ring=78,
                        stationary_efficiency=0.98),
    Brake("B", "ring"),
])


@pytest.mark.parametrize("speed", [3000.0, -3000.0])
@pytest.mark.parametrize("given", [10.0, -10.0])
def test_a_drive_torque_takes_its_sign_from_the_role(speed, given):
    sol = solve(TRAIN, OperatingPoint(speeds={"in": speed}, torques={"in": given}, drives=["in"], loads=["out"]))
    assert sol.torque("in") == pytest.approx(10.0 if speed > 0 else -10.0)
    assert sol.power("in") > 0 > sol.power("out")
    assert sol.efficiency == pytest.approx((1 + 2.6 * 0.98) / 3.6, rel=1e-12)  # Müller Tab. 4.1, mode VI


@pytest.mark.parametrize("given", [36.0, -36.0])
def test_a_load_torque_takes_its_sign_from_the_role(given):
    sol = solve(TRAIN, OperatingPoint(speeds={"in": 3000.0}, torques={"out": given}, drives=["in"], loads=["out"]))
    assert sol.torque("out") == pytest.approx(-36.0)
    assert sol.power("out") < 0 < sol.power("in")


@pytest.mark.parametrize("given, role", [(36.0, "drive"), (-36.0, "load")])
def test_elsewhere_the_given_sign_counts(given, role):
    """'out' connected but neither drive nor load: +36 N·m at +833 1/min puts power in."""
    sol = solve(TRAIN, OperatingPoint(speeds={"in": 3000.0}, torques={"out": given}, connected=["in", "out"]))
    assert sol.torque("out") == pytest.approx(given)
    assert sol.shafts["out"].role == role
