"""Running independent search tasks on Dask (local cluster or an existing scheduler).

Tasks are submitted with :meth:`distributed.Client.map` and collected with
:func:`distributed.as_completed` as they finish, so progress can be reported
per task.  Without a client or scheduler address a
:class:`distributed.LocalCluster` with one thread per worker is started for
the run and closed afterwards.

References
----------
Dask documentation, "dask.distributed: Futures" and "LocalCluster"
(docs.dask.org / distributed.dask.org).
"""

from __future__ import annotations

import logging
import os
import warnings
from collections.abc import Callable, Sequence
from typing import Any

__all__ = ["run_tasks"]


def run_tasks(function: Callable[[Any], Any], tasks: Sequence[Any], *, client: Any = None,
              scheduler: str | None = None, workers: int | None = None, processes: bool = True,
              progress: Callable[[int, int], None] | None = None, timeout: str = "10s") -> tuple[list[Any], int]:
    """Run ``function(task)`` for every task on Dask; return (results in task order, workers used).

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
    processes : bool, default True
        Local workers as processes (False: threads of this process).
    progress : callable (done, total), optional
    timeout : str, default "10s"
        How long to try to reach ``scheduler``.

    Raises
    ------
    SynthesisError
        The scheduler cannot be reached.
    """
    from distributed import Client, LocalCluster, as_completed

    own_cluster = own_client = None
    if client is None:
        if scheduler:
            try:
                client = own_client = Client(scheduler, timeout=timeout)
            except (OSError, ValueError) as exc:
                from .spec import SynthesisError

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
            with dask.config.set({"distributed.nanny.pre-spawn-environ": environ}), warnings.catch_warnings():
                # the scheduler's small HTTP server moves to a free port when 8787 is taken: not worth a warning
                warnings.filterwarnings("ignore", message="Port .* is already in use", category=UserWarning)
                own_cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=processes,
                                           dashboard_address=None, silence_logs=logging.ERROR)
            client = own_client = Client(own_cluster)
    try:
        used = len(client.scheduler_info().get("workers", {})) or 1
        futures = client.map(function, list(tasks), pure=False)
        order = {f.key: k for k, f in enumerate(futures)}
        results: list[Any] = [None] * len(futures)
        done = 0
        if progress:
            progress(0, len(futures))
        for future in as_completed(futures):
            results[order[future.key]] = future.result()
            done += 1
            if progress:
                progress(done, len(futures))
        return results, used
    finally:
        if own_client is not None:
            own_client.close()
        if own_cluster is not None:
            own_cluster.close()
