"""Synthesis: architectures screened per second, a naive baseline, 1 vs 2 Dask workers, the full space.

1. Screening throughput: the vectorised screening (:func:`epicyclic.synthesis.screening.screen`)
   of every (input, output, 2 brakes + 3 clutches) placement on a sample of 4-set
   mechanisms against the 8-speed targets of the ZF 8HP 70, in architectures per second.
   Baseline in the same run: the same first screening level written as a per-architecture
   loop (each combination's ratio at the 16 box corners from ``numpy.linalg.solve`` of its
   square system), on a small sample, extrapolated; both must keep the same architectures.
2. Dask: 40 tasks of the 8HP rediscovery test's search (4 simple sets, 2 brakes + 3 clutches,
   ties in pairs, input and output on carriers) on LocalClusters of 1 and of 2 worker processes
   (started beforehand), interleaved, best of 3; wall time, task CPU time and speed-up.
3. The full space of 4 simple sets and 6 shift elements (every tie pattern, every input and
   output, every split into brakes (at least one) and clutches, 2, 3 or 4 engaged per gear): its size, counted
   exactly, and the time to screen it at the measured throughput on N workers.

4. The exact shortcuts of the screening (multilinear interpolation of the determinants inside the
   box, block pruning) against the reference on the same sample: CPU seconds, same placements
   asserted, peak memory.

5. ``loopback``: 1 -> 2 -> 4 worker processes of a loopback cluster (`dask scheduler`, `dask worker`
   as programs on 127.0.0.1, reached by address), wall time and cores kept busy.

6. ``pruning``: the shortcuts with 5 and with 6 shift elements (2 brakes + 4 clutches, 20 combinations
   per element set, on sample // 12 mechanisms), and the full space at the 6-element pruned rate.

7. ``kernel``: three paths in one run on the same six-element sample (2 brakes + 4 clutches, 3 engaged,
   8HP targets, sample // 12 mechanisms): the numpy reference (every grid point solved, every element
   set scanned), main's pruned path before this work (commit ``BASELINE``, loaded from git), and the
   new path (compiled kernel + symmetry); placements asserted equal where they must be; peak memory
   after each path (the new one first); then the new path alone on ``sample`` mechanisms with 3 engaged
   (8HP targets) and on sample // 8 with 4 engaged (the 10R80's ten ratios, 9 shafts), and the full
   space in worker-hours at those rates.  One BLAS thread, as Dask's worker processes run
   (``OPENBLAS_NUM_THREADS=1``, set before numpy is imported).

Run:  .venv/bin/python benchmarks/bench_synthesis.py [sample_mechanisms] [shortcuts | pruning | loopback | kernel
      | kernel-new (the new path alone on the samples)]
"""

from __future__ import annotations

import os
import sys
import time

if len(sys.argv) > 2 and sys.argv[2].startswith("kernel"):  # one BLAS thread per worker, as Dask's nannies set it
    for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(_name, "1")
from math import comb

import numpy as np

from epicyclic.synthesis import SynthesisSpec, enumerate_mechanisms
from epicyclic.synthesis.kinematics import corner_points, element_rows, willis_matrices
from epicyclic.synthesis.screening import _masks, _passes, layout, screen

FORWARD = np.array([4.6957, 3.1304, 2.1039, 1.6667, 1.2845, 1.0, 0.8392, 0.6667])  # ZF 8HP 70
REVERSE = np.array([-3.2968])
LOW, HIGH = np.full(4, -4.0), np.full(4, -1.5)


