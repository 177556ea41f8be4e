"""The search: mechanisms → screened architectures → fitted ratios → tooth counts → evaluated candidates.

:func:`search_task` is one independent task (a chunk of mechanisms); it is what
Dask workers run (:mod:`~epicyclic.synthesis.distributed`).  :func:`plan`
splits a specification into tasks and :func:`synthesize` runs them and ranks the
results.

References
----------
Kahraman, Ligata, Kienzle & Zini (2004), "A kinematics and power flow analysis
methodology for automatic transmission planetary gear trains", J. Mech. Des.
126(6), 1071–1081 (configuration search, tooth counts, power flow);
Benford & Leising 1981, SAE 810102 (lever analogy).
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..rating.errors import RatingError
from .candidate import Candidate, evaluate
from .fitting import combinations_of_elements, fit_ratios, single_swap_schedule
from .mechanisms import Mechanism, enumerate_mechanisms
from .screening import _grid, layout, screen
from .spec import SynthesisError, SynthesisSpec
from .teeth import (
    TOOTH_WEIGHTS,
    choose_teeth,
    pick_teeth,
    tooth_objective,
    tooth_options,
)

__all__ = ["Arrangement", "Task", "TaskResult", "assemble", "bounds", "plan", "search_task", "sized_candidate",
           "synthesize", "synthesize_spec"]


@dataclass(frozen=True)
class Task:
    """Independent unit of work: some mechanisms, one number of engaged elements."""

    spec: SynthesisSpec
    engaged: int
    mechanisms: tuple[Mechanism, ...]


@dataclass(frozen=True)
class TaskResult:
    """Candidates of one task and what it counted."""

    candidates: tuple[Candidate, ...]
    mechanisms: int
    architectures: int
    screened: int
    fitted: int
    seconds: float
    rejected: dict[str, int] = field(default_factory=dict)
    cpu_seconds: float = 0.0


def bounds(spec: SynthesisSpec) -> tuple[np.ndarray, np.ndarray]:
    """Box of signed stationary ratios: simple sets [−hi, −lo], plus sets [lo, hi]."""
    lo, hi = spec.stationary_ratio
    low = np.array([-hi if k == "simple" else lo for k in spec.kinds])
    high = np.array([-lo if k == "simple" else hi for k in spec.kinds])
    return low, high


def _mechanisms(spec: SynthesisSpec, engaged: int) -> tuple[Mechanism, ...]:
    dof = engaged + 1
    found = enumerate_mechanisms(spec.kinds, dof, max_members_per_shaft=spec.max_members_per_shaft)
    if spec.free_input:
        found += enumerate_mechanisms(spec.kinds, dof, free_input=True, max_members_per_shaft=spec.max_members_per_shaft)
    return found


#: Architectures per task the default split aims at (about 10 s of screening): the time limit, progress and
#: checkpoints act between tasks.
TASK_ARCHITECTURES = 10**7


def plan(spec: SynthesisSpec, chunk: int | None = None) -> list[Task]:
    """Split the search into independent tasks (``chunk`` mechanisms each; default at most 8, fewer where a
    mechanism holds many architectures: about :data:`TASK_ARCHITECTURES` per task)."""
    from .estimate import count

    tasks = []
    for k in spec.engaged:
        mechs = _mechanisms(spec, k)
        if not mechs:
            continue
        per = count(spec, mechs).architectures // len(mechs)
        size = chunk or max(1, min(8, len(mechs) // 16 or 1, TASK_ARCHITECTURES // max(per, 1)))
        tasks += [Task(spec, k, mechs[i:i + size]) for i in range(0, len(mechs), size)]
    if not tasks:
        raise SynthesisError(
            f"synthesize: {spec.simple + spec.plus} set(s) cannot form a mechanism with "
            f"{', '.join(str(k + 1) for k in spec.engaged)} degree(s) of freedom; change the number of sets or "
            "elements.engaged.")
    return tasks


@dataclass(frozen=True)
class Arrangement:
    """Where a candidate's teeth go: mechanism, input, output, elements and schedule."""

    mechanism: Mechanism
    input: int
    output: int
    elements: tuple[int, ...]
    schedule: tuple[tuple[int, ...], ...]


