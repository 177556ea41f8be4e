"""ASGI middleware that guards the page: body size and time, same-origin POSTs, security headers.

* :class:`BodyLimit` refuses request bodies over a size (413) and bodies that
  stop arriving (408 after ``body_timeout`` seconds without a byte, or when
  the whole body has not arrived ``request_deadline`` seconds after the
  request's start), so a client that opens a request and never sends its
  body, or sends it a byte every few seconds, cannot hold a connection and a
  form parser for ever (the headers' deadline: :mod:`epicyclic.web.deadline`).
* :class:`SameOrigin` refuses a POST that a web page of another origin makes
  the browser send (403): every POST of the page computes, so a page
  elsewhere must not make this server work (cross-site request forgery,
  OWASP CSRF Prevention Cheat Sheet, "Verifying Origin with standard
  headers" and "Fetch Metadata headers").  A browser names the page that
  sends a POST in ``Origin`` (and in ``Sec-Fetch-Site``); a POST whose Origin
  is not this server (also ``null``, which a sandboxed or no-referrer page
  sends) or whose Sec-Fetch-Site is ``cross-site`` or ``same-site`` is
  refused.  A client that is no browser (curl, a script) sends neither and is
  let through: it could send any header it likes anyway.
* :class:`SecurityHeaders` adds the Content-Security-Policy and the usual
  hardening headers to every answer.
* :class:`PageStatus` sends the page's own requests (htmx: ``HX-Request``) the
  message about bad input with status 200 and ``X-Epicyclic-Status: 422``: the
  page shows it as an answer (the message at its line), and a browser logs every
  4xx answer as a failed load in its console; any other client gets the 422.

References
----------
OWASP Cross-Site Request Forgery Prevention Cheat Sheet (2024); W3C Fetch Metadata Request
Headers (Sec-Fetch-Site); RFC 6454 (the Origin header); RFC 9110, sec. 15.5.9 (408 Request Timeout).
"""

from __future__ import annotations

import asyncio
from typing import Any
from urllib.parse import urlsplit

from starlette.responses import HTMLResponse

from .jobs import failure

__all__ = ["BodyLimit", "SameOrigin", "SecurityHeaders", "PageStatus", "CSP", "BodyTooLarge", "BodyTooSlow"]

CSP = ("default-src 'none'; script-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data:; "
       "connect-src 'self'; form-action 'self'; base-uri 'none'; frame-ancestors 'none'")


class BodyTooLarge(Exception):
    """A request body past the limit (raised inside the app, answered with 413)."""


class BodyTooSlow(Exception):
    """A request body that stopped arriving (raised inside the app, answered with 408)."""


async def _answer(scope: dict, receive: Any, send: Any, message: str, status: int) -> None:
    reply = failure(message, status)
    await HTMLResponse(reply.body, reply.status, headers={"Connection": "close"})(scope, receive, send)


class BodyLimit:
    """ASGI middleware: refuse request bodies over ``limit`` bytes with 413 (declared or streamed), bodies
    that send nothing for ``timeout`` seconds and bodies not complete ``deadline`` seconds after the request
    came in (a body trickling in a byte at a time) with 408."""

    def __init__(self, app: Any, limit: int, timeout: float = 30.0, deadline: float = 60.0):
        self.app, self.limit, self.timeout, self.deadline = app, limit, timeout, deadline

    async def __call__(self, scope: dict, receive: Any, send: Any) -> None:
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        declared = dict(scope.get("headers", [])).get(b"content-length")
        if declared is not None and (not declared.isdigit() or int(declared) > self.limit):
            return await self._too_large(scope, receive, send)
        seen = 0
        started = late = False
        body_done = scope.get("method") in ("GET", "HEAD")
        loop = asyncio.get_running_loop()
        end = loop.time() + self.deadline

        async def counting_receive() -> dict:
            nonlocal seen, body_done, late
            if body_done:  # after the body: wait for the client to leave (no time limit)
                return await receive()
            left = end - loop.time()
            try:
                message = await asyncio.wait_for(receive(), max(0.0, min(self.timeout, left)))
            except asyncio.TimeoutError:
                late = left <= self.timeout
                raise BodyTooSlow from None
            seen += len(message.get("body", b""))
            if seen > self.limit:
                raise BodyTooLarge
            body_done = message["type"] != "http.request" or not message.get("more_body", False)
            return message

        async def tracking_send(message: dict) -> None:
            nonlocal started
            started = started or message["type"] == "http.response.start"
            await send(message)

        try:
            await self.app(scope, counting_receive, tracking_send)
        except BodyTooLarge:
            if started:
                raise
            await self._too_large(scope, receive, send)
        except BodyTooSlow:
            if started:
                raise
            within = (f"{self.deadline:g} s of the request's start" if late else
                      f"{self.timeout:g} s" + " (nothing arrived)")
            await _answer(scope, receive, send, f"the request's body did not arrive within {within} (a stalled or "
                          "very slow connection); the server closed it. Send the request again.", 408)

    async def _too_large(self, scope: dict, receive: Any, send: Any) -> None:
        await _answer(scope, receive, send,
                      f"the request is larger than {self.limit // 1024} KiB, the limit of this server; a train "
                      "description is a few KiB (start the server with a larger --max-body if needed).", 413)


