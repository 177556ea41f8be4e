"""The screenshots of the web tutorial (docs/tutorials/web.md): the page in headless Chromium.

Starts ``epicyclic serve``'s app on a free loopback port, opens the Ford C4 example on the Results and
the Pictures tab, waits until the page has answered (and the pictures are drawn) and writes
``docs/figures/web_page.png`` and ``docs/figures/web_pictures.png``, and every tab of the ZF 8HP and the
Brandenberger example into ``docs/figures/web/`` (``docs/web-tabs.md``); then records the digest of the
page's code (``stamp.py``), so that tests/docs/test_gallery.py fails when the page changes and the
screenshots do not.  ``make gallery`` runs it.  Needs Debian's chromium and chromium-driver.

Usage::

    .venv/bin/python docs/figures/make_screenshots.py
"""

from __future__ import annotations

import socket
import sys
import tempfile
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
CHROMIUM, CHROMEDRIVER = Path("/usr/bin/chromium"), Path("/usr/bin/chromedriver")
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage", "--window-size=1400,1000", "--hide-scrollbars")
#: (file, address query, what must be on the page before the shot)
SHOTS = (("web_page.png", "?example=simpson_c4_3speed", "#results table"),
         ("web_pictures.png", "?example=simpson_c4_3speed&tab=pictures", "#results svg"))
#: every tab of the page for the ZF 8HP and the Brandenberger example (docs/web-tabs.md)
TABS = ("results", "gears", "pictures", "geometry", "tools", "synthesis")
TAB_SHOTS = tuple((f"web/{example}_{tab}.png", f"?example={example}&tab={tab}", "#results table")
                  for example in ("zf_8hp70_8speed", "brandenberger_1952") for tab in TABS)
WAIT = 120  # seconds: the first answer starts the worker processes


def main() -> int:
    if not (CHROMIUM.exists() and CHROMEDRIVER.exists()):
        print("make_screenshots: needs /usr/bin/chromium and /usr/bin/chromedriver "
              "(apt-get install chromium chromium-driver); screenshots not taken", file=sys.stderr)
        return 1
    import uvicorn
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import WebDriverWait

    from epicyclic.web import Limits, create_app

    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    server = uvicorn.Server(uvicorn.Config(create_app(Limits(workers=2)), log_level="warning", lifespan="on"))
    thread = threading.Thread(target=server.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    profile = tempfile.TemporaryDirectory(prefix="epicyclic-chromium-")
    for flag in FLAGS + (f"--user-data-dir={profile.name}",):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(str(CHROMEDRIVER)), options=options)
    try:
        WebDriverWait(None, WAIT, poll_frequency=0.05).until(lambda _: server.started)
        (HERE / "web").mkdir(exist_ok=True)
        for name, query, ready in SHOTS + TAB_SHOTS:
            driver.get(f"http://127.0.0.1:{port}/{query}")
            WebDriverWait(driver, WAIT).until(lambda d: d.find_elements(By.CSS_SELECTOR, ready))
            time.sleep(3.0)  # the pictures of the tab arrive one by one
            driver.save_screenshot(str(HERE / name))
            print(f"wrote {HERE / name}")
    finally:
        driver.quit()
        profile.cleanup()
        server.should_exit = True
        thread.join(timeout=30)
        sock.close()
    from stamp import record  # beside this script

    record("web_page")  # the screenshots are as new as the page's code (tests/docs/test_gallery.py)
    return 0


if __name__ == "__main__":
    sys.exit(main())
