"""The batch solver gives exactly what the scalar solver gives, point by point."""

import math

import numpy as np
import pytest

from epicyclic import Brake, GearStage, GearTrain, OperatingPoint, OperatingPointError, PlanetarySet, solve
from epicyclic.demo import PS, brandenberger_1952
from epicyclic.solver.batch import solve_batch
from epicyclic.units import UnitError


def test_batch_matches_scalar_on_the_brandenberger_train():
    train, _ = brandenberger_1952()
    rng = np.random.default_rng(1)
    n2 = rng.uniform(-3000, 3000, 40)
    n2[np.abs(n2) < 10] = 10.0
    power = rng.uniform(0.5, 5, 40) * PS
    res = solve_batch(train, speeds={"II": n2}, powers={"II": power}, drives=["II"], loads=["I"])
    for k in range(40):
        sol = solve(train, OperatingPoint(speeds={"II": n2[k]}, powers={"II": power[k]}, drives=["II"], loads=["I"]))
        for shaft in train.shafts:
            assert res.speeds[shaft][k] == pytest.approx(sol.speed(shaft), rel=1e-9, abs=1e-9)
            assert res.torques[shaft][k] == pytest.approx(sol.torque(shaft), rel=1e-9, abs=1e-9)
        assert res.efficiency[k] == pytest.approx(sol.efficiency, rel=1e-12)
        assert res.loss[k] == pytest.approx(sol.loss, rel=1e-9)
        assert res.losses["planetary"][k] == pytest.approx(sol.elements["planetary"].loss, rel=1e-9)
    # the efficiency of this train does not depend on the speed level or the power (one pattern)
    assert res.patterns == 1
    assert np.allclose(res.efficiency, res.efficiency[0])


def test_batch_flags_self_locking_and_both_directions():
    # Plus set i0 = 1.02, η0 = 0.95, ring held (closed form of Brandenberger 1952, eq. 7): carrier → sun η = 0.2714;
    # sun → carrier self-locks.  Signed torque at the sun with no roles: the power direction decides.
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", 1.02, 0.95), Brake("B", "ring")])
    sun_speed = np.array([1000.0, 1000.0, -400.0, -400.0])
    sun_torque = np.array([2.0, -2.0, 2.0, -2.0])
    res = solve_batch(train, speeds={"sun": sun_speed}, torques={"sun": sun_torque}, loads=["carrier"])
    # point 0 and 3: the sun drives (P > 0) → self-locking; 1 and 2: the sun is driven → the carrier
    # (a designated load) would have to deliver power: also self-locking as designated.
    assert res.self_locking.tolist() == [True, True, True, True]
    free = solve_batch(train, speeds={"sun": sun_speed}, torques={"carrier": np.array([1.0, -1.0, 1.0, -1.0])},
                       connected=["sun"])
    carrier_power = free.powers["carrier"]
    for k in range(4):
        if carrier_power[k] > 0:  # carrier drives the sun
            assert free.efficiency[k] == pytest.approx((1 - 1.02) / (1 - 1.02 / 0.95), rel=1e-9)
            assert not free.self_locking[k]
        else:
            assert free.self_locking[k] and np.isnan(free.efficiency[k])


def test_batch_groups_points_by_loss_pattern():
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", -2.0, 0.97), Brake("B", "ring")])
    torque = np.where(np.arange(100) % 2 == 0, 10.0, -10.0)
    res = solve_batch(train, speeds={"sun": np.linspace(100, 3000, 100)}, torques={"sun": torque}, connected=["carrier"])
    assert res.patterns == 2
    forward = (1 + 2 * 0.97) / 3          # sun → carrier: (1 − i0·η0)/(1 − i0)
    backward = 3 / (1 + 2 / 0.97)         # carrier → sun: (1 − i0)/(1 − i0/η0)
    assert np.allclose(res.efficiency[::2], forward, rtol=1e-12)
    assert np.allclose(res.efficiency[1::2], backward, rtol=1e-12)


def test_batch_broadcasts_grids():
    train, _ = brandenberger_1952()
    n2, p = np.meshgrid(np.linspace(500, 3000, 7), np.linspace(1, 4, 5) * PS)
    res = solve_batch(train, speeds={"II": n2}, powers={"II": p}, drives=["II"], loads=["I"])
    assert res.efficiency.shape == (5, 7)
    assert "35 points" in repr(res)


