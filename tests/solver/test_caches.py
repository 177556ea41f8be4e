"""The solver's caches and fast paths give the results of a cold solve, and never another train's.

What is cached: a train's equations per set of external shafts (``assembly.matrices``), their
prepared speed and torque solvers per given shafts and loss pattern, and index tables derived from
them (``solver.point``, ``solver.solve``).  A scalar solve evaluates its point in Python floats
(``solver.point``), a batch in blocks of points (``solver.batch.BLOCK``): both must give the array
code's numbers bit for bit.  Reference: Brandenberger 1952, Bild 10 (the demo train), whose
published efficiency the cold solve reproduces in tests/solver/test_brandenberger.py.
"""

from __future__ import annotations

import importlib

import numpy as np
import pytest

from epicyclic import GearStage, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.demo import brandenberger_1952
from epicyclic.errors import OperatingPointError
from epicyclic.solver import assembly, batch, point
from epicyclic.solver.batch import solve_batch
from epicyclic.solver.evaluate import evaluate

solve_module = importlib.import_module("epicyclic.solver.solve")


def _clear_caches() -> None:
    assembly._matrices.cache_clear()
    point._plain.cache_clear()
    solve_module._element_layouts.cache_clear()


def _train(efficiency: float = 0.9, z_ring: int = 42) -> GearTrain:
    """Brandenberger's closed train (Bild 10) built anew: an equal but distinct object."""
    return GearTrain([
        PlanetarySet.stepped("planetary", sun="I", ring="II", carrier="III", z_sun=50, z_planet_sun=24,
                             z_planet_ring=30, z_ring=z_ring, ring_internal=False,
                             stationary_efficiency=efficiency),
        GearStage.from_teeth("stage", "III", "II", [(40, 44, "external"), (20, 64, "external")], efficiency=0.9),
    ], name="Brandenberger 1952, Bild 10")


POINTS = [
    OperatingPoint(speeds={"II": 1500.0}, powers={"II": 2206.49625}, drives=["II"], loads=["I"]),
    OperatingPoint(speeds={"II": 1500.0}, torques={"II": 14.0}, connected=["I"]),
    OperatingPoint(speeds={"II": -900.0}, torques={"II": 14.0}, connected=["I"]),  # the other loss pattern
    OperatingPoint(speeds={"I": 500.0}, torques={"I": 3.0}, drives=["I"], loads=["II"]),  # driven from I
    OperatingPoint(speeds={"III": 700.0}, torques={"II": 5.0}, drives=["II"], loads=["I"]),
]


@pytest.mark.parametrize("op", POINTS)
def test_cached_solve_equals_a_cold_solve(op):
    train, _ = brandenberger_1952()
    _clear_caches()
    cold = solve(train, op)
    warm = [solve(train, op) for _ in range(3)]
    assert all(w.to_dict() == cold.to_dict() for w in warm)
    assert all(w.ideal.to_dict() == cold.ideal.to_dict() for w in warm)
    assert solve(_train(), op).to_dict() == cold.to_dict()  # equal but distinct train: same equations


def test_the_cache_never_answers_for_another_train_or_operating_point():
    """Every point solved on trains that share the caches: each equals its own cold solve."""
    trains = [_train(), _train(efficiency=0.8), _train(z_ring=41), _train()]
    for train in trains:
        for op in POINTS:
            solve(train, op)  # fill the caches with every train and pattern
    for train in trains:
        for op in POINTS:
            warm = solve(train, op).to_dict()
            _clear_caches()
            assert solve(train, op).to_dict() == warm
    # and the trains differ where they should
    efficiencies = {round(solve(t, POINTS[0]).efficiency, 12) for t in trains}
    assert len(efficiencies) == 3