def naive_level0(mech, lay, x: int, y: int, limit: int) -> tuple[list[int], int]:
    """Per-architecture loop: every combination of every element set solved on its own at the corners."""
    rows = element_rows(mech.shafts)
    lmats = willis_matrices(mech, corner_points(LOW, HIGH))
    targets = np.concatenate([FORWARD, REVERSE])
    full = (1 << targets.size) - 1
    kept, done = [], 0
    io = (1 << x) | (1 << y)
    for a in range(len(lay.element_sets)):
        if lay.brake_shafts[a] & io:
            continue
        masks = []
        for combo in lay.combos[lay.set_combos[a]]:
            ratios = []
            for lmat in lmats:
                system = np.vstack([lmat, rows[combo], np.eye(mech.shafts)[x]])
                rhs = np.zeros(mech.shafts)
                rhs[-1] = 1.0
                try:
                    n = np.linalg.solve(system, rhs)
                except np.linalg.LinAlgError:
                    ratios = None
                    break
                ratios.append(1.0 / n[y] if abs(n[y]) > 1e-12 else np.nan)
            if ratios is None or not np.all(np.isfinite(ratios)) or len({np.sign(r) for r in ratios}) > 1:
                masks.append(0)
                continue
            masks.append(int(_masks(np.array(True), np.array(min(ratios)), np.array(max(ratios)), targets, 0.01)))
        if _passes(np.array([masks]), full, targets.size)[0]:
            kept.append(a)
        done += 1
        if done >= limit:
            break
    return kept, done


def throughput(sample: int) -> float:
    mechs = enumerate_mechanisms(("simple",) * 4, 4, max_members_per_shaft=2)
    rng = np.random.default_rng(0)
    chosen = [mechs[i] for i in sorted(rng.choice(len(mechs), size=min(sample, len(mechs)), replace=False))]
    lay = layout(8, 2, 3, 3)
    screen(chosen[0], lay, LOW, HIGH, FORWARD, REVERSE, 0.01, levels=0)  # warm-up
    start = time.perf_counter()
    examined = survivors = 0
    for m in chosen:
        placements, n = screen(m, lay, LOW, HIGH, FORWARD, REVERSE, 0.01, levels=4)
        examined += n
        survivors += len(placements)
    seconds = time.perf_counter() - start
    rate = examined / seconds
    print(f"mechanisms sampled                 {len(chosen):>10d} of {len(mechs)} (4 simple sets, ties in pairs)")
    print(f"architectures screened             {examined:>10,d} in {seconds:.1f} s -> {rate:,.0f} per s")
    print(f"passed screening (4 levels)        {survivors:>10,d}")

    # baseline: level 0 only, one mechanism, one input/output pair, first architectures
    m, (x, y), limit = chosen[0], (0, 1), 300
    start = time.perf_counter()
    kept, done = naive_level0(m, lay, x, y, limit)
    naive_rate = done / (time.perf_counter() - start)
    start = time.perf_counter()
    repeat = 20
    for _ in range(repeat):
        placements, n = screen(m, lay, LOW, HIGH, FORWARD, REVERSE, 0.01, levels=0)
    fast_rate = repeat * n / (time.perf_counter() - start)
    allowed = [a for a in range(len(lay.element_sets)) if not lay.brake_shafts[a] & ((1 << x) | (1 << y))][:limit]
    fast_kept = sorted(a for a in allowed if any(p.input == x and p.output == y and
                                                  p.elements == tuple(int(e) for e in lay.element_sets[a])
                                                  for p in placements))
    agree = fast_kept == sorted(kept)
    print(f"naive loop, level 0 ({done} archs)   {naive_rate:>10,.0f} per s")
    print(f"vectorised, level 0                {fast_rate:>10,.0f} per s  ({fast_rate / naive_rate:,.0f} x)")
    print(f"same architectures kept            {agree!s:>10}")
    if not agree:
        raise SystemExit("vectorised and naive screening disagree")
    return rate


