"""Pictures drawn once per file and gear, and drawn ahead for the gears the page shows next.

Drawing is the page's slow part (matplotlib: 0.1–1 s a picture, the ZF 8HP
speed plan with four sets about 1 s), the tables take milliseconds.  A
picture is a pure function of what it is drawn from: the text, its name for
messages, the units and the gear shown and the picture's own settings (the set shown, the
animation's size); :func:`figure_key` is that, hashed.  The server process
keeps the answers in :class:`FigureCache` (least recently used first out,
bounded in bytes), so a picture asked for again (back to a gear, the same
example opened in another tab) is answered without a worker.

After an answer for a transmission the worker names the gears the page shows
after a click on another gear (:attr:`epicyclic.web.render.Reply.next_gears`,
nearest gear first); :meth:`FigureCache.draw_ahead` draws their pictures one
at a time, only while no request of a client waits and on all workers but one
(a picture drawn ahead takes up to a second; the page's own requests that come
right after an answer find a worker free), so drawing ahead never slows down
what a user asked for.  A newer plan of the same page replaces an older one.
"""

from __future__ import annotations

import asyncio
import hashlib
import json
from collections import OrderedDict
from collections.abc import Awaitable, Callable, Sequence
from dataclasses import replace
from typing import Any

from .render import Reply
from .state import PageState

__all__ = ["FigureCache", "figure_key", "AHEAD_KINDS"]

#: The pictures drawn ahead by default (the animation is cheap and depends on the set chosen in the page; a page
#: whose browser draws the charts has the server draw ahead only the others, :func:`epicyclic.web.charts.ahead_kinds`).
AHEAD_KINDS = ("speed", "lever", "chart", "torque", "power", "flow")


def figure_key(state: PageState, name: str) -> str | None:
    """What picture ``name`` of ``state`` is drawn from, hashed; None where the settings are not readable
    (the worker then gives the message)."""
    from ..errors import EpicyclicError
    from .figures import FIGURES, read_settings

    kind = FIGURES.get(name)
    if kind is None:
        return None
    try:
        settings = read_settings(kind, state.extra)
    except EpicyclicError:
        return None
    shown = (settings.option, settings.size, settings.frames, settings.fps) if kind.animated else (settings.option,)
    data = json.dumps([name, state.text, state.source, state.units, state.gear, *shown], ensure_ascii=False)
    return hashlib.sha256(data.encode("utf-8", "surrogatepass")).hexdigest()


class FigureCache:
    """Picture answers by :func:`figure_key`, at most ``max_bytes`` of them; drawing ahead for the next gears.

    Parameters
    ----------
    max_bytes : int, default 64 MiB
        The answers kept at most (their bodies' bytes); the least recently used go first.
    kinds : tuple of str, default AHEAD_KINDS
        The pictures drawn ahead.
    """

    def __init__(self, max_bytes: int = 64 << 20, kinds: tuple[str, ...] = AHEAD_KINDS):
        self.max_bytes = max_bytes
        self.kinds = kinds
        self.size = 0
        self.answers: OrderedDict[str, Reply] = OrderedDict()
        self.drawing: dict[str, asyncio.Future] = {}  # drawn ahead right now
        self.plans: dict[str, asyncio.Task] = {}  # page → its plan of drawing ahead
        self.generation: dict[str, int] = {}  # page → number of its newest plan (an older one stops)
        self.tasks: set[asyncio.Task] = set()  # drawings ahead under way
        self.hits = self.misses = self.drawn_ahead = 0
        self.ahead_running = 0  # jobs drawing ahead now (none while a client waits; one worker kept for clients)

    def get(self, key: str) -> Reply | None:
        """The answer kept for ``key``, if any (it becomes the most recently used)."""
        reply = self.answers.get(key)
        if reply is not None:
            self.answers.move_to_end(key)
        return reply

    def put(self, key: str, reply: Reply) -> None:
        """Keep ``reply`` (only a picture drawn: status 200)."""
        if reply.status != 200 or key in self.answers:
            return
        size = len(reply.body)
        if size > self.max_bytes:
            return
        self.answers[key] = reply
        self.size += size
        while self.size > self.max_bytes:
            _, old = self.answers.popitem(last=False)
            self.size -= len(old.body)

    async def answer(self, key: str | None, draw: Callable[[], Awaitable[Reply]]) -> Reply:
        """The kept answer, the one being drawn ahead, or ``draw()`` (kept when it is a picture)."""
        if key is None:
            return await draw()
        kept = self.get(key)
        if kept is None and key in self.drawing:
            future = self.drawing[key]
            try:
                kept = await asyncio.shield(future)
            except asyncio.CancelledError:
                if not future.cancelled():
                    raise  # this request was cancelled, not the drawing
                kept = None
        if kept is not None and kept.status == 200:
            self.hits += 1
            return kept
        self.misses += 1
        reply = await draw()
        self.put(key, reply)
        return reply

    def draw_ahead(self, page: str, state: PageState, gears: Sequence[str], jobs: Any, figure: Callable,
                   timeout: float) -> None:
        """Draw the pictures of ``gears`` (as ``state`` in that gear) while the server is idle."""
        self.draw_states_ahead(page, [replace(state, gear=gear, rows=(), extra={}) for gear in gears], jobs, figure,
                               timeout)

    def draw_states_ahead(self, page: str, states: Sequence[PageState], jobs: Any, figure: Callable,
                          timeout: float) -> None:
        """Draw the pictures of each of ``states`` (in this order) while the server is idle; a newer plan of
        the same ``page`` replaces this one."""
        self.generation[page] = generation = self.generation.get(page, 0) + 1
        if states and self.max_bytes:  # a cache that keeps nothing draws nothing ahead
            self.plans[page] = asyncio.ensure_future(self._plan(page, generation, states, jobs, figure, timeout))

    async def _plan(self, page: str, generation: int, states: Sequence[PageState], jobs: Any,
                    figure: Callable, timeout: float) -> None:
        def stale() -> bool:
            return self.generation.get(page) != generation

        try:
            for ahead in states:
                for name in self.kinds:
                    key = figure_key(ahead, name)
                    if key is None or key in self.answers or key in self.drawing:
                        continue
                    while not stale() and (jobs.pending > self.ahead_running  # a client waits
                                           or self.ahead_running >= max(1, jobs.workers - 1)):  # one kept free
                        await asyncio.sleep(0.05)
                    if stale():  # the page shows something else now: its newer plan draws
                        return
                    future = asyncio.get_running_loop().create_future()
                    self.drawing[key] = future
                    self.ahead_running += 1
                    task = asyncio.ensure_future(self._draw(key, future, jobs, figure, ahead, name, timeout))
                    self.tasks.add(task)
                    task.add_done_callback(self.tasks.discard)
        except asyncio.CancelledError:
            pass
        finally:
            if self.plans.get(page) is asyncio.current_task():
                del self.plans[page]
                del self.generation[page]

    async def _draw(self, key: str, future: asyncio.Future, jobs: Any, figure: Callable, state: PageState,
                    name: str, timeout: float) -> None:
        try:
            reply = await jobs.run(figure, state, name, timeout=timeout, client="ahead")
        except BaseException:  # the server stops
            future.cancel()
            raise
        finally:
            self.drawing.pop(key, None)
            self.ahead_running -= 1
        future.set_result(reply)
        if reply.status == 200:
            self.put(key, reply)
            self.drawn_ahead += 1

    def close(self) -> None:
        """Stop drawing ahead (the server stops)."""
        for task in (*self.plans.values(), *self.tasks):
            task.cancel()
