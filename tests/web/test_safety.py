"""Safety under load: cross-origin POSTs refused, jobs per client and in all bounded, a job whose client
left cancelled, each worker's memory bounded, request bodies that never arrive timed out.

The server tests run uvicorn on a free port of 127.0.0.1 only, with a bounded number of requests and a
deadline for each (loopback load test)."""

from __future__ import annotations

import asyncio
import socket
import threading
import time

import httpx2 as httpx
import pytest

from epicyclic.web import Limits, create_app
from epicyclic.web.examples import bundled_examples
from epicyclic.web.jobs import Jobs

DEADLINE = 60.0  # seconds for any one server test


# ---------------------------------------------------------------------- another origin
@pytest.mark.parametrize("headers", [
    {"Origin": "http://evil.example"},
    {"Origin": "null"},  # a sandboxed frame or a page with Referrer-Policy: no-referrer
    {"Origin": "http://testserver:8080"},  # another port is another origin (RFC 6454)
    {"Origin": "https://testserver"},  # another scheme too
    {"Sec-Fetch-Site": "cross-site"},
    {"Sec-Fetch-Site": "same-site", "Origin": "http://testserver"},
])
def test_a_post_from_another_origin_is_refused(client, headers):
    answer = client.post("/example", data={"example": "brandenberger_1952"}, headers=headers)
    assert answer.status_code == 403 and "refused" in answer.text and "0.8494" not in answer.text
    assert client.post("/apply/text", data={"toml": "x"}, headers=headers).status_code == 403


@pytest.mark.parametrize("headers", [{}, {"Origin": "http://testserver"},
                                     {"Origin": "http://testserver", "Sec-Fetch-Site": "same-origin"}])
def test_a_post_from_the_page_itself_or_a_script_is_served(client, headers):
    answer = client.post("/example", data={"example": "brandenberger_1952"}, headers=headers)
    assert answer.status_code == 200 and "0.8494" in answer.text
    assert client.get("/", headers={"Sec-Fetch-Site": "cross-site"}).status_code == 200  # a link may open it


def test_the_page_sends_its_origin_with_its_posts(client):
    assert client.get("/").headers["referrer-policy"] == "same-origin"  # no-referrer would send Origin: null


# ---------------------------------------------------------------------- the pool's bounds
@pytest.fixture(scope="module")
def jobs():
    pool = Jobs(workers=1, max_queue=3, max_client_jobs=2, worker_memory=256 * 2**20, queue_wait=30)
    yield pool
    pool.close()


def test_jobs_per_client_and_in_all_are_bounded(jobs):
    async def main():
        first = [asyncio.ensure_future(jobs.run(time.sleep, 0.5, timeout=10, client="a")) for _ in range(3)]
        await asyncio.sleep(0.1)
        other = [asyncio.ensure_future(jobs.run(time.sleep, 0.5, timeout=10, client="b")) for _ in range(2)]
        return await asyncio.gather(*first), await asyncio.gather(*other)

    first, other = asyncio.run(main())
    assert [getattr(r, "status", None) for r in first] == [None, None, 429]  # a's third: too many from a
    assert [getattr(r, "status", None) for r in other] == [None, 503]  # b's second: the queue (3) is full
    assert "too many requests at once" in first[2].body and "busy" in other[1].body
    assert jobs.pending == 0 and not jobs.per_client


def test_the_cap_is_keyed_on_the_address_not_on_the_page_id(jobs):
    """Issue 30: a page id (``X-Epicyclic-Client``) is minted by the client at will; jobs with fresh ids from
    one address count as one client."""
    async def main():
        runs = [asyncio.ensure_future(jobs.run(time.sleep, 0.3, timeout=10, client=f"10.0.0.1 id{k}"))
                for k in range(3)]
        return await asyncio.gather(*runs)

    assert [getattr(r, "status", None) for r in asyncio.run(main())] == [None, None, 429]


