"""The server's side of the page's synthesis: start, progress, cancel, open a candidate (routes).

A search is one job of :mod:`epicyclic.web.jobs` (it counts for the client's
jobs and the queue, and is cancelled when its client leaves): the request
that starts it stays open until the search ends and answers with the ranked
candidates (:func:`epicyclic.web.synthesis_tool.search_view`).  Meanwhile the
page polls ``/synthesis/progress``, which the server answers from the
``progress.json`` the worker writes (nothing is computed for it), and
``/synthesis/cancel`` stops the search: its worker is stopped at once (pebble)
and the candidates of the finished tasks, kept in the search's task log, are
ranked in another job and sent as the start request's answer, saying that the
search was cancelled.  The same happens when a task overruns the page's time
limit.

Bounds: one search per client (the page's id, as for the jobs) and at most
``max(1, workers - 1)`` searches at once, so that a worker is left for the
page's other work; each search has its own folder in a temporary folder of
the server, made from an id the page gives (checked: letters, digits and
dashes) and removed when the search ends.

References
----------
htmx documentation, "hx-trigger" (polling, 286 stops it) and "hx-preserve".
"""

from __future__ import annotations

import asyncio
import re
import shutil
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

from starlette.requests import Request
from starlette.responses import Response
from starlette.routing import Route

from .jobs import failure
from .render import Reply, render
from .state import FormError, PageState, clean_text

__all__ = ["Search", "Searches", "synthesis_routes"]

#: Seconds a search's worker may run past the page's time limit (a task that overruns it) before it is stopped.
GRACE_SECONDS = 15.0
#: The id the page gives a search.
_ID = re.compile(r"^[A-Za-z0-9-]{8,64}$")
#: The fields of the synthesis form (all of them start so) and the longest pasted spec.
_PREFIX = "synth_"


@dataclass
class Search:
    """A running search: its client, folder, when it started, and whether Cancel was pressed."""

    client: str
    folder: Path
    started: float = field(default_factory=time.time)
    cancel: asyncio.Event = field(default_factory=asyncio.Event)
    #: Seconds after which the page stops the search (``Limits.synthesis_seconds``; None: no limit).
    seconds: float | None = None


class Searches:
    """The running searches of one app, in a temporary folder of their own.

    Parameters
    ----------
    most : int
        Searches running at once at most.
    """

    def __init__(self, most: int):
        self.most = max(1, int(most))
        self._root = tempfile.TemporaryDirectory(prefix="epicyclic-synthesis-")
        self.root = Path(self._root.name)
        self.running: dict[str, Search] = {}
        #: Searches started and cancelled (for the tests).
        self.started = self.cancelled = 0

    def of(self, search_id: str, client: str) -> Search | None:
        """The running search ``search_id`` of ``client`` (None: none, or another client's)."""
        search = self.running.get(search_id)
        return search if search is not None and search.client == client else None


def _response(reply: Reply, status: int | None = None) -> Response:
    return Response(reply.body, status or reply.status, headers={"Cache-Control": "no-store"},
                    media_type=reply.media_type)


def _values(form: Any) -> dict[str, str]:
    """The synthesis form's fields (``synth_*``), as text."""
    from .synthesis_tool import MAX_SPEC

    values = {}
    for key, value in form.multi_items():
        if key.startswith(_PREFIX):
            values[key] = clean_text(value, key, MAX_SPEC if key == "synth_spec" else 400,
                                     single_line=key != "synth_spec")
    return values


def _eta(seconds: float) -> str:
    from ..synthesis.estimate import duration

    return duration(seconds)


def progress_state(state: dict[str, Any] | None, search: Search) -> dict[str, Any]:
    """What the progress line shows: tasks done of all, candidates so far, time so far and left (as the command
    line estimates it: the time per finished task so far times the tasks left).

    Parameters
    ----------
    state : dict or None
        The worker's ``progress.json`` (None: not started yet).
    search : Search
    """
    if not state:
        return {"started": False, "done": 0, "total": 0, "found": 0, "percent": 0, "eta": "", "stops": "", "elapsed": "",
                "announce": "", "cancelling": search.cancel.is_set()}
    done, total = int(state.get("done", 0)), int(state.get("total", 0))
    elapsed = max(time.time() - float(state.get("started", time.time())), 0.0)
    left = elapsed / done * (total - done) if 0 < done < total else None
    eta = _eta(left) if left is not None else ""
    stops = ""
    if left is not None and search.seconds is not None and elapsed + left > search.seconds:
        # the page stops the search before it could finish: say when, and how long the whole space would take
        eta = _eta(max(search.seconds - elapsed, 0.0))
        stops = (f"the page stops the search at {_eta(search.seconds)} (the whole space needs about "
                 f"{_eta(elapsed + left)}: run epicyclic synthesize for it)")
    return {"started": True, "done": done, "total": total, "found": int(state.get("found", 0)),
            "percent": 100 * done // max(total, 1), "eta": eta, "stops": stops, "elapsed": _eta(elapsed),
            "announce": str(state.get("announce", "")), "cancelling": search.cancel.is_set()}


