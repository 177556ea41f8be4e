"""ISO 6336 rating of every mesh of the 8HP example in every gear over a 100-case duty cycle (issue 23).

examples/zf_8hp70_geometry.toml (4 simple sets, 8 meshes) in each of its 9 gears; the duty cycle
is 100 load cases (input speed 800 … 6000 1/min, input torque 20 … 400 N·m, seeded).  Both ways
rate the same solved operating points (the solving is not timed):

* vectorised: one :func:`epicyclic.rating.rate_batch` per gear over a
  :class:`~epicyclic.solver.batch.BatchSolution` of the 100 cases (every factor an array);
* per-case loop: :func:`epicyclic.rating.rate_solution` for each case's Solution, the mesh inputs
  (geometry, tooth forms, materials) built once and reused, as a user's loop would.

The results are checked to agree (S_H and S_F of every gear of every mesh, rtol 1e-9).

Run:  .venv/bin/python benchmarks/bench_rating.py [cases]
"""

from __future__ import annotations

import sys
import time
import warnings

import numpy as np

from epicyclic import OperatingPoint, solve
from epicyclic.io import load_train_file
from epicyclic.rating import RatingSpec, mesh_inputs, rate_batch, rate_solution
from epicyclic.solver.batch import solve_batch

SPEC = RatingSpec(material="18CrNiMo7-6", flank_roughness=3.0, root_roughness=10.0, viscosity_40=35.0,
                  application_factor=1.25)


def main(cases: int = 100, repeats: int = 5) -> None:
    f = load_train_file("examples/zf_8hp70_geometry.toml")
    rng = np.random.default_rng(23)
    speed, torque = rng.uniform(800.0, 6000.0, cases), rng.uniform(20.0, 400.0, cases)
    planned = mesh_inputs(f.geometry, SPEC)
    gears = list(f.transmission.schedule)
    batches, points = {}, {}
    for gear in gears:
        train = f.transmission.train_in_gear(f.train, gear)
        batches[gear] = solve_batch(train, speeds={"in": speed}, torques={"in": torque}, drives=["in"],
                                    loads=["out"])
        points[gear] = [solve(train, OperatingPoint(speeds={"in": s}, torques={"in": t}, drives=["in"],
                                                    loads=["out"])) for s, t in zip(speed, torque)]
    warnings.simplefilter("ignore")
    best_batch = best_loop = float("inf")
    for _ in range(repeats):
        start = time.process_time()
        vectorised = {g: rate_batch(batches[g], f.geometry, SPEC, gear=g, planned=planned) for g in gears}
        best_batch = min(best_batch, time.process_time() - start)
        start = time.process_time()
        looped = {g: [rate_solution(p, f.geometry, SPEC, gear=g, planned=planned) for p in points[g]] for g in gears}
        best_loop = min(best_loop, time.process_time() - start)
    agree = all(np.allclose(vectorised[g].meshes[m].gears[i].S_H[k], looped[g][k].meshes[m].gears[i].S_H, rtol=1e-9)
                and np.allclose(vectorised[g].meshes[m].gears[i].S_F[k], looped[g][k].meshes[m].gears[i].S_F,
                                rtol=1e-9)
                for g in gears for k in range(cases) for m in range(len(planned[0])) for i in (0, 1))
    ratings = len(gears) * len(planned[0]) * cases
    print(f"gears × meshes × cases       {len(gears)} × {len(planned[0])} × {cases} = {ratings} mesh ratings")
    print(f"vectorised (rate_batch)      {best_batch * 1e3:10.1f} ms   ({best_batch / ratings * 1e6:.1f} µs/mesh-case)")
    print(f"per-case loop (rate_solution){best_loop * 1e3:10.1f} ms   ({best_loop / ratings * 1e6:.1f} µs/mesh-case)")
    print(f"speed-up                     {best_loop / best_batch:10.1f} ×   (best of {repeats}, CPU time)")
    print(f"results agree                {agree!s:>10}")
    if not agree:
        raise SystemExit("vectorised and per-case ratings disagree")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 100)
