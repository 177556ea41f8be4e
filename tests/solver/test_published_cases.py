"""Published cases no issue names: three-shaft power split and the bevel differential."""

import pytest

from epicyclic import GearTrain, OperatingPoint, PlanetarySet, solve

# Toyota Prius (3rd generation) power-split device: sun 30, pinion 23, ring 78 teeth
# (Mizuno et al., SAE 2009-01-0726, "Development of New Hybrid Transmission for Compact-Class
# Vehicles"; z_sun + 2 z_pinion = 76 ≠ 78: the set is profile-shifted).  Engine on the carrier,
# generator MG1 on the sun, ring to the wheels.
PSD = PlanetarySet.simple("PSD", sun="MG1", ring="wheels", carrier="engine", z_sun=30, z_planet=23, z_ring=78)


def test_power_split_torques_follow_queitsch_eqs_27_to_29():
    # Queitsch eqs. (28), (29): M_ring/M_carrier = s/(1 − s) and M_sun/M_ring = −1/s (eq. 27);
    # with s = −78/30: the ring takes 78/108 = 72.2 % of the engine torque, the sun 30/108.
    train = GearTrain([PSD])
    op = OperatingPoint(speeds={"engine": 2000, "wheels": 3000}, torques={"engine": 100},
                        drives=["engine"], loads=["wheels"], connected=["MG1"])
    sol = solve(train, op)
    s = PSD.stationary_ratio
    assert sol.torque("wheels") / sol.torque("engine") == pytest.approx(s / (1 - s), rel=1e-12)
    assert sol.torque("wheels") == pytest.approx(-100 * 78 / 108, rel=1e-12)
    assert sol.torque("MG1") == pytest.approx(-100 * 30 / 108, rel=1e-12)
    # Queitsch eq. (26): in three-shaft operation no torque reaches the housing.
    assert sol.torque("housing") == pytest.approx(0.0, abs=1e-12)
    # Willis: n_sun = (1 − s)·n_carrier + s·n_ring (Queitsch eq. 12)
    assert sol.speed("MG1") == pytest.approx((1 - s) * 2000 + s * 3000, rel=1e-12)
    assert sol.degrees_of_freedom == 2


def test_power_split_with_losses_balances_power():
    train = GearTrain([PlanetarySet("PSD", "MG1", "wheels", "engine", -78 / 30, 0.97)])
    op = OperatingPoint(speeds={"engine": 2000, "wheels": 3000}, powers={"engine": 30e3},
                        drives=["engine"], loads=["wheels"], connected=["MG1"])
    sol = solve(train, op)
    assert sum(s.power for s in sol.shafts.values()) == pytest.approx(sol.loss, rel=1e-12)
    assert 0 < sol.loss < 0.03 * 30e3  # only the rolling power is lossy, a fraction of the input


@pytest.mark.parametrize("eta0", [1.0, 0.95, 0.8])
@pytest.mark.parametrize("radius_over_track", [3.0, 10.0, 50.0])
def test_bevel_differential_torque_bias(eta0, radius_over_track):
    # A bevel differential is a set with i0 = −1.  Cornering with curve radius R and
    # track b: wheel speeds n_c·(1 ∓ b/(2R)).  With η0 < 1 the slower wheel gets the larger torque,
    # by the factor 1/η0 (the torque bias ratio); with η0 = 1 the split is 50/50.
    diff = GearTrain([PlanetarySet("diff", "left", "right", "case", -1.0, eta0)])
    n_case, half = 600.0, 1 / (2 * radius_over_track)
    op = OperatingPoint(speeds={"left": n_case * (1 - half), "right": n_case * (1 + half)},
                        torques={"case": 500.0}, drives=["case"], loads=["left", "right"])
    sol = solve(diff, op)
    assert sol.speed("case") == pytest.approx(n_case, rel=1e-12)
    assert sol.torque("left") / sol.torque("right") == pytest.approx(1 / eta0, rel=1e-12)
    assert sol.torque("left") + sol.torque("right") == pytest.approx(-500.0, rel=1e-12)
