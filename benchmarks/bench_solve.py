"""Scalar `solve` of the demo train (Brandenberger 1952, Bild 10), against its closed form.

`solve(train, op)` does the whole analysis of one operating point: kinematics, the lossless and the
lossy statics with the loss directions, the zero rule, self-locking, circulating power, a Solution
object with every shaft and element. The baseline is the same train's closed form in plain Python
(`closed_form` of bench_batch_closed_form.py, one point): what the numbers cost without a general
solver. Both are timed as the best of several rounds of many calls.

Run:  .venv/bin/python benchmarks/bench_solve.py
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from bench_batch_closed_form import closed_form  # noqa: E402

from epicyclic import solve  # noqa: E402
from epicyclic.demo import brandenberger_1952  # noqa: E402


def per_call(function, calls: int = 500, rounds: int = 7) -> float:
    best = float("inf")
    for _ in range(rounds):
        start = time.perf_counter()
        for _ in range(calls):
            function()
        best = min(best, (time.perf_counter() - start) / calls)
    return best


def main() -> None:
    train, op = brandenberger_1952()
    solution = solve(train, op)
    speed, torque = np.array([1500.0]), np.array([solution.torque("II")])
    closed = closed_form(speed, torque)
    assert abs(closed["efficiency"][0] - solution.efficiency) < 1e-12
    t_solve = per_call(lambda: solve(train, op))
    t_closed = per_call(lambda: closed_form(speed, torque))
    print(f"solve(train, op), Bild 10           {t_solve * 1e6:9.1f} µs per call")
    print(f"closed form of the same point      {t_closed * 1e6:9.1f} µs per call (numpy, one point)")
    print(f"ratio                              {t_solve / t_closed:9.1f}")


if __name__ == "__main__":
    main()