def sized_candidate(spec: SynthesisSpec, where: Arrangement, chosen: tuple, targets: np.ndarray) -> Candidate:
    """The evaluated candidate of the admissible tooth combinations of least objective (:mod:`.teeth`).

    The smallest-error combination is sized (ISO 6336); with a ring-balance weight, the option of least
    estimated objective (:func:`~epicyclic.synthesis.teeth.pick_teeth`) is sized too and the lower true
    objective of the two is kept.

    Parameters
    ----------
    spec : SynthesisSpec
        Tolerance, tooth weights, sizing and rating inputs.
    where : Arrangement
        Mechanism, input, output, elements and schedule.
    chosen : tuple
        The admissible combinations, their gear ratios and errors (:func:`~epicyclic.synthesis.teeth.choose_teeth`).
    targets : ndarray
        Forward then reverse targets.

    Returns
    -------
    Candidate
        Evaluated and sized.

    Raises
    ------
    RatingError
        A set no module up to 50 mm can carry.

    References
    ----------
    ISO 6336-2:2019, ISO 6336-3:2019 (the sizing); Kahraman et al. 2004, section 3 (tooth counts for a ratio set).
    """
    admissible, gears, errors = chosen
    weights = {**TOOTH_WEIGHTS, **dict(spec.tooth_weights)}

    def sized(k: int) -> Candidate:
        cand = Candidate(where.mechanism, where.input, where.output, where.elements, where.schedule, admissible[k],
                         tuple(float(r) for r in gears[k]), tuple(float(t) for t in targets), len(spec.forward),
                         spec.stationary_efficiency)
        return evaluate(cand, spec.input_torque, spec.rating, spec.face_width_ratio, spec.input_speed)

    def objective(cand: Candidate, k: int) -> float:
        rings = [[np.nan if z is None else z.module * t.z_ring for t, z in zip(cand.teeth, cand.sizes)]]
        return float(tooth_objective(errors[k:k + 1], np.array(rings), spec.tolerance, weights)[0])

    best = sized(0)
    if len(admissible) == 1 or weights["ring_balance"] == 0:
        return best
    rating = dict(best.rating)
    k = pick_teeth(admissible, errors, best.sizes, spec.tolerance, weights, rating["S_Hmin"], rating["S_Fmin"])
    if k == 0:
        return best
    other = sized(k)
    return other if objective(other, k) < objective(best, 0) else best


def search_task(task: Task) -> TaskResult:
    """Run one task: screen, fit, choose teeth and evaluate every surviving architecture."""
    start, cpu = time.perf_counter(), time.process_time()
    spec = task.spec
    forward = np.array(spec.forward)
    reverse = np.array(spec.reverse)
    targets = np.concatenate([forward, reverse])
    low, high = bounds(spec)
    out: list[Candidate] = []
    examined = screened = fitted = 0
    rejected = {"ratios": 0, "teeth": 0, "sizing": 0}
    teeth_cache: dict[tuple[str, float], list] = {}
    for mech in task.mechanisms:
        lay = layout(mech.shafts, spec.brakes, spec.clutches, task.engaged)
        placements, n = screen(mech, lay, low, high, forward, reverse, spec.tolerance, levels=spec.levels,
                               input_members=spec.input_members, output_members=spec.output_members)
        examined += n
        screened += len(placements)
        if not placements:
            continue
        points, corners = _grid(low, high, spec.levels)
        for p in placements:
            combos = combinations_of_elements(p.elements, task.engaged)
            starts = points[corners[list(p.boxes)]].mean(axis=1)
            fit = fit_ratios(mech, p.input, p.output, combos, low, high, forward, reverse, spec.tolerance, starts)
            if fit is None:
                rejected["ratios"] += 1
                continue
            fitted += 1
            # among combinations of identical ratio, those that shift by single swaps
            probe = np.array([fit.stationary_ratios, 0.37 * low + 0.63 * high])
            rows = single_swap_schedule(mech, p.input, p.output, combos, fit.schedule, forward.size, probe)
            options = []
            for kind, i0 in zip(spec.kinds, fit.stationary_ratios):
                key = (kind, round(i0, 4))
                if key not in teeth_cache:
                    teeth_cache[key] = tooth_options(i0, kind, tolerance=spec.tolerance, sun=spec.sun,
                                                     planet=spec.planet, planets=spec.planets, hunting=spec.hunting)
                options.append(teeth_cache[key])
            chosen = choose_teeth(mech, p.input, p.output, combos, rows, targets, options, spec.tolerance)
            if chosen is None:
                rejected["teeth"] += 1
                continue
            schedule = tuple(tuple(int(e) for e in combos[j]) for j in rows)
            try:
                out.append(sized_candidate(spec, Arrangement(mech, p.input, p.output, p.elements, schedule),
                                            chosen, targets))
            except RatingError:  # no module of the series carries a set: never written unsized
                rejected["sizing"] += 1
    return TaskResult(tuple(out), len(task.mechanisms), examined, screened, fitted, time.perf_counter() - start,
                      rejected, time.process_time() - cpu)