def test_a_client_with_many_jobs_waiting_does_not_hold_up_another():
    """Issue 30: the fair queue: with one worker, 8 jobs of one client waiting and then one of another, the
    other's job runs at the next free turn (after at most two of the first client's), not after all 8."""
    pool = Jobs(workers=1, max_queue=64, max_client_jobs=16, worker_memory=None, queue_wait=60)
    try:
        asyncio.run(pool.run(abs, -1, timeout=60))  # the worker is up

        async def main():
            done: list[str] = []

            async def job(client: str, k: int) -> None:
                await pool.run(time.sleep, 0.4, timeout=30, client=client)
                done.append(f"{client.split()[0]}:{k}")

            first = [asyncio.ensure_future(job(f"10.0.0.1 id{k}", k)) for k in range(8)]
            await asyncio.sleep(0.1)
            await asyncio.gather(job("10.0.0.2 x", 0), *first)
            return done

        done = asyncio.run(main())
        assert done.index("10.0.0.2:0") <= 2, done
    finally:
        pool.close()


def test_a_job_whose_client_left_is_cancelled_and_the_pool_keeps_working(jobs):
    async def main():
        start = time.perf_counter()
        answer = await jobs.run(time.sleep, 30, timeout=60, client="c", gone=lambda: asyncio.sleep(0.3))
        return answer, time.perf_counter() - start

    before = jobs.cancelled
    answer, seconds = asyncio.run(main())
    assert answer.status == 499 and seconds < 5 and jobs.cancelled == before + 1
    assert asyncio.run(jobs.run(abs, -3, timeout=30)) == 3  # a new worker took over


def test_a_worker_past_its_memory_limit_says_so(jobs):
    answer = asyncio.run(jobs.run(bytearray, 2**30, timeout=30))  # 1 GiB > 256 MiB
    assert answer.status == 507 and "more memory than a worker may use (256 MiB" in answer.body
    assert asyncio.run(jobs.run(len, bytearray(10), timeout=30)) == 10  # the worker still serves