def synthesis_routes(searches: Searches, limits: Any, form_of: Callable[..., Any],
                     client_of: Callable[[Request], str], run: Callable[..., Any]) -> list[Route]:
    """The routes of the Synthesis tab.

    Parameters
    ----------
    searches : Searches
        The app's running searches.
    limits : Limits
        The server's limits (``synthesis_architectures``, ``synthesis_seconds``, ``workers``, ``solve_timeout``).
    form_of : async callable (request) → form
        The app's form reader (its size and field limits).
    client_of : callable (request) → str
        The client a job counts for.
    run : async callable (request, function, *args) → Reply
        The app's way to run a function in a worker (cancelled when the client leaves).
    """
    from . import synthesis_tool as tool

    bound, seconds = limits.synthesis_architectures, limits.synthesis_seconds

    async def values_of(request: Request) -> dict[str, str]:
        return _values(await form_of(request))

    def bad(exc: Exception, status: int = 400) -> Response:
        return _response(failure(str(exc), status))

    async def estimate(request: Request) -> Response:
        try:
            values = await values_of(request)
        except FormError as exc:
            return bad(exc)
        return _response(await run(request, tool.estimate_view, values, bound, seconds))

    async def start(request: Request) -> Response:
        try:
            values = await values_of(request)
        except FormError as exc:
            return bad(exc)
        search_id = values.pop("synth_id", "")
        if not _ID.match(search_id):
            return bad(FormError("synthesis: the search needs an id of 8 to 64 letters, digits or dashes (the page "
                                 "gives one); reload the page."))
        client = client_of(request)
        if any(s.client == client for s in searches.running.values()):
            return bad(FormError("synthesis: a search of this page is running; cancel it or wait for it first."), 429)
        if len(searches.running) >= searches.most or search_id in searches.running:
            return bad(FormError(f"synthesis: the server runs {searches.most} search(es) at once and is busy with "
                                 "another; try again in a moment, or run `epicyclic synthesize` on the command "
                                 "line."), 503)
        folder = searches.root / search_id
        folder.mkdir()
        search = searches.running[search_id] = Search(client, folder, seconds=seconds)
        searches.started += 1

        async def gone() -> None:  # the client left, or pressed Cancel
            async def left() -> None:
                while (await request.receive())["type"] != "http.disconnect":
                    pass

            waits = [asyncio.ensure_future(left()), asyncio.ensure_future(search.cancel.wait())]
            try:
                await asyncio.wait(waits, return_when=asyncio.FIRST_COMPLETED)
            finally:
                for task in waits:
                    task.cancel()

        jobs = request.app.state.jobs
        try:
            reply = await jobs.run(tool.search_view, values, str(folder), bound, seconds,
                                   timeout=seconds + GRACE_SECONDS, client=client, gone=gone)
            stopped = "cancelled" if search.cancel.is_set() else (
                f"stopped at the page's limit of {seconds:g} s" if reply.status == 504 else "")
            if stopped and reply.status in (499, 504):
                searches.cancelled += bool(search.cancel.is_set())
                reply = await jobs.run(tool.partial_view, values, str(folder), stopped, seconds,
                                       timeout=limits.solve_timeout, client=client)
            return _response(reply)
        finally:
            del searches.running[search_id]
            shutil.rmtree(folder, ignore_errors=True)

    async def search_of(request: Request) -> tuple[Search | None, Response | None]:
        try:
            values = await values_of(request)
        except FormError as exc:
            return None, bad(exc)
        return searches.of(values.get("synth_id", ""), client_of(request)), None

    async def progress(request: Request) -> Response:
        search, problem = await search_of(request)
        if problem is not None:
            return problem
        if search is None:  # finished (its answer has come or is coming): 286 stops the page's polling
            return Response("", 286, headers={"Cache-Control": "no-store"})
        state = progress_state(tool.read_progress(search.folder), search)
        return _response(Reply(render("synthesis_progress.html", **state)))

    async def cancel(request: Request) -> Response:
        search, problem = await search_of(request)
        if problem is not None:
            return problem
        if search is not None:
            search.cancel.set()
        return Response("", 204)

    async def open_candidate(request: Request) -> Response:
        """A candidate's train file in the editor, as a file opened from disk (a new document)."""
        from .views import open_text

        try:
            form = await form_of(request)
            text = clean_text(form.get("toml"), "toml", limits.max_body, single_line=False)
            name = clean_text(form.get("name"), "name", 200) or "candidate.toml"
            state = PageState(text, name, units=clean_text(form.get("units"), "units", 20) or "file",
                              lang=clean_text(form.get("lang"), "lang", 5) or "en")
        except FormError as exc:
            return bad(exc)
        return _response(await run(request, open_text, state.text, state.source, state.units, state.lang))

    async def panel(request: Request) -> Response:
        """The tab's fields (loaded once into the page, then kept)."""
        return _response(Reply(render("synthesis.html", fields=tool.FIELDS)))

    return [
        Route("/synthesis/panel", panel),
        Route("/synthesis/estimate", estimate, methods=["POST"]),
        Route("/synthesis/start", start, methods=["POST"]),
        Route("/synthesis/progress", progress, methods=["POST"]),
        Route("/synthesis/cancel", cancel, methods=["POST"]),
        Route("/synthesis/open", open_candidate, methods=["POST"]),
    ]
