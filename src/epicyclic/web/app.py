"""The web app of ``epicyclic serve`` (Starlette): routes, limits and security headers.

The server process only routes requests, checks their size and form, and hands
the work to worker processes (:mod:`epicyclic.web.jobs`), which answer with HTML
rendered from templates (:mod:`epicyclic.web.views`).  Safe by default:

* binds to loopback (``epicyclic serve`` defaults to 127.0.0.1) and accepts
  only requests addressed to this host (no DNS rebinding);
* request bodies larger than ``Limits.max_body`` are refused with 413, forms
  with too many fields or files with 400, bodies that stop arriving for
  ``Limits.body_timeout`` seconds with 408;
* POSTs from a page of another origin are refused with 403 (every POST
  computes; :class:`~epicyclic.web.guards.SameOrigin`);
* every computation has a time limit (504 after it, the worker is replaced),
  a memory limit per worker (507), is cancelled when its client leaves, and
  the jobs per client (429) and in all (503) are bounded
  (:mod:`epicyclic.web.jobs`);
* nothing the client sends becomes a path: examples are looked up by key in a
  table read at start, uploads are read in memory;
* every user text is escaped by the templates, and the Content-Security-Policy
  allows scripts from this server only (no inline scripts, no ``eval``).

Examples
--------
>>> from starlette.testclient import TestClient
>>> with TestClient(create_app(Limits(workers=1))) as client:
...     page = client.get("/")
...     answer = client.post("/example", data={"example": "brandenberger_1952"})
>>> page.status_code, answer.status_code, "0.85" in answer.text
(200, 200, True)
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass, replace
from typing import Any

from starlette.applications import Starlette
from starlette.middleware import Middleware
from starlette.middleware.trustedhost import TrustedHostMiddleware
from starlette.requests import Request
from starlette.responses import HTMLResponse, PlainTextResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from ..limits import MAX_FILE_BYTES
from .cache import FigureCache, figure_key
from .charts import ahead_kinds
from .examples import DEFAULT_EXAMPLE, bundled_examples
from .guards import BodyLimit, BodyTooLarge, BodyTooSlow, PageStatus, SameOrigin, SecurityHeaders
from .jobs import Jobs, failure
from .render import Reply, render
from .state import FormError, PageState, clean_text, restored_state
from .synthesis_routes import Searches, synthesis_routes
from .synthesis_tool import PAGE_ARCHITECTURES, PAGE_SECONDS
from .views import apply, download, figure, open_file, open_text, save_figure, shown_gear, tool, tool_fields

__all__ = ["Limits", "create_app", "LOOPBACK_HOSTS", "UNIT_LABELS"]

#: The units selector: value → label (the file's ``[units]`` and the presets of ``web.state.UNIT_PRESETS``).
UNIT_LABELS = (("file", "the file's units"), ("si", "SI (1/min, N·m, W)"), ("kw", "1/min, N·m, kW"),
               ("rpm-kw", "rpm, N·m, kW"), ("rpm-hp", "rpm, lbf·ft, hp"), ("rads-kw", "rad/s, N·m, kW"),
               ("mw", "1/min, kN·m, MW"))

#: Host names a loopback server answers to.
LOOPBACK_HOSTS = ("127.0.0.1", "localhost", "::1", "[::1]", "testserver")

@dataclass(frozen=True)
class Limits:
    """The server's limits.

    Parameters
    ----------
    max_body : int, default 4 MiB
        Largest request body in bytes: a TOML text or an uploaded file as large as the command line reads
        (:data:`epicyclic.limits.MAX_FILE_BYTES`, 1 MiB), sent URL-encoded (up to three bytes per byte).
    solve_timeout : float, default 10
        Seconds of work for a solve, a picture or a geometry form.
    report_timeout : float, default 60
        Seconds of work for a download (the HTML report draws every picture).
    workers : int, default 2
        Worker processes.
    max_queue : int, default 256
        Requests waiting for a worker or running at most (more get 503).
    max_client_jobs : int, default 16
        Requests of one client (its address and the page's client id) waiting or running at most (429).
    worker_memory : int or None, default 2 GiB
        Bytes each worker's address space may grow after its start (``RLIMIT_AS``; 507 past it).
    body_timeout : float, default 30
        Seconds a request body may send nothing before it is refused (408).
    request_deadline : float, default 20
        Seconds from a request's start until its headers are complete, and again until its body is (408): a
        request trickling in a byte at a time is cut off (:mod:`epicyclic.web.deadline`, ``BodyLimit``).
    picture_cache : int, default 64 MiB
        Bytes of pictures kept in the server process (:mod:`epicyclic.web.cache`; 0: none kept).
    draw_examples : bool, default False
        Draw the pictures of every bundled example ahead once the server has started, while it is idle
        (``epicyclic serve`` does; the default example first), so that opening an example shows them at once.
    allowed_hosts : tuple of str
        Host headers accepted (loopback names by default; ``("*",)`` for any).
    synthesis_architectures : int, default 2e7
        Largest synthesis the page runs (architectures; larger ones are refused before they start and left to
        ``epicyclic synthesize``; :mod:`epicyclic.web.synthesis_tool`).
    synthesis_seconds : float, default 60
        Seconds after which the page stops a synthesis (keeping the candidates found by then).
    browser_charts : bool, default True
        The browser draws the speed plan, the speed chart, the torques and the powers from their data
        (:mod:`epicyclic.web.charts`); False: the server draws every picture (as before; the benchmark's
        baseline).
    """

    max_body: int = 4 * MAX_FILE_BYTES
    solve_timeout: float = 10.0
    report_timeout: float = 60.0
    workers: int = 2
    max_queue: int = 256
    max_client_jobs: int = 16
    worker_memory: int | None = 2 << 30
    body_timeout: float = 30.0
    request_deadline: float = 20.0
    picture_cache: int = 64 << 20
    draw_examples: bool = False
    allowed_hosts: tuple[str, ...] = LOOPBACK_HOSTS
    synthesis_architectures: int = PAGE_ARCHITECTURES
    synthesis_seconds: float = PAGE_SECONDS
    browser_charts: bool = True


def _reply(reply: Reply) -> Response:
    headers = {"Cache-Control": "no-store", **dict(reply.headers)}
    if reply.filename:
        headers["Content-Disposition"] = f'attachment; filename="{reply.filename}"'
    return Response(reply.body, reply.status, headers=headers, media_type=reply.media_type)


def create_app(limits: Limits | None = None) -> Starlette:
    """The Starlette application of the page (workers start with the app's lifespan).

    Parameters
    ----------
    limits : Limits, optional
    """
    limits = limits or Limits()
    examples = bundled_examples()

    async def form_of(request: Request) -> Any:
        try:
            return await request.form(max_files=1, max_fields=3000, max_part_size=limits.max_body)
        except (BodyTooLarge, BodyTooSlow):  # answered by the BodyLimit middleware
            raise
        except Exception as exc:  # starlette's multipart errors: too many fields, malformed body
            raise FormError(f"the request's form cannot be read ({getattr(exc, 'detail', exc)}).") from None

    async def state_of(request: Request) -> PageState:
        return PageState.from_form(await form_of(request), max_text=limits.max_body)

    def bad(exc: Exception) -> Response:
        return _reply(failure(str(exc), 400))

    def client_of(request: Request) -> str:
        """The client a job counts for: its address and the page's id (every tab of the page has its own)."""
        address = request.client.host if request.client else ""
        return f"{address} {request.headers.get('x-epicyclic-client', '')[:64]}"

    async def run(request: Request, function: Any, *args: Any, timeout: float | None = None) -> Reply:
        async def gone() -> None:  # returns when the client has closed the connection
            while (await request.receive())["type"] != "http.disconnect":
                pass

        jobs: Jobs = app.state.jobs
        return await jobs.run(function, *args, timeout=timeout or limits.solve_timeout, client=client_of(request),
                              gone=gone)

    async def work(request: Request, function: Any, *args: Any, timeout: float | None = None,
                   ahead: PageState | None = None) -> Response:
        """``function(*args)`` in a worker; with ``ahead`` (the state shown), the pictures of the gears the
        page shows next are drawn ahead while the server is idle."""
        reply = await run(request, function, *args, timeout=timeout)
        if ahead is not None and reply.status == 200 and reply.next_gears:
            ahead = replace(ahead, text=reply.next_text or ahead.text)
            app.state.cache.draw_ahead(client_of(request), ahead, reply.next_gears, app.state.jobs, figure,
                                       limits.solve_timeout)
        return _reply(reply)

    async def page(request: Request) -> Response:
        from .. import __version__

        query = request.query_params
        chosen = query.get("example", DEFAULT_EXAMPLE)
        restore = restored_state(query)
        missing = ""
        if query.get("file") and not query.get("example"):  # a file of one's own, kept (or not) in the browser:
            # its operating point and gear belong to it, never to the example shown if the browser lacks it
            restore.update(restore_rows=(), restore_gear="")
            missing = clean_text(query.get("file", "")[:200], "file", 200)
        body = render("page.html", examples=[(e.key, e.title) for e in examples.values()],
                      initial=chosen if chosen in examples else DEFAULT_EXAMPLE, version=__version__,
                      unit_choices=UNIT_LABELS, missing_file=missing, **restore)
        return HTMLResponse(body, headers={"Cache-Control": "no-store"})

    async def open_example(request: Request) -> Response:
        """An example; with the operating point and gear of a shared link or a reload (the URL holds them)."""
        try:
            form = await form_of(request)
            key = clean_text(form.get("example"), "example", 200) or DEFAULT_EXAMPLE
            state = PageState.from_form(form, max_text=limits.max_body)
        except FormError as exc:
            return bad(exc)
        if key not in examples:
            return _reply(failure(f"no bundled example {key!r}; choose one from the list.", 404))
        example = examples[key]
        if example.rexs:  # a REXS model opens as `epicyclic convert` writes it (converted in the worker)
            return await work(request, open_file, example.rexs, example.file_name, state.units, state.lang,
                              limits.browser_charts, state.rows, state.gear, key)
        return await work(request, open_text, example.text, example.file_name, state.units, state.lang,
                          state.rows, state.gear, limits.browser_charts, key,
                          ahead=replace(state, text=example.text, source=example.file_name))

    async def upload(request: Request) -> Response:
        try:
            form = await form_of(request)
            file = form.get("file")
            if file is None or isinstance(file, str):
                raise FormError("upload: choose a .toml file.")
            data = await file.read()
            name = clean_text(file.filename or "upload.toml", "file name", 200) or "upload.toml"
            state = PageState("", units=form.get("units", "file"), lang=form.get("lang", "en"))
        except FormError as exc:
            return bad(exc)
        return await work(request, open_file, data, name, state.units, state.lang, limits.browser_charts,
                          ahead=replace(state, source=name))

    async def with_state(request: Request, function: Any, *args: Any, timeout: float | None = None) -> Response:
        """Read the page's form and run ``function(state, *args)`` in a worker."""
        try:
            state = await state_of(request)
        except FormError as exc:
            return bad(exc)
        return await work(request, function, state, *args, timeout=timeout)

    async def change(request: Request) -> Response:
        origin = request.path_params["origin"]
        if origin not in ("text", "form"):
            return _reply(failure(f"no such action {origin!r}.", 404))
        try:
            state = await state_of(request)
        except FormError as exc:
            return bad(exc)
        return await work(request, apply, state, origin, limits.browser_charts, ahead=state)

    async def picture(request: Request) -> Response:
        """A picture: kept from before or drawn ahead where it can be (epicyclic.web.cache)."""
        try:
            state = await state_of(request)
        except FormError as exc:
            return bad(exc)
        name = request.path_params["kind"]
        return _reply(await app.state.cache.answer(figure_key(state, name), lambda: run(request, figure, state, name)))

    async def save_picture(request: Request) -> Response:
        return await with_state(request, save_figure, request.path_params["kind"], timeout=limits.report_timeout)

    async def geometry(request: Request) -> Response:
        return await with_state(request, tool, request.path_params["name"])

    async def geometry_fields(request: Request) -> Response:
        return await with_state(request, tool_fields, request.path_params["name"])

    async def report(request: Request) -> Response:
        return await with_state(request, download, request.path_params["kind"], timeout=limits.report_timeout)

    async def health(request: Request) -> Response:
        return PlainTextResponse("ok")

    @contextlib.asynccontextmanager
    async def lifespan(app: Starlette):
        app.state.jobs = Jobs(limits.workers, limits.max_queue, max_client_jobs=limits.max_client_jobs,
                              worker_memory=limits.worker_memory)
        app.state.cache = FigureCache(limits.picture_cache, ahead_kinds(limits.browser_charts))
        if limits.draw_examples and limits.picture_cache:
            ordered = sorted(examples.values(), key=lambda e: e.key != DEFAULT_EXAMPLE)
            states = [PageState(e.text, e.file_name, gear=shown_gear(e.text, e.file_name))  # as the page opens them
                      for e in ordered if not e.rexs]
            app.state.cache.draw_states_ahead("examples", states, app.state.jobs, figure, limits.solve_timeout)
        try:
            yield
        finally:
            app.state.cache.close()
            app.state.jobs.close()

    routes = [
        Route("/", page),
        Route("/healthz", health),
        Route("/example", open_example, methods=["POST"]),
        Route("/upload", upload, methods=["POST"]),
        Route("/apply/{origin}", change, methods=["POST"]),
        Route("/figure/{kind}", picture, methods=["POST"]),
        Route("/save/{kind}", save_picture, methods=["POST"]),
        Route("/tool/{name}", geometry, methods=["POST"]),
        Route("/tool/{name}/fields", geometry_fields, methods=["POST"]),
        Route("/download/{kind}", report, methods=["POST"]),
        Mount("/static", StaticFiles(packages=[("epicyclic.web", "static")]), name="static"),
    ]
    searches = Searches(limits.workers - 1)  # the Synthesis tab (epicyclic.web.synthesis_routes)
    routes[-1:-1] = synthesis_routes(searches, limits, form_of, client_of, run)
    middleware = [
        Middleware(SecurityHeaders),
        Middleware(PageStatus),
        Middleware(TrustedHostMiddleware, allowed_hosts=list(limits.allowed_hosts)),
        Middleware(SameOrigin),
        Middleware(BodyLimit, limit=limits.max_body, timeout=limits.body_timeout, deadline=limits.request_deadline),
    ]
    app = Starlette(routes=routes, middleware=middleware, lifespan=lifespan)
    app.state.limits = limits
    app.state.searches = searches
    return app
