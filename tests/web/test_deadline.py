"""A request trickling in a byte at a time is cut off (issue 30): the headers by the server's protocol
(:mod:`epicyclic.web.deadline`), the body by :class:`epicyclic.web.guards.BodyLimit`.  On loopback only,
each case bounded (the deadline 1.5 s, a byte every 0.3 s; before the fix both stayed open for as long as
the bytes came)."""

from __future__ import annotations

import socket
import threading
import time

import pytest

from epicyclic.web import Limits, create_app
from epicyclic.web.deadline import deadline_protocol

DEADLINE = 1.5


@pytest.fixture(scope="module")
def port():
    import uvicorn

    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.bind(("127.0.0.1", 0))
    app = create_app(Limits(workers=1, request_deadline=DEADLINE))
    server = uvicorn.Server(uvicorn.Config(app, log_level="warning", lifespan="on", http=deadline_protocol(DEADLINE)))
    thread = threading.Thread(target=server.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    start = time.monotonic()
    while not server.started and time.monotonic() - start < 60:
        time.sleep(0.05)
    try:
        yield sock.getsockname()[1]
    finally:
        server.should_exit = True
        thread.join(timeout=30)
        sock.close()


def trickle(port: int, head: bytes, drip: bytes, limit: float = 15.0) -> tuple[float, bytes]:
    """Send ``head`` at once, then ``drip`` a byte every 0.3 s until the server answers or closes; the
    seconds it took and what came back."""
    with socket.create_connection(("127.0.0.1", port), timeout=1) as conn:
        start = time.monotonic()
        conn.sendall(head)
        answer = b""
        for byte in drip:
            try:
                conn.sendall(bytes([byte]))
            except OSError:  # closed by the server
                break
            conn.settimeout(0.3)
            try:
                chunk = conn.recv(4096)
            except socket.timeout:
                chunk = None
            except OSError:
                break
            if chunk is not None:
                answer += chunk
                if not chunk or answer.count(b"\r\n\r\n"):
                    break
            if time.monotonic() - start > limit:
                break
        conn.settimeout(2)
        try:
            while chunk := conn.recv(4096):
                answer += chunk
        except OSError:
            pass
        return time.monotonic() - start, answer


def test_headers_trickling_in_are_cut_off(port):
    head = b"GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\n"
    seconds, answer = trickle(port, head, b"X-Slow: " + b"a" * 200)
    assert answer.startswith(b"HTTP/1.1 408"), answer[:200]
    assert DEADLINE - 0.2 < seconds < DEADLINE + 4


def test_a_body_trickling_in_is_cut_off(port):
    head = (b"POST /example HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/x-www-form-urlencoded\r\n"
            b"Content-Length: 300\r\n\r\n")
    seconds, answer = trickle(port, head, b"example=" + b"a" * 292)
    assert answer.startswith(b"HTTP/1.1 408"), answer[:200]
    assert b"of the request&#39;s start" in answer or b"of the request's start" in answer
    assert DEADLINE - 0.2 < seconds < DEADLINE + 4


def test_a_prompt_request_is_served(port):
    with socket.create_connection(("127.0.0.1", port), timeout=5) as conn:
        conn.sendall(b"GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
        answer = b""
        while chunk := conn.recv(4096):
            answer += chunk
    assert answer.startswith(b"HTTP/1.1 200") and answer.endswith(b"ok")
