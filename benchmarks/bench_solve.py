"""Scalar `solve` of the demo train (Brandenberger 1952, Bild 10), against its closed form.

`solve(train, op)` does the whole analysis of one operating point: kinematics, the lossless and the
lossy statics with the loss directions, the zero rule, self-locking, circulating power, a Solution
object with every shaft and element. The baseline is the same train's closed form in numpy
(`closed_form` of bench_batch_closed_form.py, one point): what the numbers cost without a general
solver. For comparison the run also times the same analysis through the array code on one point
(`solve_batch` with arrays of one entry: what `solve` cost per point before it evaluated one point in
Python floats), `solve` at 100 different operating points in turn (nothing is cached per point:
the caches hold the train's equations and prepared operators, not results), and `solve` followed by
reading the parts of the Solution that are made on first access (the circulating power, the warnings
and the lossless solution `.ideal`), i.e. the whole analysis as a report needs it. Each figure is the
best of several rounds of many calls, in CPU time (run it with OPENBLAS_NUM_THREADS=1).

Run:  OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_solve.py
"""

from __future__ import annotations

import itertools
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from bench_batch_closed_form import closed_form  # noqa: E402

from epicyclic import OperatingPoint, solve  # noqa: E402
from epicyclic.demo import brandenberger_1952  # noqa: E402
from epicyclic.solver.batch import solve_batch  # noqa: E402


def per_call(function, calls: int = 500, rounds: int = 7) -> float:
    """Seconds per call: the best of ``rounds`` rounds of ``calls`` calls, in the process's CPU time
    (single-threaded work: on a shared machine the wall clock also counts the time other processes hold
    the core, the CPU time does not)."""
    best = float("inf")
    for _ in range(rounds):
        start = time.process_time()
        for _ in range(calls):
            function()
        best = min(best, (time.process_time() - start) / calls)
    return best


def main() -> None:
    train, op = brandenberger_1952()
    solution = solve(train, op)
    speed, torque = np.array([1500.0]), np.array([solution.torque("II")])
    closed = closed_form(speed, torque)
    assert abs(closed["efficiency"][0] - solution.efficiency) < 1e-12
    one = {"speeds": {"II": speed}, "powers": {"II": np.array([op.powers["II"]])}, "drives": ["II"], "loads": ["I"]}
    assert abs(solve_batch(train, **one).efficiency[0] - solution.efficiency) < 1e-12
    points = itertools.cycle([OperatingPoint(speeds={"II": n}, powers={"II": op.powers["II"]}, drives=["II"],
                                             loads=["I"]) for n in np.linspace(300.0, 3000.0, 100)])
    t_solve = per_call(lambda: solve(train, op))

    def solve_and_read_everything():  # the parts a Solution makes on first access, made
        solved = solve(train, op)
        return solved.circulation, solved.warnings, solved.ideal.circulation, solved.ideal.warnings

    t_everything = per_call(solve_and_read_everything)
    t_many = per_call(lambda: solve(train, next(points)))
    t_array = per_call(lambda: solve_batch(train, **one))
    t_closed = per_call(lambda: closed_form(speed, torque))
    print(f"solve(train, op), Bild 10               {t_solve * 1e6:9.1f} µs per call")
    print(f"solve at 100 operating points in turn   {t_many * 1e6:9.1f} µs per call")
    print(f"solve, then every result read           {t_everything * 1e6:9.1f} µs per call "
          "(circulation, warnings, the lossless solution)")
    print(f"array code on one point (solve_batch)   {t_array * 1e6:9.1f} µs per call")
    print(f"closed form of the same point           {t_closed * 1e6:9.1f} µs per call (numpy, one point)")
    print(f"ratio solve / closed form               {t_solve / t_closed:9.1f}")


if __name__ == "__main__":
    main()
