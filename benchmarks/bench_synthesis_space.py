"""The full synthesis space of 4 simple sets and 6 shift elements, measured stratum by stratum.

The space (every tie pattern, input on a member or a separate shaft, every split into b ≥ 1 brakes
and 6 − b clutches, 2, 3 or 4 engaged per gear; 3.96 · 10¹¹ architectures) falls into strata
(engaged, separate input, brakes) whose screening costs differ by more than 10 × per architecture:
with one brake few element sets reach the reverse gear and the first level rejects almost all, with
two or three brakes many survive into the bisection.  One rate for the whole space (the
``kernel-new`` mode of ``bench_synthesis.py`` measures 2 brakes + 4 clutches with 3 and 4 engaged)
therefore misstates it; here every stratum holding more than 0.01 % of the architectures is
measured on its own random sample of mechanisms, and its time is

    (mechanisms in the stratum) × (mean CPU seconds of one mechanism's screening in the sample),

one ``screen`` call being every input/output pair and element set of the mechanism with that split.
The strata below 0.01 % (5 or 6 brakes; 0.02 % of the space together) are charged at the slowest
per-architecture cost measured.  The standard error of each stratum's mean is propagated to the
total (±1 s.e.).  Targets: the ZF 8HP 70's nine ratios with 2 and 3 engaged, the Ford 10R80's
eleven with 4 engaged (ten speeds need four engaged of six), ± 1 %; stationary ratios −4 … −1.5.
CPU time (``time.process_time``), one BLAS thread, as a Dask worker process runs.

Naive baseline in the same run: the ratio fit of up to 60 surviving placements per stratum by the
fit of commit ``BASELINE`` (the general path, a null-space solve per point, and SciPy's finite
differences), read with ``git show``, against this checkout's fit (the ratio functions of the box
and their exact derivatives); CPU seconds and whether both fit the same placements.

Run:  .venv/bin/python benchmarks/bench_synthesis_space.py [mechanisms_per_stratum=6] [levels=3] [seed=0]

``levels`` is the screening's bisection depth: 3 is the depth of every earlier full-space figure in
docs/performance.md (and of the issue's 110–130 worker-hours), 4 the spec's default for 4 sets.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time

for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")
from math import comb, sqrt

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_synthesis import FORWARD, HIGH, LOW, REVERSE, TEN_FORWARD, TEN_REVERSE, _baseline_module  # noqa: E402

from epicyclic.synthesis import SynthesisSpec, enumerate_mechanisms  # noqa: E402
from epicyclic.synthesis.fitting import combinations_of_elements, fit_ratios  # noqa: E402
from epicyclic.synthesis.boxes import _grid  # noqa: E402
from epicyclic.synthesis.search import Task, bounds, search_task  # noqa: E402
from epicyclic.synthesis.kernel import AVAILABLE  # noqa: E402
from epicyclic.synthesis.screening import layout, screen  # noqa: E402

ELEMENTS = 6
MEASURED = (1, 2, 3, 4)  # brakes; 5 and 6 hold < 0.01 % of the space


def _peak() -> float:
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def stratum_count(mechanisms: int, shafts: int, free: bool, brakes: int) -> int:
    """Architectures of one stratum: mechanisms × input/output pairs × element sets (no brake on either)."""
    members = shafts - int(free)
    pairs = members if free else members * (members - 1)
    return mechanisms * pairs * comb(shafts - 2, brakes) * comb(comb(shafts, 2), ELEMENTS - brakes)


def _spec(engaged: int, free: bool, brakes: int, levels: int) -> SynthesisSpec:
    forward, reverse = (TEN_FORWARD, TEN_REVERSE) if engaged == 4 else (FORWARD, REVERSE)
    return SynthesisSpec.create(list(forward) + list(reverse), sets=4,
                                elements={"brakes": brakes, "clutches": ELEMENTS - brakes, "engaged": engaged},
                                constraints={"levels": levels, "free_input": free, "tolerance": 0.01,
                                             "stationary_ratio": (1.5, 4.0)})


def stratum(engaged: int, free: bool, brakes: int, per_stratum: int, levels: int, seed: int) -> dict:
    """One stratum in this process: screening and whole task (screen, fit, teeth, sizing) per sampled mechanism."""
    mechs = enumerate_mechanisms(("simple",) * 4, engaged + 1, free_input=free)
    spec = _spec(engaged, free, brakes, levels)
    forward, reverse = np.array(spec.forward), np.array(spec.reverse)
    low, high = bounds(spec)
    start = time.process_time()
    lay = layout(mechs[0].shafts, brakes, ELEMENTS - brakes, engaged)
    lay.containing  # noqa: B018 - built once per layout and worker (cached)
    build = time.process_time() - start
    rng = np.random.default_rng([seed, engaged, int(free), brakes])
    chosen = [mechs[i] for i in sorted(rng.choice(len(mechs), size=min(per_stratum, len(mechs)), replace=False))]
    # not timed, once per process as in a worker: the kernels compile or load numba's cache (each where it is
    # first reached), the grids and child tables of every level are built, SciPy's optimiser is imported
    import scipy.optimize  # noqa: F401

    for m in [mechs[i] for i in rng.choice(len(mechs), size=min(6, len(mechs)), replace=False)]:
        if search_task(Task(spec, engaged, (m,))).screened:
            break
    screening, whole, kept, candidates, survivors = [], [], 0, 0, []
    for m in chosen:
        start = time.process_time()
        placements, _ = screen(m, lay, low, high, forward, reverse, spec.tolerance, levels=levels)
        screening.append(time.process_time() - start)
        kept += len(placements)
        survivors += [(m, p) for p in placements]
        start = time.process_time()
        result = search_task(Task(spec, engaged, (m,)))
        whole.append(time.process_time() - start)
        candidates += len(result.candidates)
    return {"mechanisms": len(mechs), "shafts": mechs[0].shafts, "sample": len(chosen), "screening": screening,
            "whole": whole, "kept": kept, "candidates": candidates, "layout": build, "peak": _peak(),
            "fits": _fits(spec, engaged, survivors[:FIT_SAMPLE], low, high, levels)}


#: commit before the fit used the ratio functions (the general path and finite differences): the naive baseline.
BASELINE = "8676c57"
FIT_SAMPLE = 60  # placements per stratum fitted by both paths


def _baseline_fitting():
    """fitting.py of commit BASELINE, read with ``git show`` and run against this checkout's kinematics."""
    return _baseline_module(BASELINE, "fitting.py")


