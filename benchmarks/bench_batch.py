"""Batch solver vs a per-point Python loop of the same solver (issue: engine, item 5).

Efficiency map of Brandenberger's closed train (1952, Bild 10) over 10**6 operating points:
speed of the drive shaft II and its power, both directions of power flow (drive at II and
drive at I alternate), so more than one loss-direction pattern is solved.

The per-point loop runs `epicyclic.solve` on a subset and is extrapolated linearly to 10**6 points
(running it in full would take many minutes); the batch results on that subset are checked
against the loop to round-off.

Run:  .venv/bin/python benchmarks/bench_batch.py [points]
"""

from __future__ import annotations

import sys
import time

import numpy as np

from epicyclic import OperatingPoint, solve
from epicyclic.demo import brandenberger_1952
from epicyclic.solver.batch import solve_batch


def operating_points(count: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    speed = rng.uniform(200.0, 3000.0, count) * rng.choice([-1.0, 1.0], count)
    torque = rng.uniform(1.0, 30.0, count) * rng.choice([-1.0, 1.0], count)  # N·m at II; sign sets the flow
    return speed, torque


def main(points: int = 1_000_000, loop_points: int = 2_000) -> None:
    train, _ = brandenberger_1952()
    speed, torque = operating_points(points)

    solve_batch(train, speeds={"II": speed[:1000]}, torques={"II": torque[:1000]}, connected=["I"])  # warm-up
    start = time.perf_counter()
    result = solve_batch(train, speeds={"II": speed}, torques={"II": torque}, connected=["I"])
    batch_time = time.perf_counter() - start

    start = time.perf_counter()
    loop_eff = []
    for k in range(loop_points):
        op = OperatingPoint(speeds={"II": speed[k]}, torques={"II": torque[k]}, connected=["I"])
        sol = solve(train, op)
        loop_eff.append(np.nan if sol.efficiency is None else sol.efficiency)
    loop_time = (time.perf_counter() - start) / loop_points * points

    agree = np.allclose(np.array(loop_eff), result.efficiency[:loop_points], rtol=1e-9, equal_nan=True)
    print(f"points                      {points:>12,d}")
    print(f"loss-direction patterns     {result.patterns:>12d}")
    print(f"batch solve                 {batch_time:>12.3f} s   ({batch_time / points * 1e6:.3f} µs/point)")
    print(f"per-point loop (from {loop_points} pts) {loop_time:>9.1f} s   ({loop_time / points * 1e6:.1f} µs/point, extrapolated)")
    print(f"speed-up                    {loop_time / batch_time:>12.0f} ×")
    print(f"results agree on the subset {agree!s:>12}")
    eff = result.efficiency[result.defined]
    print(f"efficiency range            {eff.min():.4f} … {eff.max():.4f}  ({int(result.self_locking.sum())} self-locking points)")
    if not agree:
        raise SystemExit("batch and loop disagree")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000)
