"""Conditioning, not luck: extreme ratios, i0 near 1, long chains, near-singular and non-finite trains.

Closed forms (Brandenberger 1952, eq. 1 for speeds; eq. 7 with Bild 8/9 for the loss rule): a set with
one member held is a two-shaft gear whose efficiency is
  ring held, sun → carrier: η = (1 − i0·η0^w)/(1 − i0),   carrier → sun: η = (1 − i0)/(1 − i0/η0^w)
with w = +1 where the sun drives relative to the carrier.  A chain of stages multiplies ratios and
efficiencies.  Tolerances: 1e-12 relative where the solver evaluates the same products; the closed
forms themselves are evaluated with the exact difference 1 − i0 (Sterbenz) where i0 is near 1.
"""

import math

import numpy as np
import pytest

from epicyclic import (
    Brake,
    EpicyclicError,
    GearStage,
    GearTrain,
    OperatingPoint,
    PlanetarySet,
    UnderdeterminedError,
    solve,
)
from epicyclic.errors import NearSingularError, NonFiniteResultError
from epicyclic.solver.batch import solve_batch


@pytest.mark.parametrize(("stages", "ratio"), [(30, 3.0), (30, 1 / 3), (40, -3.0), (20, 1e3)])
def test_long_chains_are_exact(stages, ratio):
    # 30 stages of 3: total ratio 3^30 ≈ 2e14 (the issue asks for ≥ 3^20); 20 stages of 1000: 1e60.
    train = GearTrain([GearStage(f"G{k}", f"s{k}", f"s{k + 1}", ratio, 0.99) for k in range(stages)])
    sol = solve(train, OperatingPoint(speeds={"s0": 3000.0}, torques={"s0": 10.0}, drives=["s0"],
                                      loads=[f"s{stages}"]))
    assert sol.speed(f"s{stages}") == pytest.approx(3000.0 / ratio**stages, rel=1e-12)
    assert sol.torque(f"s{stages}") == pytest.approx(-10.0 * ratio**stages * 0.99**stages, rel=1e-12)
    assert sol.efficiency == pytest.approx(0.99**stages, rel=1e-12)
    assert all(e.loss_direction == 1 for e in sol.elements.values())


@pytest.mark.parametrize("i0", [1e6, -1e6, 1e8, -3e7])
def test_extreme_stationary_ratios(i0):
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", i0, 0.97), Brake("B", "ring")])
    forward = solve(train, OperatingPoint(speeds={"sun": 1000.0}, torques={"sun": 10.0}, drives=["sun"],
                                          loads=["carrier"]))
    assert forward.speed("carrier") == pytest.approx(1000.0 / (1 - i0), rel=1e-12)
    # the sun drives relative to the carrier (w = +1) for either sign of i0
    assert forward.efficiency == pytest.approx((1 - i0 * 0.97) / (1 - i0), rel=1e-12)
    backward = solve(train, OperatingPoint(speeds={"carrier": 1.0}, torques={"carrier": 10.0},
                                           drives=["carrier"], loads=["sun"]))
    assert backward.speed("sun") == pytest.approx(1 - i0, rel=1e-12)
    assert backward.torque("sun") * backward.speed("sun") < 0 or backward.is_self_locking


@pytest.mark.parametrize("delta", [1e-6, -1e-6, 1e-9, -1e-9, 1e-11])
def test_stationary_ratio_near_one_solves_exactly(delta):
    i0 = 1.0 + delta
    gap = 1.0 - i0  # exact (Sterbenz): the difference the model really has
    # ring held, carrier → sun: n_sun = (1 − i0)·n_carrier, a gear reduction of ~1/δ
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", i0, 0.999), Brake("B", "ring")])
    sol = solve(train, OperatingPoint(speeds={"carrier": 1000.0}, torques={"carrier": 10.0}, drives=["carrier"],
                                      loads=["sun"]))
    assert sol.speed("sun") == pytest.approx(gap * 1000.0, rel=1e-12)
    # sun and ring given: n_c = (n_s − i0·n_r)/(1 − i0), amplified ~1/δ but exact
    free = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", i0, 1.0)])
    sol = solve(free, OperatingPoint(speeds={"sun": 1000.0, "ring": 999.0}, torques={"carrier": 1.0},
                                     connected=["sun", "ring"]))
    exact = (1000.0 - i0 * 999.0) / gap  # i0·999 and the difference are exact here (few bits)
    assert sol.speed("carrier") == pytest.approx(exact, rel=1e-12)
    assert sol.efficiency == 1.0


