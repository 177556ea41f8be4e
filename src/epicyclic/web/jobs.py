"""Run the page's work in worker processes with a time limit (:mod:`pebble`).

Solving, drawing and reporting happen in a pool of worker processes, never in
the server process: a request that runs past its time limit has its worker
stopped and replaced (pebble), so neither a hostile input nor a bug can hold
the server, and the server keeps answering other requests meanwhile.  Each
worker imports the library once (``forkserver`` with the views preloaded).

The work is bounded every way a client could make it unbounded:

* the jobs waiting or running in all: past ``max_queue`` the page answers 503 at
  once instead of queuing without end;
* the jobs of one client: past ``max_client_jobs`` it answers 429, so one page
  or script cannot fill the queue for everyone.  A client is its network
  address (the part of the ``client`` key before its first space), which it
  cannot mint freely; the page's id (``X-Epicyclic-Client``, one per tab) is
  the client's own choice and counts for nothing here;
* the jobs wait in a fair queue (:class:`FairQueue`): a worker that becomes
  free takes the next job of the next client in turn, so a client with many
  jobs waiting does not make another wait for all of them;
* a job whose client has gone (the browser closed the connection: a newer
  request replaced it, the tab was closed) is cancelled, its worker stopped
  and replaced, so no worker computes for nobody;
* each worker's address space (``RLIMIT_AS``, Linux) may grow by
  ``worker_memory`` bytes beyond what it has after its start; an allocation
  past it fails in the worker and the page says so (507), instead of the
  computer running out of memory.
"""

from __future__ import annotations

import asyncio
import multiprocessing
import sys
import traceback
from collections.abc import Awaitable, Callable
from concurrent.futures import CancelledError, TimeoutError as FutureTimeout
from typing import Any

from .render import Reply, render

__all__ = ["Jobs", "FairQueue", "failure", "peer_of"]


def peer_of(client: str) -> str:
    """The part of a client key that the caps and the queue count by: its network address, the text before
    the first space (``"127.0.0.1 <page id>"`` → ``"127.0.0.1"``)."""
    return client.split(" ", 1)[0]


class FairQueue:
    """Turns at ``slots`` workers, taken round robin over the clients waiting (each client's jobs in order).

    A job ``await acquire(client)`` before it runs and calls :meth:`release` after; a waiter that is
    cancelled (its client left, its time ran out) leaves the queue.

    Examples
    --------
    >>> import asyncio
    >>> async def order():
    ...     queue, done = FairQueue(1), []
    ...     async def job(client, k):
    ...         await queue.acquire(client)
    ...         done.append(f"{client}{k}")
    ...         await asyncio.sleep(0)
    ...         queue.release()
    ...     await asyncio.gather(*(job("a", k) for k in range(3)), job("b", 0))
    ...     return done
    >>> asyncio.run(order())
    ['a0', 'a1', 'b0', 'a2']
    """

    def __init__(self, slots: int):
        self.slots, self.busy = max(1, int(slots)), 0
        self.waiting: dict[str, list[asyncio.Future]] = {}  # insertion order: the round robin's turn

    async def acquire(self, client: str) -> None:
        if self.busy < self.slots and not self.waiting:
            self.busy += 1
            return
        turn = asyncio.get_running_loop().create_future()
        self.waiting.setdefault(client, []).append(turn)
        try:
            await turn
        except asyncio.CancelledError:
            if turn.done() and not turn.cancelled():  # granted while being cancelled: pass it on
                self.release()
            else:
                queue = self.waiting.get(client, [])
                if turn in queue:
                    queue.remove(turn)
                if not queue:
                    self.waiting.pop(client, None)
            raise

    def release(self) -> None:
        self.busy -= 1
        while self.waiting and self.busy < self.slots:
            client = next(iter(self.waiting))
            queue = self.waiting.pop(client)
            turn = queue.pop(0)
            if queue:
                self.waiting[client] = queue  # to the end of the turn
            if not turn.done():
                self.busy += 1
                turn.set_result(None)


