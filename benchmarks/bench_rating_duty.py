"""All failure modes of every mesh of the 8HP example in every gear over a 100-case duty cycle (issue 28).

examples/rating/zf_8hp70_rating.toml (examples/zf_8hp70_geometry.toml with a ``[rating]`` table that
asks for micropitting, ISO/TS 6336-22, and scuffing, ISO/TS 6336-20/-21): 4 simple sets, 8 meshes,
9 gears; the duty cycle is 100 load cases per gear (input speed 800 … 6000 1/min, input torque
20 … 400 N·m, seeded).  Each mesh is rated for pitting and tooth root (ISO 6336-2/-3, method B),
micropitting (S_λ) and scuffing by the integral (S_intS) and the flash temperature (S_B) method; a
mesh that turns as a block in a gear has no film and is not rated for those (said in its notes).
Both ways rate the same solved operating points (the solving is not timed):

* vectorised: one :func:`epicyclic.rating.rate_batch` per gear over a
  :class:`~epicyclic.solver.batch.BatchSolution` of the 100 cases (every factor an array), the way
  the duty-cycle rating (:func:`epicyclic.rating.duty_damage.gear_damages`) rates its cases;
* per-case loop: :func:`epicyclic.rating.rate_solution` for each case's Solution, the mesh inputs
  (geometry, tooth forms, materials) built once and reused, as a user's loop would.

The results are checked to agree: S_H and S_F of every gear of every mesh and the safety of every
failure mode, rtol 1e-9.

Run:  PYTHONPATH=src .venv/bin/python benchmarks/bench_rating_duty.py [cases] [repeats]
"""

from __future__ import annotations

import sys
import time
import warnings

import numpy as np

from epicyclic import OperatingPoint, solve
from epicyclic.io import load_train_file
from epicyclic.rating import mesh_inputs, rate_batch, rate_solution
from epicyclic.solver.batch import solve_batch

FILE = "examples/rating/zf_8hp70_rating.toml"


def _safeties(rating, k=None):
    """Every safety of the rating as one flat array (case k of a batch, or the case of a Solution)."""
    out = []
    for m in rating.meshes:
        for g in m.gears:
            out += [g.S_H, g.S_F]
        out += [mode.value for mode in m.modes]
    values = [np.asarray(x, dtype=float).reshape(-1) for x in out]
    return np.array([v[k] if k is not None and v.size > 1 else v[0] for v in values])


def main(cases: int = 100, repeats: int = 3) -> None:
    f = load_train_file(FILE)
    spec = f.rating
    rng = np.random.default_rng(28)
    speed, torque = rng.uniform(800.0, 6000.0, cases), rng.uniform(20.0, 400.0, cases)
    planned = mesh_inputs(f.geometry, spec)
    gears = list(f.transmission.schedule)
    batches, points = {}, {}
    for gear in gears:
        train = f.transmission.train_in_gear(f.train, gear)
        batches[gear] = solve_batch(train, speeds={"in": speed}, torques={"in": torque}, drives=["in"],
                                    loads=["out"])
        points[gear] = [solve(train, OperatingPoint(speeds={"in": s}, torques={"in": t}, drives=["in"],
                                                    loads=["out"])) for s, t in zip(speed, torque)]
    warnings.simplefilter("ignore")  # the illustrative design leaves some ranges of validity (warned by the CLI)
    best_batch = best_loop = float("inf")
    for _ in range(repeats):
        start = time.process_time()
        vectorised = {g: rate_batch(batches[g], f.geometry, spec, gear=g, planned=planned) for g in gears}
        best_batch = min(best_batch, time.process_time() - start)
        start = time.process_time()
        looped = {g: [rate_solution(p, f.geometry, spec, gear=g, planned=planned) for p in points[g]] for g in gears}
        best_loop = min(best_loop, time.process_time() - start)
    agree = all(np.allclose(_safeties(vectorised[g], k), _safeties(looped[g][k]), rtol=1e-9)
                for g in gears for k in range(cases))
    meshes = len(planned[0])
    modes = sum(len(m.modes) for g in gears for m in vectorised[g].meshes)
    idle = sum(1 for g in gears for m in vectorised[g].meshes if not m.modes)
    ratings = len(gears) * meshes * cases
    print(f"file                          {FILE}")
    print(f"gears × meshes × cases        {len(gears)} × {meshes} × {cases} = {ratings} mesh ratings")
    print(f"failure modes rated           pitting, root on all; micropitting, scuffing (integral, flash): "
          f"{modes} mode ratings × {cases} cases ({idle} gear-meshes turn as a block: not rated)")
    print(f"vectorised (rate_batch)       {best_batch * 1e3:10.1f} ms   ({best_batch / ratings * 1e6:.1f} µs/mesh-case)")
    print(f"per-case loop (rate_solution) {best_loop * 1e3:10.1f} ms   ({best_loop / ratings * 1e6:.1f} µs/mesh-case)")
    print(f"speed-up                      {best_loop / best_batch:10.1f} ×   (best of {repeats}, CPU time)")
    print(f"results agree                 {agree!s:>10}")
    if not agree:
        raise SystemExit("vectorised and per-case ratings disagree")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 100, int(sys.argv[2]) if len(sys.argv) > 2 else 3)
