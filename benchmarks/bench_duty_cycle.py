"""Duty cycle of the ZF 8HP 70 with geometry: the vectorised analysis vs a per-case loop (issue 23).

``examples/zf_8hp70_geometry.toml`` (Schlenk mesh friction, planet-bearing friction and drag in all four
sets; planet and carrier bearings rated per ISO 281) over a duty cycle of N load cases spread over the
nine gears, random input speeds 1000–4500 1/min and torques 30–400 N·m (seeded).

* vectorised: :func:`epicyclic.rating.analyse_duty_cycle` — one batch solve with the loss models per gear,
  then the bearing loads of every case;
* per-case loop: for each case :func:`epicyclic.losses.solve_with_losses`, the energies, and the bearing
  loads by :func:`~epicyclic.geometry.planetary_forces` / :func:`~epicyclic.geometry.share_planets` of
  that solution, the lives summed as the analysis sums them.

Both give the same energies and bearing lives (checked to 1e-7 relative); the figures are printed with
their ratio.  A second pair of runs adds the tooth rating (ISO 6336 Method B of every mesh, case-carburised
18CrNiMo7-6 throughout, an illustrative RatingSpec) and the flank/root damage sums: vectorised, one
:func:`~epicyclic.rating.train.rate_batch` per gear; the loop, one :func:`~epicyclic.rating.train.rate_solution`
per case (the damage sums compared to 1e-7).

Run:  .venv/bin/python benchmarks/bench_duty_cycle.py [cases [repeats]]   (best of repeats, default 100 3)
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from epicyclic import OperatingPoint
from epicyclic.geometry import planetary_forces, share_planets
from epicyclic.io import load_train_file
from epicyclic.losses import solve_with_losses
from epicyclic.rating import DutyCycle, LoadCase, analyse_duty_cycle
from epicyclic.rating.bearing_life import (
    basic_rating_life,
    rating_life_hours,
    spectrum_life,
)
from epicyclic.rating.life_factors import miner_damage
from epicyclic.rating.spec import RatingSpec
from epicyclic.rating.train import mesh_inputs, rate_solution

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "zf_8hp70_geometry.toml"


def duty_cycle(train_file, cases: int, seed: int = 0) -> DutyCycle:
    rng = np.random.default_rng(seed)
    gears = list(train_file.transmission.schedule)
    t = train_file.transmission
    out = []
    for k in range(cases):
        op = OperatingPoint(speeds={t.input: float(rng.uniform(1000.0, 4500.0))},
                            torques={t.input: float(rng.uniform(30.0, 400.0))}, drives=[t.input], loads=[t.output])
        out.append(LoadCase(f"case {k + 1}", op, gears[k % len(gears)], hours=float(rng.uniform(1.0, 100.0))))
    return DutyCycle(tuple(out))


def per_case_loop(f, duty: DutyCycle, spec: RatingSpec | None = None):
    """The naive baseline: one solve per case, the forces (and the rating) of that solution, sums at the end."""
    energy_in, lives, stresses = [], {}, {}
    hours = duty.hours
    planned = mesh_inputs(f.geometry, spec) if spec is not None else None
    for k, case in enumerate(duty.cases):
        train = f.transmission.train_in_gear(f.train, case.gear)
        sol = solve_with_losses(train, case.operating_point, f.losses)
        energy_in.append(sol.input_power * hours[k] / 1000.0)
        names = {e.name for e in train.elements}
        forces = {s: planetary_forces(sol, s, g) for s, g in f.geometry.items() if s in names}
        forces = share_planets(forces, {s: f.geometry[s] for s in forces})
        for s, ratings in f.bearings.items():
            pset = f.geometry[s].planetary_set
            k_planet = pset.teeth.planet_factors[0]
            n_rel = abs(k_planet * (sol.speed(pset.sun) - sol.speed(pset.carrier)))
            for body in forces[s].bodies:
                if "planet" in ratings:
                    r = ratings["planet"]
                    life = rating_life_hours(basic_rating_life(r.dynamic_load_rating, body.bearing_load,
                                                               r.life_exponent), n_rel)
                    lives.setdefault((s, body.index), []).append(float(life))
        if spec is None:
            continue
        for mesh in rate_solution(sol, f.geometry, spec, planned=planned).meshes:
            for i, gear in enumerate(mesh.gears):
                g = gear.factors
                ratio = g["sigma_H"].value / (g["sigma_HG"].value / g["Z_NT"].value)
                stresses.setdefault((mesh.element, mesh.mesh, gear.gear, i), []).append(
                    (ratio, g["N_L"].value / spec.life * hours[k]))
    q = duty.shares
    damage = {}
    if spec is not None:
        curves = {(p.input.element, p.input.name): p.input.static["Z_curves"] for p in planned[0]}
        damage = {key[:3]: miner_damage(v, curves[key[:2]][key[3]], 1.0) for key, v in stresses.items()}
    return np.array(energy_in), {key: spectrum_life(v, q) for key, v in lives.items()}, damage


def main(cases: int = 100, repeats: int = 3) -> None:
    import warnings

    warnings.simplefilter("ignore", RuntimeWarning)  # K_v at standstill divides by zero (no effect on D)
    f = load_train_file(EXAMPLE)
    duty = duty_cycle(f, cases)
    kwargs = {"schedule": f.transmission, "losses": f.losses, "geometry": f.geometry, "bearings": f.bearings}
    analyse_duty_cycle(f.train, duty_cycle(f, 9), **kwargs)  # warm-up
    best_vector = best_loop = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        result = analyse_duty_cycle(f.train, duty, **kwargs)
        best_vector = min(best_vector, time.perf_counter() - start)
        start = time.perf_counter()
        loop_energy, loop_lives, _ = per_case_loop(f, duty)
        best_loop = min(best_loop, time.perf_counter() - start)
    agree = np.allclose(result.energy.input, loop_energy, rtol=1e-7)
    planets = {(b.element, int(b.position.split()[1]) - 1): b.life_hours for b in result.bearings if b.role == "planet"}
    agree = agree and all(np.isclose(planets[key], life, rtol=1e-7) for key, life in loop_lives.items())
    print(f"load cases                  {cases:>10d}  (9 gears, {len(result.bearings)} bearings rated)")
    print(f"vectorised analysis         {best_vector * 1e3:>10.1f} ms  ({best_vector / cases * 1e3:.2f} ms/case)")
    print(f"per-case loop               {best_loop * 1e3:>10.1f} ms  ({best_loop / cases * 1e3:.2f} ms/case)")
    print(f"speed-up                    {best_loop / best_vector:>10.1f} x")
    print(f"results agree               {agree!s:>10}")
    print(f"cycle efficiency            {result.cycle_efficiency:>10.4f}")
    spec = RatingSpec(material="18CrNiMo7-6", flank_roughness=3.0, root_roughness=10.0, viscosity_40=32.0,
                      application_factor=1.1, life=6000.0)
    rated_vector = rated_loop = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        rated = analyse_duty_cycle(f.train, duty, rating=spec, **kwargs)
        rated_vector = min(rated_vector, time.perf_counter() - start)
        start = time.perf_counter()
        _, _, damage = per_case_loop(f, duty, spec)
        rated_loop = min(rated_loop, time.perf_counter() - start)
    same = all(np.isclose(d.flank_damage, damage[(d.element, d.mesh, d.gear)], rtol=1e-7) for d in rated.damage)
    worst = max(rated.damage, key=lambda d: d.flank_damage)
    print(f"with the tooth rating       {len(rated.damage):>10d}  gear flanks and roots, damage sums")
    print(f"vectorised analysis         {rated_vector * 1e3:>10.1f} ms")
    print(f"per-case loop               {rated_loop * 1e3:>10.1f} ms")
    print(f"speed-up                    {rated_loop / rated_vector:>10.1f} x")
    print(f"damage sums agree           {same!s:>10}   (largest D_H {worst.flank_damage:.3g}: {worst.element} "
          f"{worst.mesh} {worst.gear})")
    if not (agree and same):
        raise SystemExit("vectorised and per-case results disagree")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 100, int(sys.argv[2]) if len(sys.argv) > 2 else 3)