def _fits(spec: SynthesisSpec, engaged: int, survivors: list, low: np.ndarray, high: np.ndarray, levels: int) -> dict:
    """The ratio fit of up to FIT_SAMPLE surviving placements by this checkout and by BASELINE: CPU s, verdicts."""
    if not survivors:
        return {"count": 0}
    base = _baseline_fitting()
    forward, reverse = np.array(spec.forward), np.array(spec.reverse)
    points, corners = _grid(low, high, levels)
    out = {"count": len(survivors)}
    verdicts = {}
    for name, fit in (("new", fit_ratios), ("baseline", base.fit_ratios)):
        start = time.process_time()
        verdicts[name] = [fit(m, p.input, p.output, combinations_of_elements(p.elements, engaged), low, high, forward,
                              reverse, spec.tolerance, points[corners[list(p.boxes)]].mean(axis=1))
                          for m, p in survivors]
        out[name] = time.process_time() - start
        out[f"{name}_fitted"] = sum(v is not None for v in verdicts[name])
    out["same_verdict"] = sum((a is None) == (b is None) for a, b in zip(verdicts["new"], verdicts["baseline"]))
    return out


def _mean(values: list[float]) -> tuple[float, float]:
    data = np.array(values)
    return float(data.mean()), float(data.std(ddof=1) / sqrt(data.size)) if data.size > 1 else float(data.mean())


