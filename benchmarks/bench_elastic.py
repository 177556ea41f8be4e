"""The elastic set (issue 29): modes of a 7-planet set, 10⁴ Monte-Carlo load-sharing draws, a 1000-speed Campbell diagram.

Each against a naive per-point loop in the same run, results checked to agree:

* modes: :func:`epicyclic.elastic.natural_modes` (stiffness K = Vᵀ diag(k) V in one product,
  ``scipy.linalg.eigh``, classification, strain energy) of the Lin & Parker 1999 set with 7 planets
  — against assembling K entry by entry in Python loops and ``scipy.linalg.eig`` (general solver);
  goal ≤ 10 ms;
* Monte Carlo: :func:`epicyclic.elastic.monte_carlo_sharing`, 10 000 draws of a 5-planet set (pin
  position and tooth thickness errors ± 10 µm) solved together — against
  :func:`epicyclic.elastic.load_sharing` draw by draw on the first 300 draws, scaled to 10 000;
  goal ≤ 1 s;
* Campbell: :func:`epicyclic.elastic.frequencies_at_speeds` over 1000 carrier speeds in one batched
  eigenvalue call — against one call per speed; goal ≤ 1 s.

Times are wall seconds (``time.perf_counter``), best of ``repeats`` (the goals are wall times).

Run:  .venv/bin/python benchmarks/bench_elastic.py [repeats]
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np
import scipy.linalg

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from elastic_cases import lin_parker_1999  # noqa: E402

from epicyclic.elastic import (  # noqa: E402
    PlanetErrors,
    PlanetaryLumpedModel,
    Tolerances,
    frequencies_at_speeds,
    load_sharing,
    monte_carlo_sharing,
    natural_modes,
)


def _best(fn, repeats: int) -> tuple[float, object]:
    """Best wall time (``time.perf_counter``) of ``repeats`` runs, and the result."""
    best, out = float("inf"), None
    for _ in range(repeats):
        start = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - start)
    return best, out


def _naive_modes(model: PlanetaryLumpedModel) -> np.ndarray:
    names, k, v = model.springs()
    n = model.size
    stiffness = [[0.0] * n for _ in range(n)]
    for s in range(len(k)):
        for i in range(n):
            for j in range(n):
                stiffness[i][j] += k[s] * v[s, i] * v[s, j]
    w = scipy.linalg.eig(np.array(stiffness), model.mass_matrix(), right=True)[0]
    return np.sort(np.sqrt(np.clip(w.real, 0.0, None))) / (2 * math.pi)


def _sharing_set() -> PlanetaryLumpedModel:
    m = lin_parker_1999(5)
    return PlanetaryLumpedModel(m.carrier, m.ring, m.sun, m.planet, m.planet_angles, m.sun_mesh, m.ring_mesh,
                                m.planet_bearing, supports={"carrier": (1e8, 0.0), "ring": (1e8, 0.0),
                                                            "sun": (0.0, 0.0)},
                                sun_pressure_angle=m.sun_pressure_angle, ring_pressure_angle=m.ring_pressure_angle)


def main(repeats: int = 5) -> None:
    model7 = lin_parker_1999(7)
    t_fast, modes = _best(lambda: natural_modes(model7), repeats * 4)
    t_naive, naive = _best(lambda: _naive_modes(model7), repeats)
    assert np.allclose(modes.frequencies, naive, rtol=1e-7, atol=1e-3)
    print(f"modes, 7 planets ({model7.size} DOF): natural_modes {t_fast * 1e3:.2f} ms, naive loop + eig "
          f"{t_naive * 1e3:.2f} ms ({t_naive / t_fast:.1f}x); goal <= 10 ms: {'met' if t_fast <= 0.01 else 'NOT met'}")

    model5 = _sharing_set()
    tol = Tolerances(pin_position=10.0, tooth_thickness=10.0)
    draws, sample = 10_000, 300
    t_mc, mc = _best(lambda: monte_carlo_sharing(model5, 400.0, tol, draws=draws, seed=29), repeats)
    drawn = tol.draw(5, draws, np.random.default_rng(29))

    def one_by_one():
        return np.array([load_sharing(model5, 400.0, PlanetErrors(
            pin_radial=tuple(drawn["pin_radial"][b]), pin_tangential=tuple(drawn["pin_tangential"][b]),
            tooth_thickness=tuple(drawn["tooth_thickness"][b]))).k_gamma for b in range(sample)])

    t_loop, looped = _best(one_by_one, max(1, repeats // 2))
    assert np.allclose(looped, mc.k_gamma[:sample], rtol=1e-9)
    scaled = t_loop * draws / sample
    print(f"Monte Carlo, 5 planets, {draws} draws: batched {t_mc:.3f} s (p95 K_gamma {mc.percentile(95):.4f}), "
          f"draw by draw {t_loop:.3f} s for {sample} -> {scaled:.2f} s for {draws} ({scaled / t_mc:.1f}x); "
          f"goal <= 1 s: {'met' if t_mc <= 1.0 else 'NOT met'}")

    model4 = lin_parker_1999(4)
    speeds = np.linspace(0.0, 600.0, 1000)                # carrier speed, rad/s
    t_batch, batch = _best(lambda: frequencies_at_speeds(model4, speeds), repeats)
    t_points, points = _best(lambda: np.vstack([frequencies_at_speeds(model4, s) for s in speeds]),
                             max(1, repeats // 2))
    assert np.allclose(batch, points, rtol=1e-9, atol=1e-6)
    print(f"Campbell, 4 planets ({model4.size} DOF), 1000 speeds with gyroscopic terms: batched {t_batch:.3f} s, "
          f"per speed {t_points:.3f} s ({t_points / t_batch:.1f}x); goal <= 1 s: "
          f"{'met' if t_batch <= 1.0 else 'NOT met'}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 5)
