"""The page in headless Chromium: opening an example, and a gear change with every picture shown.

Run:  .venv/bin/python benchmarks/bench_page.py [rounds] [example]

* serves the page on a free port of 127.0.0.1 (uvicorn in a thread, 2 worker processes) and drives
  Debian's chromium (``/usr/bin/chromium``, ``/usr/bin/chromedriver``) with Selenium, in a window
  1400 px wide and tall enough that every picture of the Pictures tab is on screen (so every one is
  drawn: the page draws the pictures that are shown);
* a gear change is a click on a gear of the strip above the pictures; its time runs from the click
  until every picture of the new gear is on the page (no request in flight, none still drawing);
* ``rounds`` (default 2) rounds through every gear of ``example`` (default the ZF 8HP70,
  ``zf_8hp70_8speed``: 9 gears, 7 pictures, a speed plan of four sets);
* three pages in the same run, each on a fresh server: *naive* (``Limits(picture_cache=0,
  browser_charts=False)``: every picture drawn by the server on every change, none kept), *before*
  (``browser_charts=False``: pictures kept per file and gear and drawn ahead for the next gears while
  the server is idle, the page before the browser drew the charts) and *page* (the speed plan, the
  speed chart, the torques and the powers drawn in the browser from the data sent with the results,
  ``web/charts.py``; the lever, the power flow and the animation kept and drawn ahead); the user
  looks ``PAUSE`` (3 s) at each gear before the next click;
* opening the example: from the address typed to the results shown (Results tab, 3 times), and to
  every picture drawn (Pictures tab, 3 times, each in units not shown before so that no picture of
  them is kept, on an idle server).

Every gear change also reports the CPU seconds it cost (the worker processes of the server and
the browser's processes, from ``psutil``): on a shared machine the times above grow with the load,
the CPU seconds do not.  The load average is printed with the figures.

Bounded: every wait has a deadline (60 s); only loopback addresses are used.
"""

from __future__ import annotations

import os
import platform
import socket
import statistics
import sys
import threading
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))

WAIT = 60.0
PAUSE = 3.0  # seconds the user looks at a gear before the next click
CHROMIUM, CHROMEDRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"
#: Nothing in flight, no picture still drawing, every shown picture an SVG not from before the click.
#: A chart the browser draws (charts.js) counts once it is drawn (its canvases on the page).
DONE = ("return !document.querySelector('.htmx-request, .htmx-swapping, .htmx-settling') && "
        "Array.from(document.querySelectorAll('.fig-body')).filter(b => b.offsetParent !== null)"
        ".every(b => (b.querySelector('svg') || b.hasAttribute('data-drawn') && b.querySelector('canvas'))"
        " && !b.querySelector('.loading') && !b.hasAttribute('data-old'))"
        " && document.querySelectorAll('.fig-body svg, .chart-body canvas').length > 0;")
#: The pages compared in one run: (name, picture cache in bytes, the browser draws the charts).
PAGES = (("naive: every picture drawn by the server on every change, none kept", 0, False),
         ("before: pictures kept per file and gear, drawn ahead (main before the charts)", 64 << 20, False),
         ("page: charts drawn in the browser, other pictures kept and drawn ahead", 64 << 20, True))


def serve(picture_cache: int, browser_charts: bool = True):
    import uvicorn

    from epicyclic.web import Limits, create_app

    app = create_app(Limits(workers=2, picture_cache=picture_cache, browser_charts=browser_charts))
    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    server = uvicorn.Server(uvicorn.Config(app, log_level="warning", lifespan="on"))
    thread = threading.Thread(target=server.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    until(lambda: server.started)
    return f"http://127.0.0.1:{sock.getsockname()[1]}", app, server, thread


def until(condition, deadline: float = WAIT, poll: float = 0.01):
    start = time.perf_counter()
    while time.perf_counter() - start < deadline:
        value = condition()
        if value:
            return value
        time.sleep(poll)
    raise SystemExit(f"bench_page: a wait ran past its {deadline:g} s deadline")


def browser():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=1400,9000",
                 "--disable-background-networking", "--no-first-run"):
        options.add_argument(flag)
    return webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)


def cpu_seconds() -> tuple[float, float]:
    """CPU seconds used so far by this process's descendants: (the server's workers, the browser)."""
    import psutil

    workers = browser = 0.0
    for child in psutil.Process().children(recursive=True):
        try:
            times, name = child.cpu_times(), child.name()
        except psutil.Error:
            continue
        if "chrom" in name:
            browser += times.user + times.system
        else:
            workers += times.user + times.system
    return workers, browser


CPU: dict[str, list[tuple[float, float]]] = {}
CHARTS: dict[str, list[float]] = {}