def synthesize_spec(spec: SynthesisSpec, *, client: Any = None, scheduler: str | None = None,
                    workers: int | None = None, processes: bool | None = None,
                    progress: Callable[[int, int], None] | bool | None = None, chunk: int | None = None,
                    announce: Callable[[str], None] | bool = True, checkpoint: str | None = None,
                    on_candidates: Callable[[tuple[Candidate, ...]], None] | None = None,
                    on_task: Callable[[int, TaskResult], None] | None = None):
    """Run a validated :class:`SynthesisSpec` and rank the candidates (see :func:`synthesize`).

    Before anything is enumerated the size of the search is estimated from counting
    formulas (:func:`~epicyclic.synthesis.estimate.estimate`), then bounded exactly over
    the enumerated mechanisms; both are announced, and a search over
    ``spec.max_architectures`` is refused.  Candidates found by several tasks are kept
    once; the statistics (tasks, workers, mechanisms, screened, fitted, rejected, seconds,
    the estimate, whether the search completed) go into the result.

    Parameters
    ----------
    spec : SynthesisSpec
        The validated search (:meth:`SynthesisSpec.create` or ``SynthesisSpec.from_file``).
    client : dask.distributed.Client, optional
        Run on this client.
    scheduler : str, optional
        Address of an existing Dask scheduler (``tcp://host:8786``).
    workers : int, optional
        Workers of the local cluster started otherwise (default: CPU count, at most
        :data:`~epicyclic.limits.MAX_SYNTHESIS_WORKERS`).
    processes : bool, optional
        Local workers as processes (True) or threads of this process (False); default: threads
        for a small search, processes for a big one where the main script allows it
        (:func:`~epicyclic.synthesis.distributed.use_processes`).
    progress : callable (done, total), bool or None, optional
        Called after each finished task; True: a progress line on stderr
        (:class:`~epicyclic.synthesis.progress.ProgressLine`: tasks, percent, time left); None (default):
        that line where stderr is a terminal and ``announce`` is True; False: none.
    chunk : int, optional
        Mechanisms per task (default: about 8).
    announce : callable (str) or bool, default True
        Where the bound and estimate line goes before the search starts (True: stderr; False: nowhere).
    checkpoint : str or Path, optional
        File of finished tasks (:class:`~epicyclic.synthesis.checkpoint.Checkpoint`): written
        atomically as tasks finish; a search started again with it runs only the missing tasks.
    on_candidates : callable (tuple of Candidate), optional
        Called with each finished task's candidates as the task finishes (results stream back).
    on_task : callable (task index, TaskResult), optional
        Called with each finished task's index in the plan and its whole result, as it finishes
        (what :func:`assemble` ranks; the page keeps them, so that a stopped search keeps its candidates).

    Returns
    -------
    SynthesisResult

    Raises
    ------
    SynthesisError
        A search over its bound, workers out of range, processes a script cannot start.

    References
    ----------
    Kahraman et al. 2004, J. Mech. Des. 126(6), 1071–1081.
    """
    import os
    import sys

    from .distributed import check_workers, run_tasks, use_processes
    from .estimate import check, count, estimate

    say = (lambda text: print(text, file=sys.stderr)) if announce is True else (announce or (lambda text: None))
    if progress is True or (progress is None and announce is True and sys.stderr.isatty()):
        from .progress import ProgressLine

        progress = ProgressLine()
    elif progress is False:
        progress = None
    workers = check_workers(workers)
    if chunk is not None and (isinstance(chunk, bool) or not isinstance(chunk, int) or chunk < 1):
        raise SynthesisError(f"synthesize: chunk must be a whole number of mechanisms >= 1, got {chunk!r:.40}.")
    start = time.perf_counter()
    first = estimate(spec)
    check(spec, first)  # refused before a single mechanism is enumerated
    tasks = plan(spec, chunk)
    size = count(spec, (m for t in tasks for m in t.mechanisms))
    check(spec, size)
    local = client is None and not scheduler
    cores = os.cpu_count() or 1
    n = min(workers or cores, cores) if local else None
    with_processes, note = use_processes(processes, size.worker_seconds, n) if local else (False, None)
    if local and workers and workers > cores:  # more local workers than cores only compete (and 64 processes
        # on 2 cores exhaust the machine's semaphores): capped, and said so
        note = (f"synthesize: {workers} local workers asked for on a machine with {cores} core(s): using {n}"
                + (f"; {note}" if note else ""))
    limit = f", stopped after {spec.time_limit:g} s" if spec.time_limit else ""
    where = (f"{n} local worker {'process' if with_processes else 'thread'}{'es' * with_processes if n > 1 else ''}"
             f"{'s' * (not with_processes) if n > 1 else ''}" if local
             else f"the cluster at {scheduler}" if scheduler else "the given Dask client")
    saved = None
    if checkpoint is not None:
        from .checkpoint import Checkpoint, fingerprint

        saved = Checkpoint(checkpoint, fingerprint(spec, tasks))
    before = len(saved.done) if saved else 0
    resumed = f"; {before} task(s) done before, from {checkpoint}" if before else ""
    say(f"synthesize: {size.describe(n)}; {len(tasks)} task(s) on {where}{limit}{resumed}")
    if note:
        say(note)

    def finished(index: int, result: TaskResult) -> None:
        if saved is not None:
            saved.add(index, result)
        if on_candidates is not None:
            on_candidates(result.candidates)
        if on_task is not None:
            on_task(index, result)

    try:
        results, used = run_tasks(search_task, tasks, client=client, scheduler=scheduler, workers=n,
                                  processes=with_processes, progress=progress, time_limit=spec.time_limit,
                                  done=saved.done if saved else None, on_result=finished)
    finally:
        if saved is not None:  # also when interrupted: what finished is kept
            saved.save(force=True)
    return assemble(spec, results, first, size, workers=used, processes=with_processes, resumed=before,
                    seconds=time.perf_counter() - start)


