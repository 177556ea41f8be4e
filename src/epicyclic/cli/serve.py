"""``epicyclic serve``: the page to work in, on this computer (http://127.0.0.1:8000).

Starts the web app of :mod:`epicyclic.web` with uvicorn.  It binds to the
loopback address by default, so only this computer reaches it; with another
``--host`` it warns and accepts any host name.
"""

from __future__ import annotations

import ipaddress
import math
from typing import Annotated

import typer

from ..limits import MAX_SYNTHESIS_ARCHITECTURES
from ._common import fail

__all__ = ["serve"]


def _is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


def _address_problem(host: str, port: int) -> str:
    """Why ``host:port`` cannot be served ("" if it can): checked before uvicorn starts, whose own
    errors are several log lines and exit code 3."""
    import socket

    try:
        infos = socket.getaddrinfo(host.strip("[]"), port, type=socket.SOCK_STREAM)
    except (socket.gaierror, UnicodeError, ValueError) as exc:
        return f"the address cannot be resolved ({getattr(exc, 'strerror', None) or exc}); give an IP address or a host name."
    family, kind, proto, _, address = infos[0]
    try:
        with socket.socket(family, kind, proto) as probe:
            probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            probe.bind(address)
    except OSError as exc:
        return f"cannot listen there ({exc.strerror or exc}); choose another --port or --host."
    return ""


def serve(
    host: Annotated[str, typer.Option(help="Address to bind; the default reaches this computer only.")] = "127.0.0.1",
    port: Annotated[int, typer.Option(help="TCP port.", min=1, max=65535)] = 8000,
    workers: Annotated[int, typer.Option(help="Worker processes that solve and draw.", min=1, max=64)] = 2,
    timeout: Annotated[float, typer.Option(help="Seconds a solve or picture may take.", min=0.1, max=3600)] = 10.0,
    max_body: Annotated[int, typer.Option(help="Largest request in KiB (a train description).", min=1,
                                          max=65536)] = 4096,
    worker_memory: Annotated[int, typer.Option(help="MiB each worker's memory may grow after its start "
                                               "(0: no limit).", min=0, max=1 << 20)] = 2048,
    synthesis_architectures: Annotated[int, typer.Option(
        help="Largest synthesis the Synthesis tab runs, in architectures (larger ones are refused before they "
             "start, with the command line to run them).", min=1, max=MAX_SYNTHESIS_ARCHITECTURES)] = 2 * 10**7,
    synthesis_seconds: Annotated[float, typer.Option(
        help="Seconds after which the Synthesis tab stops a search, keeping what it found.", min=1.0,
        max=86400.0)] = 60.0,
) -> None:
    """Open a page to work in: examples, an editor, the operating point, results, pictures, reports."""
    try:
        import uvicorn

        from ..web import Limits, create_app
    except ImportError as exc:  # pragma: no cover - the web dependencies are installed with the package
        fail(f"error: epicyclic serve needs the web dependencies ({exc.name}); reinstall epicyclic.")
        return
    if not math.isfinite(timeout):  # a float range lets NaN through (every comparison is False)
        fail(f"error: serve --timeout must be a number of seconds from 0.1 to 3600, got {timeout}.")
        return
    if not math.isfinite(synthesis_seconds):
        fail(f"error: serve --synthesis-seconds must be a number of seconds from 1 to 86400, got {synthesis_seconds}.")
        return
    problem = _address_problem(host, port)
    if problem:
        fail(f"error: serve --host {host!r:.60} --port {port}: {problem}")
        return
    loopback = _is_loopback(host)
    if not loopback:
        typer.echo(f"warning: serving on {host}, reachable from other computers; the page has no login.", err=True)
    limits = Limits(max_body=max_body * 1024, solve_timeout=timeout, workers=workers,
                    worker_memory=worker_memory * 2**20 or None, draw_examples=True,
                    allowed_hosts=Limits.allowed_hosts if loopback else ("*",),
                    synthesis_architectures=synthesis_architectures, synthesis_seconds=synthesis_seconds)
    shown = f"[{host}]" if ":" in host else host
    typer.echo(f"epicyclic serve: open http://{shown}:{port}/ (Ctrl+C stops)")
    from ..web.deadline import deadline_protocol

    uvicorn.run(create_app(limits), host=host, port=port, log_level="warning",
                http=deadline_protocol(limits.request_deadline))