def shortcuts(sample: int, clutches: int = 3, levels: int = 3) -> float:
    """The exact shortcuts (multilinear interpolation inside the box, rarest-target first level, matching
    pruning) against the reference screening (every grid point solved, every element set scanned, no
    pruning), CPU seconds (the machine is shared: wall time measures the load).  The pruned placements must
    be the reference's in the reference's order, less those that admit no one-combination-per-target
    matching in any box (which the ratio fit rejects; ``tests/synthesis/test_screening.py``).
    Returns the pruned rate in architectures per CPU second."""
    import resource

    mechs = enumerate_mechanisms(("simple",) * 4, 4, max_members_per_shaft=2)
    rng = np.random.default_rng(0)
    chosen = [mechs[i] for i in sorted(rng.choice(len(mechs), size=min(sample, len(mechs)), replace=False))]
    lay = layout(8, 2, clutches, 3)
    lay.containing  # noqa: B018 - built once per layout (cached), not per mechanism
    screen(chosen[0], lay, LOW, HIGH, FORWARD, REVERSE, 0.01, levels=0)  # warm-up
    results, cpu = {}, {}
    print(f"{len(chosen)} mechanisms, 2 brakes + {clutches} clutches ({comb(2 + clutches, 3)} combinations per "
          f"element set), {levels} levels:")
    for fast in (False, True):
        start = time.process_time()
        out, examined = [], 0
        for m in chosen:
            placements, n = screen(m, lay, LOW, HIGH, FORWARD, REVERSE, 0.01, levels=levels, interpolate=fast,
                                   prune=fast)
            out.append(placements)
            examined += n
        cpu[fast], results[fast] = time.process_time() - start, out
        print(f"  {'pruned' if fast else 'reference'} screening    {examined / cpu[fast]:>12,.0f} "
              f"architectures per CPU s ({cpu[fast]:.2f} s, {sum(map(len, out))} placements kept)")
    ordered = all([p for p in ref if p in set(new)] == new for ref, new in zip(results[False], results[True]))
    print(f"  speed-up                       {cpu[False] / cpu[True]:>12.2f} x; kept = reference's, in order: "
          f"{ordered}")
    print(f"  peak memory of this process    {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:>12.0f} MiB")
    if not ordered:
        raise SystemExit("the pruning kept a placement the reference did not, or changed the order")
    return examined / cpu[True]