def test_efficiency_is_continuous_and_monotone_near_i0_one():
    # carrier → sun, ring held: η = (1 − i0)/(1 − i0/η0) (w = −1 for a plus set driven from the carrier),
    # a smooth function of i0 and η0: the solver follows it across 1 ± 1e-6, never jumping.
    def eta(i0, eta0):
        train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", i0, eta0), Brake("B", "ring")])
        sol = solve(train, OperatingPoint(speeds={"carrier": 1000.0}, torques={"carrier": 10.0},
                                          drives=["carrier"], loads=["sun"]))
        return sol.efficiency
    for i0 in 1 + np.linspace(1e-6, 3e-6, 7):
        value = eta(float(i0), 0.999)
        assert value == pytest.approx((1 - i0) / (1 - i0 / 0.999), rel=1e-9)
    lows = [eta(1.0001, e) for e in np.linspace(0.95, 0.999, 9)]
    assert all(b >= a for a, b in zip(lows, lows[1:]))


@pytest.mark.parametrize("eta0", [0.5, 0.9, 0.9836, 0.998, 0.99989, 0.9999])
@pytest.mark.parametrize("given", ["sun", "ring"])
def test_issue_13_reproduction_near_i0_one(eta0, given):
    # Issue 13: PlanetarySet i0 = 1.0001 with GearStage("G", "ring", "sun", −0.2, 1.0), sun drives ring.
    # The carrier has no external torque, so T_c = 0 and T_a·(1 − i0·η0^w) = 0: the set carries no
    # torque for every η0 < 1/i0 and the lossless stage carries everything: η = 1, no self-locking.
    # (The old solver reported false self-locking at 0.9836 and η = 1 at 0.998 from round-off.)
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", 1.0001, eta0),
                       GearStage("G", "ring", "sun", -0.2, 1.0)])
    sol = solve(train, OperatingPoint(speeds={"sun": 1000.0}, torques={given: 10.0}, drives=["sun"],
                                      loads=["ring"]))
    assert sol.self_locking is None and sol.efficiency == 1.0
    assert sol.elements["P"].status == "idle" and set(sol.elements["P"].torques.values()) == {0.0}
    assert sol.elements["P"].loss == 0.0 and sol.elements["P"].rolling_power == 0.0


def test_issue_13_reproduction_held_load():
    # Issue 13: the brake holds x2, the stage holds x3 (n3 = n2/0.7561 = 0): a torque given at the
    # load x3 is a reaction, not power.  The set P0 has a free carrier, so it is idle; no power flows.
    # Old result: η = 1.213 at exit 0 from 1e-10 W of round-off.
    from epicyclic import Brake as B

    train = GearTrain([B("B0", "x2"), PlanetarySet("P0", "x2", "x0", "x1", 1.09375, 0.5),
                       GearStage("G1", "x2", "x3", 0.7561, 0.7561)])
    sol = solve(train, OperatingPoint(speeds={"x0": 1338.2}, torques={"x3": 564.16}, drives=["x0"],
                                      loads=["x3"]))
    assert sol.speed("x2") == 0.0 and sol.speed("x3") == 0.0  # exactly: held by the brake
    assert sol.efficiency is None and sol.self_locking is None
    assert sol.input_power == 0.0 and sol.output_power == 0.0 and sol.loss == 0.0
    assert sol.torque("x3") == 564.16 and sol.torque("x0") == 0.0
    assert sol.elements["P0"].status == "idle" and sol.elements["G1"].status == "locked"
    # the brake takes the reaction through the standing stage: 564.16/0.7561 N·m
    assert abs(sol.elements["B0"].torques["shaft"]) == pytest.approx(564.16 / 0.7561, rel=1e-12)
    assert any("'x3' is a load but the train holds it still" in w for w in sol.warnings)
    assert any("no power flows" in w for w in sol.warnings)
    batch = solve_batch(train, speeds={"x0": np.array([1338.2, -50.0])}, torques={"x3": 564.16}, drives=["x0"],
                        loads=["x3"])
    assert np.isnan(batch.efficiency).all() and not batch.self_locking.any()
    assert batch.speeds["x3"].tolist() == [0.0, 0.0] and batch.input_power.tolist() == [0.0, 0.0]


