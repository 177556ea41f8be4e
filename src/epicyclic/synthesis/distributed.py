"""Running independent search tasks: in this process, on local Dask workers, or on an existing cluster.

Tasks are submitted with :meth:`distributed.Client.map` and collected with
:func:`distributed.as_completed` as they finish, so progress can be reported
per task.  Where the work runs (:func:`run_tasks`):

* a ``client`` or a ``scheduler`` address: that cluster;
* one worker of threads (``workers=1``, no processes): the tasks run one after
  the other in the calling thread (no cluster is started: works in a script,
  a notebook and a web server alike);
* otherwise a :class:`distributed.LocalCluster` of threads in this process
  (the default for small searches) or of worker processes (asked for, or
  chosen for a big search, see :func:`use_processes`).

Worker processes are *spawned*: each imports the main module again.  A plain
script whose call is not under ``if __name__ == "__main__":`` would run its
search again in every worker; :func:`main_is_guarded` reads the script to tell,
and then processes asked for are refused with a message saying so, and
processes chosen automatically give way to threads.

References
----------
Dask documentation, "dask.distributed: Futures" and "LocalCluster"
(docs.dask.org / distributed.dask.org); Python documentation, "multiprocessing —
Contexts and start methods" and "Safe importing of main module".
"""

from __future__ import annotations

import ast
import logging
import os
import sys
import time
import warnings
from collections.abc import Callable, Sequence
from typing import Any

from ..limits import MAX_SYNTHESIS_WORKERS

__all__ = ["run_tasks", "main_is_guarded", "use_processes", "check_workers", "PROCESS_THRESHOLD_S"]

#: Estimated worker-seconds from which the default local cluster uses processes instead of threads.
PROCESS_THRESHOLD_S = 120.0

_GUARD_ADVICE = ("worker processes import the main script again, so a script that calls synthesize must do so "
                 "under `if __name__ == \"__main__\":` (Python's multiprocessing rule); add that guard, or pass "
                 "processes=False (threads in this process)")


def check_workers(workers: Any, where: str = "synthesize") -> int | None:
    """``workers`` as a whole number in 1 … :data:`~epicyclic.limits.MAX_SYNTHESIS_WORKERS` (or None).

    Parameters
    ----------
    workers : int or None
    where : str, default "synthesize"
        First word of the message (``--workers`` on the command line).

    Raises
    ------
    SynthesisError
    """
    from .spec import SynthesisError

    if workers is None:
        return None
    if isinstance(workers, bool) or not isinstance(workers, int) or not 1 <= workers <= MAX_SYNTHESIS_WORKERS:
        raise SynthesisError(f"{where}: workers must be a whole number in 1 … {MAX_SYNTHESIS_WORKERS} (local "
                             f"workers; a larger cluster is reached with a scheduler address), got {workers!r:.40}.")
    return workers


def main_is_guarded() -> bool:
    """Whether spawned worker processes can import the main module without running the search again.

    True in a notebook, the interactive interpreter, ``python -c`` and inside a worker-free main
    module; for a script (or ``python -m module``) True only when the call being made now lies under
    ``if __name__ == "__main__":`` in it (read with :mod:`ast`).
    """
    main = sys.modules.get("__main__")
    path = getattr(main, "__file__", None)
    if main is None or path is None:
        return True  # interactive, notebook, -c: nothing is imported again
    frame = _module_frame(sys._getframe(1), main)
    if frame is None:  # called from another thread: is the main thread still running the script's body?
        import threading

        frame = _module_frame(sys._current_frames().get(threading.main_thread().ident), main)
    if frame is None:
        return True  # the main module has finished running (called later, e.g. from a callback)
    try:
        with open(path, encoding="utf-8") as handle:
            tree = ast.parse(handle.read())
    except (OSError, SyntaxError, ValueError):
        return False
    line = frame.f_lineno
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and _is_main_test(node.test) and node.body:
            if node.body[0].lineno <= line <= (node.body[-1].end_lineno or node.body[-1].lineno):
                return True
    return False


def _module_frame(frame: Any, main: Any) -> Any:
    """The frame running the main module's body on this stack, or None."""
    while frame is not None and not (frame.f_globals is vars(main) and frame.f_code.co_name == "<module>"):
        frame = frame.f_back
    return frame


def _is_main_test(test: ast.expr) -> bool:
    """``__name__ == "__main__"`` (either side)."""
    if not (isinstance(test, ast.Compare) and len(test.ops) == 1 and isinstance(test.ops[0], ast.Eq)):
        return False
    sides = [test.left, test.comparators[0]]
    return (any(isinstance(s, ast.Name) and s.id == "__name__" for s in sides)
            and any(isinstance(s, ast.Constant) and s.value == "__main__" for s in sides))


def use_processes(processes: bool | None, worker_seconds: float, workers: int) -> tuple[bool, str | None]:
    """Whether the local cluster uses worker processes, and a note when the choice was not the one asked for.

    Parameters
    ----------
    processes : bool or None
        Asked for (True/False) or left to the search (None: processes for a search estimated at
        :data:`PROCESS_THRESHOLD_S` worker-seconds or more on more than one worker).
    worker_seconds : float
        The search's estimated screening time on one worker.
    workers : int
        Local workers.

    Raises
    ------
    SynthesisError
        Processes asked for by a script whose call is not under ``if __name__ == "__main__":``.
    """
    from .spec import SynthesisError

    if processes is False or workers <= 1 and processes is None:
        return False, None
    if processes is None and worker_seconds < PROCESS_THRESHOLD_S:
        return False, None
    if main_is_guarded() and not _in_spawned_child():
        return True, None
    if processes:
        raise SynthesisError(f"synthesize: processes=True, but {_GUARD_ADVICE}.")
    return False, (f"synthesize: running on threads in this process: {_GUARD_ADVICE} to use worker processes "
                   "for this big search.")