@pytest.mark.parametrize("op", POINTS)
def test_the_point_evaluation_equals_the_array_code(op):
    """solver.point evaluates one point in floats; the array code must give the same numbers bit for bit."""
    train, _ = brandenberger_1952()
    mats = assembly.matrices(train, op.external_shafts)
    speeds = solve_module.solve_speeds(mats, op.speeds)
    n = np.array([[speeds[s]] for s in train.shafts])
    torques = solve_module.given_torques(op, speeds)
    solver = solve_module.torque_solver(mats, list(torques), None)
    x = solver.torques(np.array(list(torques.values())))[:, None]
    for pattern in (None, (1, 1), (1, -1), (-1, 0)):
        fast = point.evaluate_point(mats, n[:, 0].tolist(), x[:, 0].tolist(), pattern, torques)
        slow = evaluate(mats, n, x, None if pattern is None else np.array(pattern)[:, None],
                        {s: np.array([v]) for s, v in torques.items()})
        for name in ("x", "torques", "powers", "relative", "rolling", "coupling", "loss", "pattern", "direction"):
            a, b = getattr(fast, name), getattr(slow, name)
            assert a.shape == b.shape and np.array_equal(a, b) and np.array_equal(np.signbit(a), np.signbit(b)), name


def _points(count: int, seed: int = 3):
    rng = np.random.default_rng(seed)
    return (rng.uniform(200.0, 3000.0, count) * rng.choice([-1.0, 1.0], count),
            rng.uniform(1.0, 30.0, count) * rng.choice([-1.0, 1.0], count))


def test_blocks_of_a_batch_give_the_numbers_of_one_block(monkeypatch):
    train, _ = brandenberger_1952()
    speed, torque = _points(2 * batch.BLOCK + 17)
    efficiencies = {"planetary": {"mesh": np.linspace(0.9, 0.99, speed.size), "bearing": 0.99}}

    def run():
        return (solve_batch(train, speeds={"II": speed}, torques={"II": torque}, connected=["I"]),
                solve_batch(train, speeds={"II": speed}, torques={"II": torque}, connected=["I"],
                            efficiencies=efficiencies))

    blocks = run()
    monkeypatch.setattr(batch, "BLOCK", 10 * speed.size)
    whole = run()
    for b, w in zip(blocks, whole):
        assert b.patterns == w.patterns == 2
        for name in ("speeds", "torques", "powers", "port_torques", "losses"):
            got, want = getattr(b, name), getattr(w, name)
            assert list(got) == list(want)
            assert all(np.array_equal(got[k], want[k]) for k in want), name
        for name in ("input_power", "output_power", "loss", "efficiency", "self_locking"):
            assert np.array_equal(getattr(b, name), getattr(w, name), equal_nan=True), name
        assert {e: list(p) for e, p in b.loss_sources.items()} == {e: list(p) for e, p in w.loss_sources.items()}


def test_an_error_in_a_later_block_names_its_point_in_the_whole_batch():
    train, _ = brandenberger_1952()
    speed, _ = _points(batch.BLOCK + 40)
    speed[batch.BLOCK + 5] = 0.0  # a power given where the shaft stands still
    with pytest.raises(OperatingPointError, match=rf"stands still at point {batch.BLOCK + 5}\b"):
        solve_batch(train, speeds={"II": speed}, powers={"II": 2000.0}, drives=["II"], loads=["I"])


@pytest.mark.parametrize("example", ["brandenberger_1952.toml", "toyota_prius_power_split.toml"])
def test_one_point_of_solve_equals_the_array_code_bit_for_bit(example):
    """solve takes its one point through the speed and torque operators in Python floats where one speed
    or torque is given (a product per entry, BLAS's numbers) and through numpy where more are (BLAS may
    fuse a multiply and an add): every speed, torque and power equals solve_batch's on that point, bit for
    bit. The Prius file gives two speeds (engine and wheels), the demo one."""
    from pathlib import Path

    from epicyclic.io import load_train_file

    train_file = load_train_file(Path(__file__).parents[2] / "examples" / example)
    op = train_file.operating_point
    solution = train_file.solve()
    one = {group: {s: np.array([v]) for s, v in getattr(op, group).items()} for group in ("speeds", "torques", "powers")}
    batch_solution = solve_batch(train_file.train, **one, drives=op.drives, loads=op.loads, connected=op.connected)
    for shaft in train_file.train.shafts:
        for quantity in ("speeds", "torques", "powers"):
            scalar = getattr(solution.shafts[shaft], quantity[:-1])
            array = float(getattr(batch_solution, quantity)[shaft][0])
            assert scalar == array and np.signbit(scalar) == np.signbit(array), (shaft, quantity)