def dask_speedup(tasks_used: int = 40, repeats: int = 3) -> None:
    """1 vs 2 worker processes on the same tasks; clusters started beforehand, best of interleaved runs."""
    import logging
    import os

    from distributed import Client, LocalCluster

    from epicyclic.synthesis.distributed import run_tasks
    from epicyclic.synthesis.search import plan, search_task

    spec = SynthesisSpec.create([*FORWARD, *REVERSE], 4, {"brakes": 2, "clutches": 3, "engaged": 3},
                                {"tolerance": 0.01, "max_members_per_shaft": 2, "free_input": False,
                                 "input_members": ["carrier"], "output_members": ["carrier"]})
    tasks = plan(spec)
    step = max(1, len(tasks) // tasks_used)
    tasks = tasks[::step][:tasks_used]
    clusters = {}
    for workers in (1, 2):
        import dask

        environ = {k: v for k, v in dask.config.get("distributed.nanny.pre-spawn-environ").items()
                   if k != "MALLOC_TRIM_THRESHOLD_"}
        with dask.config.set({"distributed.nanny.pre-spawn-environ": environ}):
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                                   silence_logs=logging.ERROR)
        clusters[workers] = (cluster, Client(cluster))
    best = {1: float("inf"), 2: float("inf")}
    cpu = {1: 0.0, 2: 0.0}
    try:
        for _ in range(repeats):
            for workers in (1, 2):
                start = time.perf_counter()
                results, _used = run_tasks(search_task, tasks, client=clusters[workers][1])
                wall = time.perf_counter() - start
                if wall < best[workers]:
                    best[workers], cpu[workers] = wall, sum(r.cpu_seconds for r in results)
    finally:
        for cluster, client in clusters.values():
            client.close()
            cluster.close()
    mechs = sum(len(t.mechanisms) for t in tasks)
    print(f"Dask: {len(tasks)} tasks ({mechs} mechanisms) of the 8HP test search, best of {repeats}, "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    for workers in (1, 2):
        print(f"  {workers} worker process(es)            {best[workers]:>10.1f} s wall, task CPU {cpu[workers]:.1f} s "
              f"= {cpu[workers] / best[workers]:.2f} cores busy")
    print(f"  speed-up 1 -> 2 workers          {best[1] / best[2]:>10.2f} x")


def loopback(tasks_used: int = 16, sizes: tuple[int, ...] = (1, 2, 4)) -> None:
    """1 -> 2 -> 4 worker processes of a real loopback cluster: `dask scheduler` and `dask worker` started as
    separate programs on 127.0.0.1, reached by address as `--scheduler` does; wall time, task CPU time and
    the cores kept busy (task CPU / wall)."""
    import os
    import shutil
    import subprocess

    from distributed import Client

    from epicyclic.synthesis.distributed import run_tasks
    from epicyclic.synthesis.search import plan, search_task

    spec = SynthesisSpec.create([*FORWARD, *REVERSE], 4, {"brakes": 2, "clutches": 3, "engaged": 3},
                                {"tolerance": 0.01, "max_members_per_shaft": 2, "free_input": False,
                                 "input_members": ["carrier"], "output_members": ["carrier"]})
    tasks = plan(spec)
    tasks = tasks[::max(1, len(tasks) // tasks_used)][:tasks_used]
    dask = shutil.which("dask") or os.path.join(os.path.dirname(sys.executable), "dask")
    port = 8786 + os.getpid() % 1000
    address = f"tcp://127.0.0.1:{port}"
    print(f"loopback cluster at {address}: {len(tasks)} tasks of the 8HP search, load average "
          f"{os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    for n in sizes:
        scheduler = subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port", str(port),
                                      "--no-dashboard"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        workers = [subprocess.Popen([dask, "worker", address, "--nthreads", "1", "--no-dashboard"],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL) for _ in range(n)]
        try:
            with Client(address, timeout="60s") as client:
                client.wait_for_workers(n, timeout=120)
                start = time.perf_counter()
                results, used = run_tasks(search_task, tasks, client=client)
                wall = time.perf_counter() - start
            cpu = sum(r.cpu_seconds for r in results)
            print(f"  {n} worker process(es): {wall:7.1f} s wall, task CPU {cpu:6.1f} s, {cpu / wall:4.2f} cores busy")
        finally:
            for w in workers:
                w.terminate()
            scheduler.terminate()
            for proc in (*workers, scheduler):
                proc.wait(timeout=30)


def full_space(rate) -> None:
    """The full space's size and time; ``rate`` per worker-second, or {engaged: rate} (2 engaged at the 3-engaged
    rate, the lowest measured for fewer elements per combination)."""
    rates = rate if isinstance(rate, dict) else {2: rate, 3: rate, 4: rate}
    rates.setdefault(2, rates[3])
    kinds = ("simple",) * 4
    total = 0
    hours = 0.0
    print("full space, 4 simple sets, 6 shift elements (every split brakes/clutches, k engaged):")
    for k in (2, 3, 4):
        for free in (False, True):
            mechs = enumerate_mechanisms(kinds, k + 1, free_input=free)
            if not mechs:
                continue
            n = mechs[0].shafts
            members = n - int(free)
            io = members if free else members * (members - 1)
            sets_ = sum(comb(n - 2, b) * comb(comb(n, 2), 6 - b) for b in range(1, 7))
            count = len(mechs) * io * sets_
            total += count
            hours += count / rates[k] / 3600
            print(f"  k={k} free input={free!s:5}: {len(mechs):>6,d} mechanisms x {io} in/out x {sets_:,} element "
                  f"sets = {count:.3e}")
    print(f"  total architectures              {total:.3e}")
    shown = ", ".join(f"{k} engaged {r:,.0f}" for k, r in sorted(rates.items()))
    for workers in (1, 2, 16, 256):
        print(f"  screening time on {workers:>3d} workers     {hours / workers:>10.1f} h  (per s per worker: {shown})")
    print("  (an overestimate: the rates count the architectures a screening examines, about 45 % of the counted "
          "space's, which also holds element sets that leave a one-member shaft free; and one split and sample stand "
          "for all. benchmarks/bench_synthesis_space.py measures the space stratum by stratum)")


#: main before the compiled kernel and the symmetry classes (the "current main's pruned path").
BASELINE = "2e29162"
TEN_FORWARD = np.array([4.696, 2.985, 2.146, 1.769, 1.520, 1.275, 1.000, 0.854, 0.689, 0.636])  # Ford 10R80
TEN_REVERSE = np.array([-4.866])


def _baseline_module(commit: str, path: str):
    """A module of the package at ``commit`` (``path`` under src/epicyclic/synthesis), read with ``git show`` and run
    against this checkout's other modules: the same-run baseline of a benchmark."""
    import subprocess
    import types

    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    source = subprocess.run(["git", "show", f"{commit}:src/epicyclic/synthesis/{path}"], cwd=root,
                            capture_output=True, text=True, check=True).stdout
    module = types.ModuleType(f"epicyclic.synthesis._{path[:-3]}_{commit}")
    module.__package__ = "epicyclic.synthesis"
    sys.modules[module.__name__] = module
    exec(compile(source, f"{path}@{commit}", "exec"), module.__dict__)  # noqa: S102 - our own history
    return module


def _baseline_screening():
    """The screening module of commit BASELINE, read with ``git show`` and run against this checkout's kinematics."""
    return _baseline_module(BASELINE, "screening.py")


def _peak() -> float:
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def _rate(chosen, lay, forward, reverse, levels, **flags):
    start = time.process_time()
    out, examined = [], 0
    for m in chosen:
        placements, n = screen(m, lay, LOW, HIGH, forward, reverse, 0.01, levels=levels, **flags)
        out.append(placements)
        examined += n
    return examined, time.process_time() - start, out


def kernel_paths(sample: int, compare: bool = True) -> None:
    """Reference, main's pruned path (BASELINE) and the new path on one six-element sample; the new path's rates
    with 3 and 4 engaged (against main's unless ``compare`` is False: ``kernel-new``); the full space in
    worker-hours."""
    from epicyclic.synthesis import kernel
    from epicyclic.synthesis.symmetry import automorphisms

    def plain(runs):  # the baseline module has its own Placement class
        return [[(p.input, p.output, p.elements, tuple(int(b) for b in p.boxes)) for p in run] for run in runs]

    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores; numba kernel: {kernel.AVAILABLE}; "
          f"OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS')}")
    mechs = enumerate_mechanisms(("simple",) * 4, 4, max_members_per_shaft=2)
    rng = np.random.default_rng(0)
    chosen = [mechs[i] for i in sorted(rng.choice(len(mechs), size=max(1, sample // 12), replace=False))]
    lay = layout(8, 2, 4, 3)
    lay.containing  # noqa: B018 - built once per layout (cached)
    screen(chosen[0], lay, LOW, HIGH, FORWARD, REVERSE, 0.01, levels=1)  # compiles or loads the kernel
    print(f"{len(chosen)} mechanisms (8HP space), 2 brakes + 4 clutches, 3 engaged, 3 levels, CPU seconds:")
    examined, cpu, new = _rate(chosen, lay, FORWARD, REVERSE, 3)
    print(f"  new path (kernel + symmetry)   {examined / cpu:>12,.0f} per CPU s ({cpu:.2f} s, "
          f"{sum(map(len, new))} placements); peak memory so far {_peak():.0f} MiB")
    base = _baseline_screening() if compare else None
    if compare:
        _compare_first(chosen, lay, base, examined, cpu, new, plain)
    _samples(mechs, base, plain, automorphisms)


def _compare_first(chosen, lay, base, examined, cpu, new, plain) -> None:
    """Main's pruned path and the reference on the first sample, against the new path's figures."""
    blay = base.layout(8, 2, 4, 3)
    blay.containing  # noqa: B018
    start = time.process_time()
    old = [base.screen(m, blay, LOW, HIGH, FORWARD, REVERSE, 0.01, levels=3)[0] for m in chosen]
    old_cpu = time.process_time() - start
    print(f"  main's pruned path ({BASELINE})  {examined / old_cpu:>12,.0f} per CPU s ({old_cpu:.2f} s, "
          f"{sum(map(len, old))} placements); peak memory so far {_peak():.0f} MiB")
    if plain(old) != plain(new):
        raise SystemExit("the new path's placements differ from main's pruned path")
    _, ref_cpu, ref = _rate(chosen, lay, FORWARD, REVERSE, 3, interpolate=False, prune=False, kernel=False,
                            symmetry=False)
    print(f"  numpy reference                {examined / ref_cpu:>12,.0f} per CPU s ({ref_cpu:.2f} s, "
          f"{sum(map(len, ref))} placements); peak memory {_peak():.0f} MiB")
    ordered = all([p for p in r if p in set(n)] == n for r, n in zip(ref, new))
    print(f"  speed-up: {old_cpu / cpu:.2f} x over main's pruned path, {ref_cpu / cpu:.1f} x over the reference; "
          f"new = main's, kept = reference's in order: {ordered}")
    if not ordered:
        raise SystemExit("the new path kept a placement the reference did not, or changed the order")


def _samples(mechs, base, plain, automorphisms) -> None:
    """The new path (and main's pruned path, with ``base``) on the 3- and 4-engaged samples; the full space."""
    sample = int(sys.argv[1]) if len(sys.argv) > 1 else 24
    rates = {}
    rng = np.random.default_rng(1)
    big = [mechs[i] for i in sorted(rng.choice(len(mechs), size=min(sample, len(mechs)), replace=False))]
    four = enumerate_mechanisms(("simple",) * 4, 5)
    picked = [four[i] for i in sorted(rng.choice(len(four), size=max(1, sample // 8), replace=False))]
    for engaged, chosen_, shafts, forward, reverse, what in (
            (3, big, 8, FORWARD, REVERSE, "8HP targets, ties in pairs"),
            (4, picked, 9, TEN_FORWARD, TEN_REVERSE, "10R80 targets, every tie pattern")):
        lay_ = layout(shafts, 2, 4, engaged)
        lay_.containing  # noqa: B018
        examined, cpu, out = _rate(chosen_, lay_, forward, reverse, 3)
        rates[engaged] = examined / cpu
        symmetric = sum(bool(automorphisms(m, LOW, HIGH)) for m in chosen_)
        print(f"{len(chosen_)} mechanisms ({symmetric} symmetric), {engaged} engaged, {what}, {examined:.3g} "
              f"architectures, {sum(map(len, out))} placements kept:")
        print(f"  new path {rates[engaged]:>12,.0f} per CPU s ({cpu:.1f} s); peak memory {_peak():.0f} MiB")
        if base is None:
            continue
        blay_ = base.layout(shafts, 2, 4, engaged)
        blay_.containing  # noqa: B018
        start = time.process_time()
        old = [base.screen(m, blay_, LOW, HIGH, forward, reverse, 0.01, levels=3)[0] for m in chosen_]
        old_cpu = time.process_time() - start
        print(f"  main's pruned path {examined / old_cpu:>12,.0f} per CPU s ({old_cpu:.1f} s): {old_cpu / cpu:.2f} x; "
              f"same placements: {plain(old) == plain(out)}; peak memory {_peak():.0f} MiB")
        if plain(old) != plain(out):
            raise SystemExit("the new path's placements differ from main's pruned path")
    full_space(rates)


def main(sample: int = 24) -> None:
    if len(sys.argv) > 2 and sys.argv[2] in ("kernel", "kernel-new"):
        kernel_paths(sample, compare=sys.argv[2] == "kernel")
        return
    if len(sys.argv) > 2 and sys.argv[2] == "shortcuts":
        shortcuts(sample)
        return
    if len(sys.argv) > 2 and sys.argv[2] == "pruning":  # 5 and 6 elements; the full space at the 6-element rate
        shortcuts(sample)
        rate = shortcuts(max(1, sample // 12), clutches=4)
        full_space(rate)
        return
    if len(sys.argv) > 2 and sys.argv[2] == "loopback":
        loopback()
        return
    shortcuts(sample)
    rate = throughput(sample)
    dask_speedup()
    full_space(rate)
    print("(the rate was measured with 5 elements, 10 combinations per element set; with 6 elements an element "
          "set has 15-20 combinations, so the times above are low by about 2x)")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 24)
