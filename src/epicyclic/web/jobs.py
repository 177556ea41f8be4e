"""Run the page's work in worker processes with a time limit (:mod:`pebble`).

Solving, drawing and reporting happen in a pool of worker processes, never in
the server process: a request that runs past its time limit has its worker
stopped and replaced (pebble), so neither a hostile input nor a bug can hold
the server, and the server keeps answering other requests meanwhile.  Each
worker imports the library once (``forkserver`` with the views preloaded).

The number of waiting jobs is bounded too: past ``max_queue`` the page answers
503 at once instead of queuing without end.
"""

from __future__ import annotations

import asyncio
import multiprocessing
import sys
import traceback
from collections.abc import Callable
from concurrent.futures import TimeoutError as FutureTimeout
from typing import Any

from .render import Reply, render

__all__ = ["Jobs", "failure"]


def _start_worker() -> None:
    """Worker process setup: files-only matplotlib backend; one small drawing so that the first picture
    a user asks for does not pay for matplotlib's first-time setup (fonts, text layout)."""
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
    """

    def __init__(self, workers: int = 2, max_queue: int = 1000, queue_wait: float = 120.0):
        from pebble import ProcessPool

        context = multiprocessing.get_context("forkserver")
        context.set_forkserver_preload(["epicyclic.web.views", "epicyclic.plotting", "matplotlib.pyplot"])
        self.pool = ProcessPool(max_workers=max(1, int(workers)), initializer=_start_worker, context=context)
        self.max_queue = max_queue
        self.queue_wait = queue_wait
        self.pending = 0

    async def run(self, function: Callable[..., Reply], *args: Any, timeout: float) -> Reply:
        """``function(*args)`` in a worker; 504 after ``timeout`` seconds of work, 503 when too busy."""
        if self.pending >= self.max_queue:
            return failure(f"the server is busy ({self.pending} requests waiting); try again in a moment.", 503)
        self.pending += 1
        try:
            future = self.pool.schedule(function, args=args, timeout=timeout)
            # pebble stops the work after `timeout`; the outer limit also bounds the wait in the queue
            return await asyncio.wait_for(asyncio.wrap_future(future), timeout + self.queue_wait)
        except (FutureTimeout, asyncio.TimeoutError):
            return failure(f"the computation took longer than {timeout:g} s and was stopped; the limit keeps the "
                           "server responsive. Simplify the input (fewer elements, narrower search bounds).", 504)
        except Exception as exc:  # a worker that died (memory, signal) or could not send its answer
            return failure(f"internal error: the worker stopped ({type(exc).__name__}: {exc}). This is a bug in "
                           "epicyclic or the input exhausted the worker; please report it.", 500)
        finally:
            self.pending -= 1

    def close(self) -> None:
        """Stop the workers (running jobs are abandoned)."""
        self.pool.stop()
        self.pool.join()