def measure(per_stratum: int, levels: int, seed: int) -> None:
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores; numba kernel: {AVAILABLE}; "
          f"{per_stratum} mechanisms per stratum, {levels} bisection levels, seed {seed}; each stratum in its own "
          "process (its peak memory)")
    rows = []
    for engaged in (2, 3, 4):
        for free in (False, True):
            mechs = enumerate_mechanisms(("simple",) * 4, engaged + 1, free_input=free)
            mechanisms, shafts = len(mechs), mechs[0].shafts
            for brakes in range(1, ELEMENTS + 1):
                count = stratum_count(mechanisms, shafts, free, brakes)
                if not count:
                    continue
                if brakes not in MEASURED:
                    rows.append((engaged, count, mechanisms, None))
                    continue
                out = subprocess.run([sys.executable, __file__, "--stratum", str(engaged), str(int(free)), str(brakes),
                                      str(per_stratum), str(levels), str(seed)], capture_output=True, text=True)
                if out.returncode:
                    raise SystemExit(out.stderr)
                got = json.loads(out.stdout.strip().splitlines()[-1])
                rows.append((engaged, count, mechanisms, got))
                screen_mean, screen_error = _mean(got["screening"])
                whole_mean, whole_error = _mean(got["whole"])
                print(f"  {engaged} engaged, separate input {free!s:5}, {brakes} brake(s): {mechanisms:>5,d} mechanisms, "
                      f"{count:.2e} architectures; per mechanism: screening {screen_mean:6.3f} ± {screen_error:.3f}, "
                      f"whole task {whole_mean:6.3f} ± {whole_error:.3f} CPU s ({count / mechanisms / screen_mean:>12,.0f}"
                      f" architectures per CPU s); {got['kept']} placements, {got['candidates']} candidates; "
                      f"-> {mechanisms * screen_mean / 3600:5.2f} h / {mechanisms * whole_mean / 3600:5.2f} h "
                      f"(layout {got['layout']:.1f} s, peak {got['peak']:.0f} MiB)", flush=True)
                fits = got["fits"]
                if fits["count"]:
                    print(f"      ratio fit of {fits['count']} placements: {fits['new']:.2f} CPU s, baseline ({BASELINE}: "
                          f"general path, finite differences) {fits['baseline']:.2f} s = {fits['baseline'] / fits['new']:.1f} x; "
                          f"fitted {fits['new_fitted']} / {fits['baseline_fitted']}, same verdict on {fits['same_verdict']}",
                          flush=True)
    total_count = sum(r[1] for r in rows)
    for key, what in (("screening", "screening alone"), ("whole", "whole search (screen, fit, teeth, ISO 6336 sizing)")):
        slowest = max(_mean(got[key])[0] * mechs / count for _, count, mechs, got in rows if got)
        seconds = variance = unmeasured = 0.0
        by_engaged: dict[int, float] = {}
        for engaged, count, mechs, got in rows:
            if got is None:  # charged at the slowest measured cost per architecture
                part = count * slowest
                unmeasured += part
            else:
                mean, error = _mean(got[key])
                part = mechs * mean
                variance += (mechs * error) ** 2
            seconds += part
            by_engaged[engaged] = by_engaged.get(engaged, 0.0) + part
        print(f"full space, {what}: {total_count:.3e} architectures in {seconds / 3600:.1f} ± "
              f"{sqrt(variance) / 3600:.1f} worker-hours at {levels} levels ({total_count / seconds:,.0f} per CPU s); "
              + ", ".join(f"{k} engaged {h / 3600:.1f} h" for k, h in sorted(by_engaged.items()))
              + f"; 5-6 brakes charged {unmeasured / 3600:.3f} h at the slowest measured cost; "
              + ", ".join(f"{w} workers {seconds / 3600 / w:.2f} h" for w in (2, 16, 64)))
    fits = [got["fits"] for *_, got in rows if got and got["fits"]["count"]]
    if fits:
        new, old = sum(f["new"] for f in fits), sum(f["baseline"] for f in fits)
        print(f"ratio fit, all strata: {sum(f['count'] for f in fits)} placements in {new:.1f} CPU s against {old:.1f} s "
              f"for the baseline ({old / new:.1f} x); same verdict on {sum(f['same_verdict'] for f in fits)}, fitted "
              f"{sum(f['new_fitted'] for f in fits)} / {sum(f['baseline_fitted'] for f in fits)}")
    print(f"largest peak memory of a stratum's process {max(got['peak'] for *_, got in rows if got):.0f} MiB")


if __name__ == "__main__":
    if sys.argv[1:2] == ["--stratum"]:
        k, free_, b, n_, levels_, seed_ = (int(a) for a in sys.argv[2:8])
        print(json.dumps(stratum(k, bool(free_), b, n_, levels_, seed_)))
    else:
        args = [int(a) for a in sys.argv[1:]]
        measure(*(args + [6, 3, 0][len(args):]))
