"""Benchmark: efficiency maps of every gear of the ZF 8HP 70 with load-dependent friction and drag.

Run:  .venv/bin/python benchmarks/bench_efficiency_map.py [grid] [loop_points]

* map: :func:`epicyclic.losses.efficiency_map` on a ``grid`` × ``grid`` map (default 200 × 200 =
  40 000 points) of input speed 500–6000 1/min and input torque 10–500 N·m, for each of the 9 gears
  of ``examples/zf_8hp70_geometry.toml``: Schlenk's load- and speed-dependent friction (ISO/TR 14179-2)
  on every mesh, SKF planet-bearing friction and a drag torque on every carrier.  Each gear is a few
  batch solves (one per round of the load-dependent fixed point), vectorised over the points.
* baseline: the same model point by point — :func:`epicyclic.losses.solve_with_losses` (the scalar
  solver and the same fixed point) in a Python loop — on ``loop_points`` random points of the grid
  per gear, extrapolated linearly to the full grid (the script says so).  On those points the
  loop's efficiencies must equal the map's to 1e-9.
"""

from __future__ import annotations

import os

# Small matrices (about 20 × 20) times many points: BLAS threads only contend (on a shared 2-core machine a
# 21 × 20 @ 20 × 3600 product took 48 ms with threads, 0.2 ms without). Set before numpy is imported.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

from epicyclic import OperatingPoint  # noqa: E402
from epicyclic.io import load_train_file  # noqa: E402
from epicyclic.losses import efficiency_map, solve_with_losses  # noqa: E402

FILE = Path(__file__).resolve().parents[1] / "examples" / "zf_8hp70_geometry.toml"


def main(grid: int = 200, loop_points: int = 40) -> None:
    f = load_train_file(FILE)
    gears = f.transmission.gears
    speeds = np.linspace(500.0, 6000.0, grid)
    torques = np.linspace(10.0, 500.0, grid)
    print(f"epicyclic efficiency-map benchmark — Python {platform.python_version()}, numpy {np.__version__}, "
          f"{platform.machine()}")
    print(f"{f.title}: {len(gears)} gears × {grid} × {grid} points, Schlenk friction, SKF bearings, drag")

    start = time.perf_counter()
    maps = {gear: efficiency_map(f, speeds, torques, gear=gear) for gear in gears}
    map_s = time.perf_counter() - start
    total = grid * grid * len(gears)
    print(f"maps      : {map_s:8.2f} s for {total:,} gear-points ({total / map_s:,.0f} points/s)")

    rng = np.random.default_rng(0)
    start = time.perf_counter()
    worst = 0.0
    for gear in gears:
        train = f.transmission.train_in_gear(f.train, gear)
        emap = maps[gear]
        for _ in range(loop_points):
            i, j = int(rng.integers(grid)), int(rng.integers(grid))
            op = OperatingPoint(speeds={"in": float(speeds[j])}, torques={"in": float(torques[i])},
                                drives=["in"], loads=["out"])
            sol = solve_with_losses(train, op, f.losses)
            if sol.efficiency is None:
                assert np.isnan(emap.efficiency[i, j])
                continue
            worst = max(worst, abs(sol.efficiency - emap.efficiency[i, j]))
    loop_s = time.perf_counter() - start
    assert worst < 1e-9, worst
    per_point = loop_s / (loop_points * len(gears))
    print(f"loop      : {loop_s:8.2f} s for {loop_points * len(gears)} gear-points measured "
          f"({per_point * 1e3:.2f} ms/point); extrapolated to {total:,}: {per_point * total:,.0f} s")
    print(f"speed-up  : {per_point * total / map_s:,.0f}× (maps vs extrapolated loop); "
          f"sampled efficiencies agree to {worst:.1e}")
    for gear in gears:
        s = maps[gear].summary()
        split = ", ".join(f"{k} {100 * v:.0f} %" for k, v in s["loss_split"].items())
        print(f"  gear {gear:>2}: η {s['efficiency_min']:.4f}…{s['efficiency_max']:.4f}, losses {split}")


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:3]))