def assemble(spec: SynthesisSpec, results: Sequence[TaskResult | None], estimated: Any, bound: Any, *,
             workers: int = 1, processes: bool = False, resumed: int = 0, seconds: float = 0.0,
             stopped: str | None = None):
    """The ranked result of a search's task results (None: a task not finished), with its statistics.

    Candidates found by several tasks are kept once and ranked (:func:`~epicyclic.synthesis.ranking.rank`);
    the statistics count what the finished tasks did.

    Parameters
    ----------
    spec : SynthesisSpec
    results : sequence of TaskResult or None
        One per task of the plan, in plan order.
    estimated, bound : SearchEstimate
        The estimate from counting formulas and the bound over the enumerated mechanisms.
    workers : int, default 1
    processes : bool, default False
    resumed : int, default 0
        Tasks taken from a checkpoint.
    seconds : float, default 0
        Wall time of the search.
    stopped : str, optional
        Why an unfinished search stopped when not at ``spec.time_limit`` ("cancelled", ...): the result says so.

    Returns
    -------
    SynthesisResult

    References
    ----------
    Kahraman et al. 2004, J. Mech. Des. 126(6), 1071–1081.
    """
    from .ranking import rank
    from .results import SynthesisResult

    finished = [r for r in results if r is not None]
    unique: dict[tuple, Candidate] = {}
    for r in finished:
        for c in r.candidates:
            unique.setdefault(c.key, c)
    ranked, standings = rank(list(unique.values()), dict(spec.weights), spec.module)
    stats = {
        "tasks": len(results), "tasks_done": len(finished), "complete": len(finished) == len(results),
        "workers": workers, "processes": processes,
        "mechanisms": sum(r.mechanisms for r in finished),
        "architectures": sum(r.architectures for r in finished),
        "screened": sum(r.screened for r in finished),
        "fitted": sum(r.fitted for r in finished),
        "rejected_ratios": sum(r.rejected.get("ratios", 0) for r in finished),
        "rejected_teeth": sum(r.rejected.get("teeth", 0) for r in finished),
        "rejected_sizing": sum(r.rejected.get("sizing", 0) for r in finished),
        "candidates": len(ranked),
        "task_seconds": sum(r.seconds for r in finished),
        "task_cpu_seconds": sum(r.cpu_seconds for r in finished),
        "estimate": estimated.to_dict(), "bound": bound.to_dict(), "resumed_tasks": resumed,
        "seconds": seconds,
    }
    if stopped and not stats["complete"]:
        stats["stopped"] = stopped
    return SynthesisResult(spec, ranked, stats, standings)