def _in_spawned_child() -> bool:
    import multiprocessing

    return multiprocessing.parent_process() is not None and sys.modules.get("__main__", None) is not None \
        and getattr(sys.modules["__main__"], "__name__", "") == "__mp_main__"


def run_tasks(function: Callable[[Any], Any], tasks: Sequence[Any], *, client: Any = None,
              scheduler: str | None = None, workers: int | None = None, processes: bool = False,
              progress: Callable[[int, int], None] | None = None, timeout: str = "10s",
              time_limit: float | None = None, done: dict[int, Any] | None = None,
              on_result: Callable[[int, Any], None] | None = None) -> tuple[list[Any], int]:
    """Run ``function(task)`` for every task; return (results in task order, workers used).

    Parameters
    ----------
    function : callable
        Importable top-level function (workers import it by name).
    tasks : sequence
        Picklable arguments, one per task.
    client : distributed.Client, optional
        Use this client (left open).
    scheduler : str, optional
        Connect to this scheduler address (``tcp://host:8786``).
    workers : int, optional
        Workers of a local cluster (default: CPU count).
    processes : bool, default False
        Local workers as processes (False: threads of this process; with one worker the tasks run in
        the calling thread, no cluster).
    progress : callable (done, total), optional
    timeout : str, default "10s"
        How long to try to reach ``scheduler``.
    time_limit : float, optional
        Seconds: tasks not finished by then are cancelled and their results are None.
    done : dict (task index → result), optional
        Results already known (a checkpoint): those tasks are not run again.
    on_result : callable (task index, result), optional
        Called in this process as each task finishes, in the order they finish (results stream).

    Raises
    ------
    SynthesisError
        The scheduler cannot be reached, or worker processes cannot start.
    """
    from .spec import SynthesisError

    deadline = None if time_limit is None else time.monotonic() + time_limit
    done = dict(done or {})
    todo = [k for k in range(len(tasks)) if k not in done]
    if client is None and not scheduler and workers == 1 and not processes:
        return _run_here(function, tasks, todo, done, progress, deadline, on_result), 1
    from distributed import Client, LocalCluster, as_completed

    own_cluster = own_client = None
    if client is None:
        if scheduler:
            try:
                client = own_client = Client(scheduler, timeout=timeout)
            except (OSError, ValueError) as exc:
                raise SynthesisError(
                    f"synthesize: cannot reach the Dask scheduler at {scheduler!r} ({exc}); start one "
                    "(`dask scheduler`, then `dask worker ADDRESS` on each machine) or leave out --scheduler "
                    "to run on a local cluster.") from None
        else:
            import dask

            n = workers or os.cpu_count() or 1
            # Dask's default MALLOC_TRIM_THRESHOLD_ for worker processes switches off glibc's adaptive
            # mmap threshold: every temporary numpy array is then a fresh mmap (page faults, system time
            # three times the work).  The search allocates many such arrays, so keep glibc's default.
            environ = {k: v for k, v in dask.config.get("distributed.nanny.pre-spawn-environ", {}).items()
                       if k != "MALLOC_TRIM_THRESHOLD_"}
            try:
                with dask.config.set({"distributed.nanny.pre-spawn-environ": environ}), warnings.catch_warnings():
                    # the scheduler's small HTTP server moves to a free port when 8787 is taken: not worth a warning
                    warnings.filterwarnings("ignore", message="Port .* is already in use", category=UserWarning)
                    own_cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=processes,
                                               dashboard_address=None, silence_logs=logging.ERROR)
            except RuntimeError as exc:  # a worker process that could not start (bootstrapping, resources)
                raise SynthesisError(f"synthesize: the local Dask worker processes did not start ({exc}); "
                                     f"{_GUARD_ADVICE}.") from None
            client = own_client = Client(own_cluster)
    try:
        used = len(client.scheduler_info().get("workers", {})) or 1
        results: list[Any] = [done.get(k) for k in range(len(tasks))]
        futures = client.map(function, [tasks[k] for k in todo], pure=False) if todo else []
        order = {f.key: k for k, f in zip(todo, futures)}
        finished = len(done)
        if progress:
            progress(finished, len(tasks))
        remaining = None if deadline is None else max(deadline - time.monotonic(), 0.0)
        try:
            for future in as_completed(futures, timeout=remaining):
                index = order[future.key]
                results[index] = future.result()
                finished += 1
                if on_result:
                    on_result(index, results[index])
                if progress:
                    progress(finished, len(tasks))
        except TimeoutError:
            client.cancel([f for f in futures if not f.done()])
        return results, used
    finally:
        if own_client is not None:
            own_client.close()
        if own_cluster is not None:
            own_cluster.close()


def _run_here(function: Callable[[Any], Any], tasks: Sequence[Any], todo: list[int], done: dict[int, Any],
              progress: Callable[[int, int], None] | None, deadline: float | None,
              on_result: Callable[[int, Any], None] | None) -> list[Any]:
    """The tasks still to do one after the other in this thread (results None after the deadline)."""
    results: list[Any] = [done.get(k) for k in range(len(tasks))]
    finished = len(done)
    if progress:
        progress(finished, len(tasks))
    for k in todo:
        if deadline is not None and time.monotonic() >= deadline:
            break
        results[k] = function(tasks[k])
        finished += 1
        if on_result:
            on_result(k, results[k])
        if progress:
            progress(finished, len(tasks))
    return results
