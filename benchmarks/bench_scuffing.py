"""Scuffing (integral and flash temperature methods) of one mesh over many load cases: batch vs per-case loop.

The sun-planet mesh of the docs' planetary set (z = 21/39, m = 3 mm, b = 40 mm) rated with ``rate_mesh``
over N load cases (torque and speed per case) in one call, against a Python loop of ``rate_mesh`` per case;
the loop's S_intS and S_B agree with the batch to round-off (checked).  The ISO 6336 pitting/root rating
alone (no ``scuffing``) is timed too, to show what the two temperature methods add.

Run:  .venv/bin/python benchmarks/bench_scuffing.py [cases]
"""

from __future__ import annotations

import sys
import time
import warnings

import numpy as np

from epicyclic import PlanetarySet
from epicyclic.geometry import SetGeometry
from epicyclic.rating import MeshInput, RatingSpec, RatingWarning, rate_mesh
from epicyclic.rating.scuffing import ScuffingSpec


def main(cases: int = 100) -> None:
    pset = PlanetarySet.simple("P", sun="in", ring="r", carrier="out", z_sun=21, z_planet=39, z_ring=99)
    mesh = SetGeometry.create(pset, 3.0, face_width=40.0, x_sun=0.25, x_planet=0.1, x_ring=-0.45).meshes[0]
    base = {"material": "18CrNiMo7-6", "flank_roughness": 3.0, "root_roughness": 10.0, "viscosity_40": 220.0,
            "viscosity_100": 19.0, "application_factor": 1.25}
    scuffing = RatingSpec(**base, scuffing=ScuffingSpec(oil_temperature=90.0, roughness_Ra=0.5, load_stage=10))
    rng = np.random.default_rng(0)
    torque, speed = rng.uniform(50.0, 250.0, cases), rng.uniform(300.0, 2000.0, cases)
    warnings.simplefilter("ignore", RatingWarning)
    for label, spec in (("ISO 6336 only", RatingSpec(**base)), ("with scuffing", scuffing)):
        inp = MeshInput("P", mesh, 40.0, ("sun", "planet"), spec)
        rate_mesh(inp, torque[:2], speed[:2])                                    # warm-up
        start = time.perf_counter()
        batch = rate_mesh(inp, torque, speed)
        t_batch = time.perf_counter() - start
        start = time.perf_counter()
        loop = [rate_mesh(inp, float(t), float(n)) for t, n in zip(torque, speed)]
        t_loop = time.perf_counter() - start
        if spec.scuffing is not None:
            for mode in ("scuffing_integral", "scuffing_flash"):
                s_batch = batch.mode(mode).value
                s_loop = np.array([r.mode(mode).value for r in loop])
                assert np.allclose(s_batch, s_loop, rtol=1e-12), f"batch and loop differ ({mode})"
        print(f"{label:14s} {cases} cases: batch {t_batch * 1e3:8.2f} ms, loop {t_loop * 1e3:8.1f} ms, "
              f"speed-up {t_loop / t_batch:6.1f}x")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 100)