def test_truly_near_singular_trains_get_a_clear_error():
    # A stage joins sun and ring with a ratio 1e-12 away from i0: given the carrier, n_ring =
    # (1 − i0)·n_c/(k − i0) is decided by round-off.  The error names the shafts and the distance.
    i0 = -2.0
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", i0, 0.98),
                       GearStage("G", "sun", "ring", i0 * (1 + 1e-12), 0.98)])
    op = OperatingPoint(speeds={"carrier": 1000.0}, torques={"carrier": 10.0}, drives=["carrier"], loads=["ring"])
    with pytest.raises(NearSingularError, match=r"from singular.*round-off") as info:
        solve(train, op)
    assert info.value.quantity == "speed" and 1e-14 < info.value.distance <= 1e-10
    assert set(info.value.shafts) >= {"ring"} and "G" in info.value.elements
    assert isinstance(info.value, EpicyclicError) and isinstance(info.value, ValueError)
    # exactly singular (the same ratio): the speed is free, said as such
    exact = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", i0, 0.98), GearStage("G", "sun", "ring", i0, 0.98)])
    with pytest.raises(UnderdeterminedError, match="still free"):
        solve(exact, op)


@pytest.mark.parametrize(("speed", "how"), [(1e308, "overflows"), (1e-307, "underflows")])
def test_speeds_out_of_float_range_name_the_quantity(speed, how):
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", -2.0, 0.97), Brake("B", "ring")])
    with pytest.raises(NonFiniteResultError, match=how) as info:
        solve(train, OperatingPoint(speeds={"carrier": speed}, torques={"sun": 1e-3}, drives=["sun"],
                                    loads=["carrier"]))
    assert info.value.quantity in ("speed", "torque", "power", "rolling power", "coupling power", "loss")
    big = solve(train, OperatingPoint(speeds={"sun": 1e300}, torques={"sun": 10.0}, drives=["sun"], loads=["carrier"]))
    assert big.efficiency == pytest.approx((1 + 2 * 0.97) / 3, rel=1e-12)
    assert all(math.isfinite(s.power) for s in big.shafts.values())


@pytest.mark.parametrize("speed", [1e300, 1e305, 1e307, 1e308, 1.7e308])
def test_speeds_near_the_float_limit_are_not_taken_for_round_off(speed):
    # Ring held, sun drives carrier at a given power: every result is finite, but the round-off bound
    # |A⁺|·|A|·|n| of the speeds overflowed near 1e308, every speed counted as round-off and the carrier
    # stood still (0 1/min): false self-locking at exit 0.  Closed form as above: n_c = n_s/(1 − i0),
    # η = (1 − i0·η0)/(1 − i0) for i0 = −2, η0 = 0.97 (1e-12: the same products).
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", -2.0, 0.97), Brake("B", "ring")])
    sol = solve(train, OperatingPoint(speeds={"sun": speed}, powers={"sun": 1e4}, drives=["sun"], loads=["carrier"]))
    assert sol.speed("carrier") == pytest.approx(speed / 3, rel=1e-12)
    assert sol.self_locking is None and sol.efficiency == pytest.approx((1 + 2 * 0.97) / 3, rel=1e-12)
    batch = solve_batch(train, speeds={"sun": np.array([speed, 1000.0])}, powers={"sun": 1e4}, drives=["sun"],
                        loads=["carrier"])
    assert batch.speeds["carrier"] == pytest.approx([speed / 3, 1000.0 / 3], rel=1e-12)
    assert batch.efficiency == pytest.approx([(1 + 2 * 0.97) / 3] * 2, rel=1e-12)


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # numpy's overflow warning; the error is ours
def test_an_overflowing_torque_is_named_not_taken_for_an_idle_set():
    # T_sun = 1.5e308 N·m, ring held: the ring and carrier torques (2× and 3×) overflow.  The idle rule
    # judged the set by |T| <= 1e-12·scale with both infinite (inf <= inf) and made it idle: zero torques,
    # a false self-locking with formal efficiency NaN, no error in the Python API.
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", -2.0, 0.97), Brake("B", "ring")])
    with pytest.raises(NonFiniteResultError, match="overflows") as info:
        solve(train, OperatingPoint(speeds={"sun": 1.0}, torques={"sun": 1.5e308}, drives=["sun"], loads=["carrier"]))
    assert info.value.quantity == "torque" and info.value.where.startswith("'P'")
    with pytest.raises(NonFiniteResultError, match="overflows"):
        solve_batch(train, speeds={"sun": np.array([1.0, 2.0])}, torques={"sun": 1.5e308}, drives=["sun"],
                    loads=["carrier"])