def synthesize(targets: Sequence[float] | Mapping[str, Any], sets: int | Mapping[str, int] = 2,
               elements: Mapping[str, int] | None = None, constraints: Mapping[str, Any] | None = None, *,
               client: Any = None, scheduler: str | None = None, workers: int | None = None,
               processes: bool | None = None, progress: Callable[[int, int], None] | bool | None = None,
               chunk: int | None = None, announce: Callable[[str], None] | bool = True,
               checkpoint: str | None = None, on_candidates: Callable[[tuple[Candidate, ...]], None] | None = None):
    """Find transmissions (architecture, shift schedule, tooth counts) that give the target ratios.

    Parameters
    ----------
    targets : sequence of float or mapping
        Gear ratios n_in/n_out (negative: reverse), or a mapping with
        ``forward``, ``reverse``, ``tolerance`` (relative, default 0.01), or
        ``spread``, ``gears``, ``first``, ``progression`` (see :class:`SynthesisSpec`).
    sets : int or mapping
        Number of simple sets, or ``{"simple": n, "plus": m}``.
    elements : mapping
        ``{"brakes": b, "clutches": c}`` and optionally ``"engaged"`` per gear.
    constraints : mapping, optional
        Bounds and search options: ``stationary_ratio`` (|i0| range), ``sun``,
        ``planet`` (tooth ranges), ``planets``, ``max_members_per_shaft``,
        ``free_input``, ``input_members``, ``output_members``, ``levels``,
        ``stationary_efficiency``, ``top``.
    client : dask.distributed.Client, optional
        Run on this client.
    scheduler : str, optional
        Address of an existing Dask scheduler (``tcp://host:8786``).
    workers : int, optional
        Workers of the local cluster started otherwise (default: CPU count).
    processes : bool, optional
        Local workers as processes (True) or threads in this process (False); default:
        threads for small searches, processes for big ones where the script allows (a plain
        script needs its call under ``if __name__ == "__main__":`` for processes; without it
        the search runs on threads, or, with processes=True, is refused with that advice).
    progress : callable (done, total), bool or None, optional
        Called after each finished task; True: a progress line on stderr
        (:class:`~epicyclic.synthesis.progress.ProgressLine`: tasks, percent, time left); None (default):
        that line where stderr is a terminal and ``announce`` is True; False: none.
    chunk : int, optional
        Mechanisms per Dask task (default: about 8, fewer for small searches).
    announce : callable (str) or bool, default True
        The bound and estimate of the search, before it starts: True prints it to stderr.
    checkpoint : str or Path, optional
        Resumable: finished tasks are kept in this file (written atomically) and not run again.
    on_candidates : callable (tuple of Candidate), optional
        Each finished task's candidates, as it finishes.

    Returns
    -------
    SynthesisResult
        Ranked candidates (table, JSON, CSV, TOML files, plot).

    Raises
    ------
    SynthesisError
        Invalid targets, sets, elements or constraints.

    References
    ----------
    Kahraman et al. 2004, J. Mech. Des. 126(6), 1071–1081.

    Examples
    --------
    >>> res = synthesize([2.46, 1.46, 1.0, -2.18], sets=2, elements={"brakes": 2, "clutches": 2, "engaged": 2},
    ...                  constraints={"tolerance": 0.01}, workers=1, announce=False)
    >>> len(res) > 0, res.best.metrics["double_shifts"], round(res.best.ratios[2], 6)
    (True, 0, 1.0)
    """
    spec = SynthesisSpec.create(targets, sets, elements, constraints)
    return synthesize_spec(spec, client=client, scheduler=scheduler, workers=workers, processes=processes,
                           progress=progress, chunk=chunk, announce=announce, checkpoint=checkpoint,
                           on_candidates=on_candidates)