# ---------------------------------------------------------------------- a real server on loopback
@pytest.fixture(scope="module")
def server():
    """The app served by uvicorn on a free loopback port (short body timeout, small caps); yields (url, app)."""
    import uvicorn

    app = create_app(Limits(workers=2, body_timeout=1.0, max_client_jobs=4, max_queue=64))
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    uv = uvicorn.Server(uvicorn.Config(app, log_level="warning", lifespan="on"))
    thread = threading.Thread(target=uv.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    start = time.perf_counter()
    while not uv.started and time.perf_counter() - start < DEADLINE:
        time.sleep(0.05)
    try:
        yield f"http://127.0.0.1:{port}", app, port
    finally:
        uv.should_exit = True
        thread.join(timeout=30)
        sock.close()


def test_a_body_that_never_arrives_is_timed_out(server):
    url, app, port = server
    with socket.create_connection(("127.0.0.1", port), timeout=DEADLINE) as conn:
        conn.sendall(b"POST /apply/text HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/x-www-form-"
                     b"urlencoded\r\nContent-Length: 100\r\n\r\ntoml=")
        start = time.perf_counter()
        chunks = [conn.recv(65536)]  # the head and the body may come in two segments: read to the close
        seconds = time.perf_counter() - start
        while chunks[-1] and time.perf_counter() - start < DEADLINE:
            chunks.append(conn.recv(65536))
        answer = b"".join(chunks).decode("utf-8", "replace")
    assert answer.startswith("HTTP/1.1 408") and "did not arrive within 1 s" in answer and seconds < 30


def test_loopback_load_bounded_per_client_and_dropped_requests_cancelled(server):
    """40 solves at once: from one client at most 4 are taken (429 for the rest, nothing else); from 40
    clients all are answered with Brandenberger's η' = 0.85; requests dropped by their client are cancelled."""
    url, app, _ = server
    form = {"toml": bundled_examples()["brandenberger_1952"].text, "source": "b.toml", "units": "file",
            "lang": "en", "gear": ""}

    async def main():
        async with httpx.AsyncClient(timeout=DEADLINE, limits=httpx.Limits(max_connections=100)) as client:
            async def solve(who: str) -> int:
                answer = await client.post(url + "/apply/text", data=form, headers={"X-Epicyclic-Client": who})
                assert answer.status_code in (200, 429), answer.text[:300]
                assert answer.status_code == 429 or 'id="efficiency">0.8494<' in answer.text
                return answer.status_code

            one = await asyncio.wait_for(asyncio.gather(*(solve("same") for _ in range(40))), DEADLINE)
            # issue 30: 100 fresh page ids from one address are still one client (the id is the client's own
            # choice); another computer (127.0.0.2 on loopback) is served meanwhile
            fresh = asyncio.gather(*(solve(f"fresh{k}") for k in range(100)))
            transport = httpx.AsyncHTTPTransport(local_address="127.0.0.2")
            async with httpx.AsyncClient(timeout=DEADLINE, transport=transport) as other_computer:
                await asyncio.sleep(0.05)
                other = await other_computer.post(url + "/apply/text", data=form, headers={"X-Epicyclic-Client": "x"})
            many = await asyncio.wait_for(fresh, DEADLINE)
            before = app.state.jobs.cancelled
            slow = {**form, "tool_map_speed": "500..6000:400", "tool_map_torque": "10..500:400"}
            for _ in range(2):  # a long map, dropped by its client after 0.5 s
                with pytest.raises(httpx.TimeoutException):
                    await client.post(url + "/tool/map", data=slow, timeout=0.5)
            wait = time.perf_counter()
            while app.state.jobs.cancelled < before + 2 and time.perf_counter() - wait < 10:
                await asyncio.sleep(0.05)
            health = await client.get(url + "/healthz")
            return one, many, other.status_code, app.state.jobs.cancelled - before, health.status_code

    one, many, other, cancelled, health = asyncio.run(main())
    assert one.count(200) >= 4 and one.count(429) > 0 and set(one) <= {200, 429}
    assert many.count(200) >= 4 and many.count(429) > 0 and set(many) <= {200, 429}
    assert other == 200
    assert cancelled == 2 and health == 200 and app.state.jobs.pending == 0


def test_the_examples_pictures_are_drawn_ahead_at_start(examples):
    """``epicyclic serve`` draws every bundled example's pictures while idle: opening one shows them at once."""
    from starlette.testclient import TestClient

    from epicyclic.web.cache import figure_key
    from epicyclic.web.state import PageState

    key = "brandenberger_1952"  # the default example is drawn first
    with TestClient(create_app(Limits(workers=1, draw_examples=True))) as client:
        cache = client.app.state.cache
        # the lever: a picture the server draws (the charts are the browser's)
        wanted = figure_key(PageState(examples[key].text, examples[key].file_name), "lever")
        start = time.perf_counter()
        while wanted not in cache.answers and time.perf_counter() - start < DEADLINE:
            time.sleep(0.05)
        assert wanted in cache.answers
        form = {"toml": examples[key].text, "source": examples[key].file_name, "units": "file", "lang": "en",
                "gear": "", "fig_lever_format": "svg", "fig_lever_dpi": "150"}  # as the page sends it
        hits = cache.hits
        answer = client.post("/figure/lever", data=form)
        assert answer.status_code == 200 and "<svg" in answer.text and cache.hits == hits + 1


def test_a_refusal_for_memory_leaves_nothing_of_the_computation_behind():
    """Issue 30: after a 507 the worker stayed at 1.8 GB until its next job (the exception's frames held the
    computation's arrays) and the next large job got a false 507 at once. The answer that goes back holds no
    frame of the computation, and the memory is given back before it goes."""
    import numpy as np

    from epicyclic.web.views import _guard

    @_guard
    def hog() -> None:
        big = np.ones(2_000_000)  # noqa: F841 - held by the frame
        raise MemoryError

    with pytest.raises(MemoryError) as caught:
        hog()
    error = caught.value
    assert error.__context__ is None and error.__cause__ is None
    tb = error.__traceback__
    while tb is not None:
        assert "big" not in tb.tb_frame.f_locals, tb.tb_frame.f_code.co_name
        tb = tb.tb_next
