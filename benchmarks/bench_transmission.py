"""Benchmark: ZF 8HP 70, every gear × 10^6 operating points, batch vs a per-point loop of solve.

Run:  .venv/bin/python benchmarks/bench_transmission.py [points]

* batch: :func:`epicyclic.transmission.batch.solve_gears` (one engine batch solve per
  gear over numpy arrays of input speed and torque), 10^6 points per gear, drive.
* baseline: a Python loop of :func:`epicyclic.solve` per point and gear.  It is timed
  on a subset (200 points per gear) and extrapolated linearly to 10^6 points per gear;
  the script says so in its output.  The subset's efficiencies are checked against the
  batch to 1e-10.
* exploration: :func:`epicyclic.transmission.explore` on the 8HP (4 sets, 5 elements)
  and on the 8HP plus one extra clutch (4 sets, 6 elements), best of 20.
"""

from __future__ import annotations

import platform
import sys
import time

import numpy as np

from epicyclic import Clutch, GearTrain, OperatingPoint, solve
from epicyclic.transmission import explore
from epicyclic.transmission.batch import solve_gears
from epicyclic.transmission.library import build, build_train


def main(points: int = 1_000_000, loop_points: int = 200) -> None:
    t = build("zf_8hp70", 0.97)
    rng = np.random.default_rng(0)
    n = rng.uniform(600.0, 6500.0, points)
    m = rng.uniform(20.0, 700.0, points)
    print(f"epicyclic transmission benchmark — Python {platform.python_version()}, numpy {np.__version__}, "
          f"{platform.machine()}")
    print(f"ZF 8HP 70, eta0 = 0.97 per set, {len(t.gears)} gears × {points:,} operating points (drive)")

    start = time.perf_counter()
    res = solve_gears(t, input_speed=n, input_torque=m)
    batch_s = time.perf_counter() - start
    total = points * len(t.gears)
    print(f"batch     : {batch_s:8.2f} s for {total:,} gear-points  ({total / batch_s:,.0f} points/s)")

    start = time.perf_counter()
    for gear in t.gears:
        train = t.gear_train(gear)
        for k in range(loop_points):
            sol = solve(train, OperatingPoint(speeds={t.input: float(n[k])}, torques={t.input: float(m[k])},
                                              drives=[t.input], loads=[t.output]))
            assert abs(sol.efficiency - res.efficiency(gear)[k]) < 1e-10
    loop_s = time.perf_counter() - start
    per_point = loop_s / (loop_points * len(t.gears))
    print(f"loop      : {loop_s:8.2f} s for {loop_points * len(t.gears):,} gear-points measured "
          f"({per_point * 1e3:.2f} ms/point); extrapolated to {total:,}: {per_point * total:,.0f} s")
    print(f"speed-up  : {per_point * total / batch_s:,.0f}× (batch vs extrapolated loop); "
          f"subset efficiencies agree to 1e-10")

    for label, target in (("8HP, 4 sets, 5 elements", t),
                          ("8HP + clutch F, 4 sets, 6 elements",
                           GearTrain(build_train("zf_8hp70").elements + (Clutch("F", "s12", "c3", engaged=False),)))):
        best = float("inf")
        for _ in range(20):
            start = time.perf_counter()
            ex = explore(target) if label.startswith("8HP,") else explore(target, "in", "out")
            best = min(best, time.perf_counter() - start)
        print(f"explore   : {label}: {ex.states} states, {len(ex)} drives, best of 20 {best * 1e3:.2f} ms")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000)