def test_batch_errors_name_the_point():
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", -2.0, 0.97), Brake("B", "ring"),
                       GearStage("G", "x", "carrier", 2.0)])
    with pytest.raises(OperatingPointError, match=r"stands still at point 1"):
        solve_batch(train, speeds={"sun": np.array([100.0, 0.0])}, powers={"sun": np.array([1.0, 1.0])},
                    loads=["x"])
    with pytest.raises(UnitError, match=r"solve_batch: speeds\['sun'\]\[2\]: expected a finite speed"):
        solve_batch(train, speeds={"sun": np.array([100.0, 1.0, np.nan])}, torques={"sun": 1.0}, loads=["x"])


def test_batch_reads_units_as_solve_does():
    """Pint quantities (also holding an array) and unit strings are converted, never stripped of their
    unit: 10 rad/s = 10·30/π 1/min (1 rad/s = 60/(2π) 1/min, exact definitions)."""
    import warnings

    import pint

    ureg = pint.UnitRegistry()
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", -2.0, 0.97), Brake("B", "ring")])
    roles = {"drives": ["sun"], "loads": ["carrier"]}
    with warnings.catch_warnings():
        warnings.simplefilter("error")   # pint's UnitStrippedWarning would be an error
        res = solve_batch(train, speeds={"sun": np.array([10.0, 100.0]) * ureg("rad/s")},
                          torques={"sun": 10.0}, **roles)
    assert res.speeds["sun"].tolist() == pytest.approx([300.0 / math.pi, 3000.0 / math.pi], rel=1e-15)
    res = solve_batch(train, speeds={"sun": ["1000 rpm", "50 1/s"]}, torques={"sun": ["10 N*m", "1 kN*m"]}, **roles)
    assert res.speeds["sun"].tolist() == [1000.0, 3000.0] and res.torques["sun"].tolist() == [10.0, 1000.0]
    scalar = solve(train, OperatingPoint(speeds={"sun": "1000 rpm"}, torques={"sun": "10 N*m"}, **roles))
    assert res.efficiency[0] == pytest.approx(scalar.efficiency, rel=1e-14)
    with pytest.raises(UnitError, match=r"solve_batch: speeds\['sun'\]\[1\]: '3 N' is not a speed"):
        solve_batch(train, speeds={"sun": [100.0, "3 N"]}, torques={"sun": 1.0}, **roles)
    with pytest.raises(UnitError, match=r"solve_batch: powers\['sun'\]: .* is not a power"):
        solve_batch(train, speeds={"sun": 100.0}, powers={"sun": np.array([1.0, 2.0]) * ureg("m")}, **roles)
    with pytest.raises(UnitError, match=r"solve_batch: torques\['sun'\]\[0\]: cannot read 'abc' as a torque"):
        solve_batch(train, speeds={"sun": 100.0}, torques={"sun": ["abc"]}, **roles)


def test_batch_with_more_than_twelve_levers_solves_each_point_with_its_own_pattern():
    # A chain of 13 stages (η0 = 0.97 each), the power flowing either way: two loss-direction patterns.
    # Patterns of more than 12 levers are grouped by np.unique; each point must get its own pattern's
    # torques (once every point got the last pattern's: η = 1.0 and a torque 2.1× too small).
    # Reference: the scalar solver at every point; a chain's η is Π η0 = 0.97^13 in both directions.
    shafts = [f"s{k}" for k in range(14)]
    train = GearTrain([GearStage(f"G{k}", shafts[k], shafts[k + 1], -1.1 if k % 2 else 1.2, 0.97) for k in range(13)])
    speed = np.array([1000.0, 1000.0, -800.0, 500.0])
    torque = np.array([10.0, -10.0, 5.0, -7.0])
    res = solve_batch(train, speeds={"s0": speed}, torques={"s0": torque}, connected=["s13"])
    assert res.patterns == 2
    for k in range(4):
        sol = solve(train, OperatingPoint(speeds={"s0": speed[k]}, torques={"s0": torque[k]}, connected=["s13"]))
        assert res.torques["s13"][k] == pytest.approx(sol.torque("s13"), rel=1e-12)
        assert res.efficiency[k] == pytest.approx(sol.efficiency, rel=1e-12)
        assert res.efficiency[k] == pytest.approx(0.97 ** 13, rel=1e-12)
