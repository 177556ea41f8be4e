"""An overall deadline for a request's head: headers that trickle in are cut off (408).

uvicorn reads a request's line and headers before the app sees the request, and
restarts its keep-alive timer on every byte received, so a client that sends one
byte every few seconds holds a connection (and its buffers) open for as long as
it likes (the "Slowloris" attack).  :func:`deadline_protocol` gives uvicorn's
h11 protocol a deadline from the moment a request may start (the connection is
made, or the previous answer is sent) until its headers are complete: past it
the server answers 408 and closes the connection.  The body has its own overall
deadline in :class:`epicyclic.web.guards.BodyLimit`.

References
----------
RFC 9110, sec. 15.5.9 (408 Request Timeout); RFC 9112, sec. 9.5 (closing a connection); R. Hansen (2009),
"Slowloris HTTP DoS" (slow headers); Apache httpd, mod_reqtimeout (a header deadline as the defence).

Examples
--------
>>> protocol = deadline_protocol(20.0)
>>> protocol.head_deadline, protocol.__name__
(20.0, 'DeadlineH11Protocol')
"""

from __future__ import annotations

import asyncio
from typing import Any

__all__ = ["deadline_protocol", "REFUSAL"]

_BODY = b"the request's headers did not arrive in time; the server closed the connection. Send it again.\n"
#: What a client whose headers came too late gets before the connection is closed.
REFUSAL = (b"HTTP/1.1 408 Request Timeout\r\ncontent-type: text/plain; charset=utf-8\r\nconnection: close\r\n"
           b"content-length: " + str(len(_BODY)).encode() + b"\r\n\r\n" + _BODY)

def deadline_protocol(seconds: float) -> type:
    """uvicorn's h11 protocol with a deadline of ``seconds`` for each request's line and headers.

    Parameters
    ----------
    seconds : float
        From the connection's start (or the end of the previous answer on a kept-alive connection) until the
        request's headers are complete.

    Returns
    -------
    type
        A subclass of :class:`uvicorn.protocols.http.h11_impl.H11Protocol` (pass it as ``uvicorn.run(http=...)``).
    """
    from uvicorn.protocols.http.h11_impl import H11Protocol

    class DeadlineH11Protocol(H11Protocol):
        head_deadline = float(seconds)
        _head_timer: asyncio.TimerHandle | None = None

        def _arm(self) -> None:
            if self._head_timer is not None:
                self._head_timer.cancel()
            self._head_timer = self.loop.call_later(self.head_deadline, self._head_late)

        def _head_late(self) -> None:
            self._head_timer = None
            in_progress = self.cycle is not None and not self.cycle.response_complete
            if in_progress or self.transport is None or self.transport.is_closing():
                return  # the headers are complete: the body and the answer have their own limits
            self.transport.write(REFUSAL)
            self.transport.close()

        def connection_made(self, transport: Any) -> None:  # type: ignore[override]
            super().connection_made(transport)
            self._arm()

        def on_response_complete(self) -> None:
            super().on_response_complete()
            if not self.transport.is_closing():
                self._arm()

        def connection_lost(self, exc: Exception | None) -> None:
            if self._head_timer is not None:
                self._head_timer.cancel()
                self._head_timer = None
            super().connection_lost(exc)

    return DeadlineH11Protocol
