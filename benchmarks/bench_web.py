"""Load test of ``epicyclic serve`` on loopback: 200 concurrent solve requests, no error allowed.

Run:  .venv/bin/python benchmarks/bench_web.py [requests] [workers]

* starts ``epicyclic serve`` on a free port of 127.0.0.1 (its default limits, ``--workers``
  worker processes) and waits for ``/healthz``;
* baseline: the same solve requests sent one after another (concurrency 1), 20 of them;
* load: ``requests`` (default 200, at most the server's queue of 256) solve requests sent at once
  (one connection and one page id each), each the
  page's "Solve" of the Brandenberger 1952 example (``POST /apply/text``: read the TOML, solve,
  render tables, summary, worked solution);
* bounded: exactly that many requests, one overall deadline (120 s); the server is stopped at
  the end.  Any answer other than 200 with the published efficiency (0.85) is an error, and the
  run exits 1 if there is one.

Only loopback addresses are used.
"""

from __future__ import annotations

import asyncio
import os
import platform
import socket
import statistics
import subprocess
import sys
import time
from pathlib import Path

import httpx2 as httpx

DEADLINE = 120.0  # seconds for the whole concurrent run
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "brandenberger_1952.toml"


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def start_server(port: int, workers: int) -> subprocess.Popen:
    code = "import sys; from epicyclic.cli.main import app; app(sys.argv[1:])"
    return subprocess.Popen([sys.executable, "-c", code, "serve", "--host", "127.0.0.1", "--port", str(port),
                             "--workers", str(workers)], stdout=subprocess.DEVNULL)


async def wait_ready(client: httpx.AsyncClient, url: str) -> None:
    start = time.perf_counter()
    while time.perf_counter() - start < 60:
        try:
            if (await client.get(url + "/healthz")).status_code == 200:
                return
        except httpx.TransportError:
            pass
        await asyncio.sleep(0.1)
    raise SystemExit("the server did not start within 60 s")


async def solve(client: httpx.AsyncClient, url: str, form: dict, who: str = "bench") -> tuple[float, str | None]:
    """(latency in s, error or None) of one solve request from the page (tab) ``who``: the server caps the
    jobs per client (16), so each concurrent request is a page of its own, as many users would be."""
    start = time.perf_counter()
    try:
        answer = await client.post(url + "/apply/text", data=form, headers={"X-Epicyclic-Client": who})
    except httpx.HTTPError as exc:
        return time.perf_counter() - start, f"{type(exc).__name__}: {exc}"
    latency = time.perf_counter() - start
    if answer.status_code != 200:
        return latency, f"status {answer.status_code}"
    if 'id="efficiency">0.8494<' not in answer.text:  # Brandenberger 1952: eta' = 0.85
        return latency, "wrong efficiency in the answer"
    return latency, None


def percentile(values: list[float], q: float) -> float:
    return statistics.quantiles(values, n=100, method="inclusive")[q - 1]


async def run(requests: int, workers: int) -> int:
    port = free_port()
    url = f"http://127.0.0.1:{port}"
    form = {"toml": EXAMPLE.read_text(encoding="utf-8"), "source": EXAMPLE.name, "units": "file", "lang": "en"}
    server = start_server(port, workers)
    limits = httpx.Limits(max_connections=requests, max_keepalive_connections=requests)
    try:
        async with httpx.AsyncClient(limits=limits, timeout=DEADLINE) as client:
            await wait_ready(client, url)
            for _ in range(2 * workers):  # every worker has solved once (imports, caches)
                await solve(client, url, form)
            sequential = [await solve(client, url, form) for _ in range(20)]
            start = time.perf_counter()
            results = await asyncio.wait_for(
                asyncio.gather(*(solve(client, url, form, f"tab{k}") for k in range(requests))), DEADLINE)
            wall = time.perf_counter() - start
    finally:
        server.terminate()
        server.wait(timeout=30)
    seq = [t for t, _ in sequential]
    latencies = [t for t, _ in results]
    errors = [e for _, e in sequential + results if e]
    print(f"epicyclic serve load test — Python {platform.python_version()}, {os.cpu_count()} cores, "
          f"{workers} worker processes, loopback")
    print("request: POST /apply/text, Brandenberger 1952 example (read, solve, tables, worked solution)")
    print(f"baseline, one at a time ({len(seq)} requests): median {1000 * statistics.median(seq):.1f} ms, "
          f"max {1000 * max(seq):.1f} ms")
    print(f"{requests} concurrent requests: wall {wall:.2f} s, {requests / wall:.0f} requests/s, "
          f"p50 {1000 * percentile(latencies, 50):.0f} ms, p95 {1000 * percentile(latencies, 95):.0f} ms, "
          f"max {1000 * max(latencies):.0f} ms")
    print(f"throughput vs one at a time: {requests / wall * statistics.median(seq):.2f} ×")
    print(f"errors: {len(errors)}" + (f" ({errors[:3]})" if errors else ""))
    return 1 if errors else 0


def main() -> None:
    requests = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    workers = int(sys.argv[2]) if len(sys.argv) > 2 else 2
    raise SystemExit(asyncio.run(run(requests, workers)))


if __name__ == "__main__":
    main()