def _origin_of(url: str) -> tuple[str, str] | None:
    """(scheme, host[:port]) of an origin or URL, lower case; None for ``null`` or an unreadable one."""
    try:
        parts = urlsplit(url.strip())
    except ValueError:
        return None
    if not parts.scheme or not parts.netloc:
        return None
    return parts.scheme.lower(), parts.netloc.lower()


def _default_port(scheme: str, netloc: str) -> str:
    port = {"http": ":80", "https": ":443"}.get(scheme, "")
    return netloc[: -len(port)] if port and netloc.endswith(port) else netloc


class SameOrigin:
    """ASGI middleware: a POST sent by a page of another origin gets 403 (see the module text)."""

    def __init__(self, app: Any):
        self.app = app

    async def __call__(self, scope: dict, receive: Any, send: Any) -> None:
        if scope["type"] == "http" and scope.get("method") not in ("GET", "HEAD", "OPTIONS"):
            why = self.foreign(scope)
            if why:
                return await _answer(scope, receive, send, f"refused: {why}. The page computes only for itself, "
                                     "so that a web page elsewhere cannot make this server work; open "
                                     "the page from this server.", 403)
        await self.app(scope, receive, send)

    @staticmethod
    def foreign(scope: dict) -> str:
        """Why the request comes from another origin ("" if it does not)."""
        headers = {k.decode("latin-1").lower(): v.decode("latin-1") for k, v in scope.get("headers", [])}
        site = headers.get("sec-fetch-site", "").lower()
        if site in ("cross-site", "same-site"):
            return f"the browser says this request comes from another site (Sec-Fetch-Site: {site})"
        origin = headers.get("origin")
        if origin is None:
            return ""
        host = headers.get("host", "").lower()
        given = _origin_of(origin)
        scheme = scope.get("scheme", "http")
        if given is None or _default_port(*given) != _default_port(scheme, host) or given[0] != scheme:
            return f"the request comes from the page {origin[:100]!r}, not from this server ({scheme}://{host[:100]})"
        return ""


class SecurityHeaders:
    """ASGI middleware: CSP and the usual hardening headers on every response.

    ``Referrer-Policy: same-origin`` (not ``no-referrer``): with ``no-referrer`` a browser sends
    ``Origin: null`` with the page's own POSTs, which :class:`SameOrigin` could not tell from a foreign
    page's; nothing of the page's address reaches another site either way.
    """

    HEADERS = [(b"content-security-policy", CSP.encode()), (b"x-content-type-options", b"nosniff"),
               (b"referrer-policy", b"same-origin"), (b"x-frame-options", b"DENY"),
               (b"cross-origin-opener-policy", b"same-origin"), (b"cross-origin-resource-policy", b"same-origin")]

    def __init__(self, app: Any):
        self.app = app

    async def __call__(self, scope: dict, receive: Any, send: Any) -> None:
        async def add_headers(message: dict) -> None:
            if message["type"] == "http.response.start":
                message["headers"] = list(message.get("headers", [])) + self.HEADERS
            await send(message)

        await self.app(scope, receive, add_headers if scope["type"] == "http" else send)


class PageStatus:
    """ASGI middleware: a 422 (bad input, answered with its message) to a request of the page itself
    (``HX-Request: true``) goes out as 200 with ``X-Epicyclic-Status: 422`` (see the module text)."""

    def __init__(self, app: Any):
        self.app = app

    async def __call__(self, scope: dict, receive: Any, send: Any) -> None:
        if scope["type"] != "http" or (b"hx-request", b"true") not in scope.get("headers", []):
            return await self.app(scope, receive, send)

        async def page_send(message: dict) -> None:
            if message["type"] == "http.response.start" and message.get("status") == 422:
                message = {**message, "status": 200,
                           "headers": [*message.get("headers", []), (b"x-epicyclic-status", b"422")]}
            await send(message)

        await self.app(scope, receive, page_send)