def _address_space() -> int | None:
    """The bytes of address space this process has mapped (Linux ``/proc``), or None elsewhere."""
    import os

    try:
        with open("/proc/self/statm") as statm:
            return int(statm.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return None


def _limit_memory(extra: int | None) -> None:
    """Let this process's address space grow by at most ``extra`` bytes (RLIMIT_AS; nothing where
    the platform has no such limit)."""
    if not extra:
        return
    try:
        import resource
    except ImportError:  # pragma: no cover - not on Windows
        return
    mapped = _address_space()
    if mapped is None or not hasattr(resource, "RLIMIT_AS"):  # pragma: no cover - not Linux
        return
    limit = mapped + int(extra)
    _, hard = resource.getrlimit(resource.RLIMIT_AS)
    if hard != resource.RLIM_INFINITY:
        limit = min(limit, hard)
    resource.setrlimit(resource.RLIMIT_AS, (limit, hard))


def _start_worker(memory: int | None = None) -> None:
    """Worker process setup: files-only matplotlib backend; one small drawing so that the first picture
    a user asks for does not pay for matplotlib's first-time setup (fonts, text layout); then the memory
    limit (after the setup, which maps fonts and libraries)."""
    _warm_up()
    try:
        _limit_memory(memory)
    except (OSError, ValueError):  # pragma: no cover - a platform that refuses: run without the limit
        traceback.print_exc(file=sys.stderr)


def _warm_up() -> None:
    try:  # never fail here: a worker whose setup fails would be restarted without end
        import matplotlib

        matplotlib.use("Agg")
        matplotlib.rcParams["text.parse_math"] = False  # a '$' in a title or name is text, as in `epicyclic plot`
        import matplotlib.pyplot as plt

        from ..plotting import figure_svg

        fig, ax = plt.subplots(figsize=(1, 1))
        ax.set_title("n in 1/min")
        figure_svg(fig)
    except Exception:  # pragma: no cover - the pictures then just start slower
        traceback.print_exc(file=sys.stderr)


def failure(message: str, status: int) -> Reply:
    """A problem box with ``message`` (escaped by the template)."""
    from .editor import Problem

    return Reply(render("problem.html", problem=Problem(message), text=None, oob=False), status)


class Jobs:
    """A pool of worker processes that answers with :class:`~epicyclic.web.views.Reply` objects.

    Parameters
    ----------
    workers : int
        Worker processes (at least 1).
    max_queue : int
        Jobs waiting or running at most; more are refused with 503.
    queue_wait : float
        Seconds a job may wait for a worker on top of its own time limit (then 504).
    max_client_jobs : int
        Jobs of one client (its address, :func:`peer_of`) waiting or running at most; more are refused with 429.
    worker_memory : int or None
        Bytes each worker's address space may grow after its start (None: no limit).
    """

    def __init__(self, workers: int = 2, max_queue: int = 256, queue_wait: float = 120.0,
                 max_client_jobs: int = 16, worker_memory: int | None = 2 << 30):
        from pebble import ProcessPool

        context = multiprocessing.get_context("forkserver")
        context.set_forkserver_preload(["epicyclic.web.views", "epicyclic.plotting", "matplotlib.pyplot"])
        self.pool = ProcessPool(max_workers=max(1, int(workers)), initializer=_start_worker,
                                initargs=(worker_memory,), context=context)
        self.max_queue, self.queue_wait, self.max_client_jobs = max_queue, queue_wait, max_client_jobs
        self.workers = max(1, int(workers))
        self.worker_memory = worker_memory
        self.pending = 0
        self.per_client: dict[str, int] = {}
        self.queue = FairQueue(self.workers)
        #: Jobs started and jobs cancelled because their client left (for the tests and the benchmarks).
        self.started = self.cancelled = 0

    async def run(self, function: Callable[..., Reply], *args: Any, timeout: float, client: str = "",
                  gone: Callable[[], Awaitable[Any]] | None = None) -> Reply:
        """``function(*args)`` in a worker.

        504 after ``timeout`` seconds of work, 503 when the server is too busy, 429 when ``client`` has
        too many jobs, 507 when the worker ran out of its memory; ``gone()`` returns when the client has
        left, and the job is then cancelled (the answer, 499, reaches nobody).
        """
        if self.pending >= self.max_queue:
            return failure(f"the server is busy ({self.pending} requests waiting); try again in a moment.", 503)
        peer = peer_of(client)
        if self.per_client.get(peer, 0) >= self.max_client_jobs:
            return failure(f"too many requests at once from this computer ({self.max_client_jobs} are waiting or "
                           "running); wait for them to finish.", 429)
        self.pending += 1
        self.started += 1
        self.per_client[peer] = self.per_client.get(peer, 0) + 1
        watch = asyncio.ensure_future(gone()) if gone is not None else None
        work = None

        async def turn() -> Reply:
            await self.queue.acquire(peer)
            try:
                future = self.pool.schedule(function, args=args, timeout=timeout)
                try:
                    return await asyncio.wrap_future(future)
                except asyncio.CancelledError:
                    future.cancel()  # pebble stops a running job's worker and starts a new one
                    raise
            finally:
                self.queue.release()

        try:
            # pebble stops the work after `timeout`; the outer limit also bounds the wait in the queue
            work = asyncio.ensure_future(asyncio.wait_for(turn(), timeout + self.queue_wait))
            done, _ = await asyncio.wait({work} | ({watch} if watch else set()), return_when=asyncio.FIRST_COMPLETED)
            if work not in done:
                work.cancel()
                self.cancelled += 1
                return failure("the client left; the computation was cancelled.", 499)
            return work.result()
        except (FutureTimeout, asyncio.TimeoutError):
            return failure(f"the computation took longer than {timeout:g} s and was stopped; the limit keeps the "
                           "server responsive. Simplify the input (fewer elements, narrower search bounds).", 504)
        except MemoryError:
            limit = f"{self.worker_memory / 2**20:.0f} MiB" if self.worker_memory else "the memory available"
            return failure(f"the computation needed more memory than a worker may use ({limit} beyond its start; "
                           "epicyclic serve --worker-memory sets it) and was stopped. Ask for less at once: fewer "
                           "map points, narrower search bounds, a smaller picture.", 507)
        except CancelledError:  # pragma: no cover - the pool was closed while the job waited
            return failure("the server is stopping; the computation was cancelled.", 503)
        except Exception as exc:  # a worker that died (memory, signal) or could not send its answer
            return failure(f"internal error: the worker stopped ({type(exc).__name__}: {exc}). This is a bug in "
                           "epicyclic or the input exhausted the worker; please report it.", 500)
        finally:
            for task in (watch, work):
                if task is None:
                    continue
                if not task.done():
                    task.cancel()
                elif not task.cancelled():
                    task.exception()  # retrieved: a pool stopped under a job is no unhandled error
            self.pending -= 1
            self.per_client[peer] -= 1
            if not self.per_client[peer]:
                del self.per_client[peer]

    def close(self) -> None:
        """Stop the workers (running jobs are abandoned)."""
        self.pool.stop()
        self.pool.join()