def gear_changes(driver, url: str, app, example: str, rounds: int, page: str) -> list[float]:
    from selenium.webdriver.common.by import By

    driver.get(f"{url}/?example={example}&tab=pictures")
    until(lambda: driver.execute_script(DONE))
    gears = [b.get_attribute("data-gear") for b in driver.find_elements(By.CSS_SELECTOR, ".gear-strip button")]
    times, cpu = [], CPU.setdefault(page, [])
    for _ in range(rounds):
        for gear in gears[1:] + gears[:1]:
            time.sleep(PAUSE)  # the user looks at the pictures (the server may draw ahead meanwhile)
            driver.execute_script("document.querySelectorAll('.fig-body').forEach(b => b.setAttribute('data-old', ''))")
            used = cpu_seconds()
            start = time.perf_counter()
            driver.find_element(By.CSS_SELECTOR, f'.gear-strip button[data-gear="{gear}"]').click()
            until(lambda: driver.execute_script(DONE))
            times.append(time.perf_counter() - start)
            drawn = driver.execute_script("return window.epicyclicCharts ? epicyclicCharts.timings.splice(0) : []")
            if drawn:  # the browser's time drawing the charts of this gear (ms, all of them)
                CHARTS.setdefault(page, []).append(sum(ms for _, ms in drawn))
            now = cpu_seconds()
            cpu.append((now[0] - used[0], now[1] - used[1]))  # drawing ahead during the pause is not counted
            title = driver.find_element(By.CSS_SELECTOR, "#results .title").text
            assert f"gear {gear}" in title, (gear, title)
    return times


def idle(app) -> None:
    """Wait until the server draws nothing ahead and no job waits (at most the deadline)."""
    until(lambda: not app.state.cache.plans and not app.state.cache.tasks and not app.state.jobs.pending,
          deadline=300, poll=0.1)


def opening(driver, url: str, example: str, tab: str, units: str = "file") -> float:
    from selenium.webdriver.common.by import By

    driver.get(url + "/healthz")
    start = time.perf_counter()
    driver.get(f"{url}/?example={example}&tab={tab}&units={units}")
    if tab == "pictures":
        until(lambda: driver.execute_script(DONE))
    else:
        until(lambda: driver.find_elements(By.ID, "efficiency"))
    return time.perf_counter() - start


def percentile(values: list[float], q: int) -> float:
    return statistics.quantiles(values, n=100, method="inclusive")[q - 1] if len(values) > 1 else values[0]


def line(name: str, values: list[float]) -> str:
    return (f"{name:<44} n={len(values):>2}  p50 {1000 * percentile(values, 50):6.0f} ms  "
            f"p95 {1000 * percentile(values, 95):6.0f} ms  max {1000 * max(values):6.0f} ms")


def main() -> int:
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 2
    example = sys.argv[2] if len(sys.argv) > 2 else "zf_8hp70_8speed"
    if not (Path(CHROMIUM).exists() and Path(CHROMEDRIVER).exists()):
        print("bench_page needs chromium and chromedriver (apt-get install chromium chromium-driver)")
        return 2
    results: dict[str, list[float]] = {}
    loads = [os.getloadavg()[0]]
    driver = browser()
    try:
        for label, cache, charts in PAGES:
            short = label.split(":")[0]
            url, app, server, thread = serve(cache, charts)
            try:
                results[f"open, Results tab ({short})"] = [opening(driver, url, example, "results") for _ in range(3)]
                opened = []
                for units in ("si", "kw", "rpm-kw"):  # units not shown before: no picture of them kept yet
                    idle(app)
                    opened.append(opening(driver, url, example, "pictures", units))
                results[f"open, Pictures tab, nothing kept ({short})"] = opened
                idle(app)
                results[f"gear change, {label}"] = gear_changes(driver, url, app, example, rounds, short)
                kept = app.state.cache
                print(f"{short}: kept pictures {len(kept.answers)} ({kept.size / 2**20:.1f} MiB), hits {kept.hits}, "
                      f"misses {kept.misses}, drawn ahead {kept.drawn_ahead}")
                loads.append(os.getloadavg()[0])
            finally:
                server.should_exit = True
                thread.join(timeout=30)
    finally:
        driver.quit()
    print(f"epicyclic page benchmark — Python {platform.python_version()}, {os.cpu_count()} cores, 2 workers, "
          f"headless Chromium 1400 px wide, example {example}, {rounds} rounds through its gears, "
          f"load average (1 min) {' / '.join(f'{x:.1f}' for x in loads)} (start, after each page)")
    for name, values in results.items():
        print(line(name, values))
    for name, values in CPU.items():
        print(f"CPU seconds per gear change ({name}): workers median {statistics.median(v[0] for v in values):.2f} s, "
              f"browser median {statistics.median(v[1] for v in values):.2f} s")
    for name, values in CHARTS.items():
        print(f"charts drawn in the browser per gear change ({name}): median {statistics.median(values):.0f} ms, "
              f"max {max(values):.0f} ms")
    changes = [percentile(results[f"gear change, {label}"], 95) for label, _, _ in PAGES]
    print(f"gear change p95: page {changes[2]:.2f} s, {changes[0] / changes[2]:.1f}x faster than naive, "
          f"{changes[1] / changes[2]:.1f}x faster than before (target <= 1 s)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