def test_tiny_efficiency_is_computed_or_named():
    # η0 = 5e-324 is inside (0, 1]: forward (w = +1) it is just a poor set; backward 1/η0 overflows.
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", -2.0, 5e-324), Brake("B", "ring")])
    forward = solve(train, OperatingPoint(speeds={"sun": 1000.0}, torques={"sun": 10.0}, drives=["sun"],
                                          loads=["carrier"]))
    assert forward.efficiency == pytest.approx(1 / 3, rel=1e-12)  # (1 − i0·η0)/(1 − i0)
    with pytest.raises(NonFiniteResultError, match="stationary efficiency 5e-324 is too small") as info:
        solve(train, OperatingPoint(speeds={"carrier": 1000.0}, torques={"carrier": 10.0}, drives=["carrier"],
                                    loads=["sun"]))
    assert info.value.quantity == "efficiency" and info.value.where == "P"


def test_a_better_eta0_can_open_a_lossy_path():
    # Not a round-off effect: Brandenberger's rule itself.  P0 (sun in, ring out, carrier x2, i0 = 2)
    # and P1 (sun in, ring x2, carrier x0 held, i0 = 1.25), both η0; M_in = 1 at n_in = 10.  Hand
    # calculation (Brandenberger eqs. 1, 2, 7, w = +1 for both): n_x2 = n_in/1.25 = 8, n_out = 9;
    # T_r0 = −2η0·T_s0, T_c0 = −(1 − 2η0)·T_s0 = −T_r1 = 1.25·η0·T_s1, T_s0 + T_s1 = 1.
    # η0 = 0.5: T_c0 = 0, P1 carries nothing, T_s0 = 1, η = |T_r0|·n_out/(M_in·n_in) = 0.9.
    # η0 = 0.6: T_s1 = 0.2·T_s0/0.75, T_s0 = 1/(1 + 0.2/0.75), η = 1.2·T_s0·9/10 = 0.85263: the
    # carrier path through the lossy P1 opens, and a better η0 gives a lower η.
    def efficiency(eta0):
        train = GearTrain([PlanetarySet("P0", "in", "out", "x2", 2.0, eta0),
                           PlanetarySet("P1", "in", "x2", "x0", 1.25, eta0), Brake("B", "x0")])
        return solve(train, OperatingPoint(speeds={"in": 10.0}, torques={"in": 1.0}, drives=["in"],
                                           loads=["out"])).efficiency
    assert efficiency(0.5) == pytest.approx(0.9, rel=1e-12)
    t_s0 = 1 / (1 + 0.2 / 0.75)
    assert efficiency(0.6) == pytest.approx(1.2 * t_s0 * 9 / 10, rel=1e-12)
    assert efficiency(0.6) < efficiency(0.5) < efficiency(1.0) == 1.0
