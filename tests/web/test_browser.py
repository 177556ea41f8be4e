"""Browser tests: the page in a real headless Chromium (Debian's chromium + chromium-driver, Selenium).

``make test`` installs chromium when it is missing.  Outside CI the tests are
skipped when the browser is not installed; with ``CI`` set they fail instead.
Set ``EPICYCLIC_SCREENSHOTS=<folder>`` to keep screenshots of every step.
Every wait is explicit (WebDriverWait on a condition), never a sleep.
"""

from __future__ import annotations

import json
import os
import socket
import tempfile
import threading
from pathlib import Path

import pytest

CHROMIUM, CHROMEDRIVER = Path("/usr/bin/chromium"), Path("/usr/bin/chromedriver")
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage", "--window-size=1400,1000")
WAIT = 60  # seconds: the first answer starts the worker processes; CI has 2 cores

if not (CHROMIUM.exists() and CHROMEDRIVER.exists()):
    if os.environ.get("CI"):
        raise RuntimeError("browser tests need /usr/bin/chromium and /usr/bin/chromedriver "
                           "(apt-get install -y chromium chromium-driver; make test does it)")
    pytest.skip("chromium and chromium-driver are not installed (make test installs them)", allow_module_level=True)

from selenium import webdriver  # noqa: E402
from selenium.common.exceptions import NoAlertPresentException, StaleElementReferenceException  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402
from selenium.webdriver.support import expected_conditions as ec  # noqa: E402
from selenium.webdriver.support.ui import Select, WebDriverWait  # noqa: E402

from epicyclic.io import loads_train_file  # noqa: E402
from epicyclic.io.tables import fmt  # noqa: E402
from epicyclic.web import Limits, create_app  # noqa: E402
from epicyclic.web.examples import bundled_examples  # noqa: E402


@pytest.fixture(scope="module")
def server():
    """The app served by uvicorn on a free loopback port, in a thread; yields its URL."""
    import uvicorn

    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    config = uvicorn.Config(create_app(Limits(workers=2)), log_level="warning", lifespan="on")
    uv = uvicorn.Server(config)
    thread = threading.Thread(target=uv.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    try:
        WebDriverWait(None, WAIT, poll_frequency=0.05).until(lambda _: uv.started)
        yield f"http://127.0.0.1:{port}"
    finally:
        uv.should_exit = True
        thread.join(timeout=30)
        sock.close()


@pytest.fixture(scope="module")
def downloads():
    with tempfile.TemporaryDirectory(prefix="epicyclic-downloads-") as folder:
        yield Path(folder)


@pytest.fixture(scope="module")
def browser(downloads):
    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    profile = tempfile.TemporaryDirectory(prefix="epicyclic-chromium-")
    for flag in FLAGS + (f"--user-data-dir={profile.name}",):
        options.add_argument(flag)
    options.add_experimental_option("prefs", {"download.default_directory": str(downloads),
                                              "download.prompt_for_download": False})
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(str(CHROMEDRIVER)), options=options)
    driver.execute_cdp_cmd("Page.setDownloadBehavior", {"behavior": "allow", "downloadPath": str(downloads)})
    try:
        yield driver
    finally:
        driver.quit()
        profile.cleanup()


def shot(browser, name: str) -> None:
    folder = os.environ.get("EPICYCLIC_SCREENSHOTS")
    if folder:
        Path(folder).mkdir(parents=True, exist_ok=True)
        height = browser.execute_script("return document.body.scrollHeight")
        browser.set_window_size(1400, min(max(height, 1000), 6000))
        browser.save_screenshot(str(Path(folder) / f"{name}.png"))
        browser.set_window_size(1400, 1000)


def wait(browser, condition, timeout: float = WAIT):
    """Wait for ``condition``; an element replaced by a swap while it is read is read again."""
    return WebDriverWait(browser, timeout, poll_frequency=0.05,
                         ignored_exceptions=(StaleElementReferenceException,)).until(condition)


#: True while the page is still changing: an htmx request in flight (htmx marks the requesting element or
#: its indicator with ``htmx-request``), a swap settling, or a picture still being drawn.  Content below the
#: pictures moves while they arrive, so a click is only sent to a settled page.
_BUSY = ("return !!document.querySelector('.htmx-request, .htmx-swapping, .htmx-settling, .htmx-added, "
         ".fig-body .loading');")


def settled(browser) -> None:
    """Wait until no request is in flight and every picture is drawn (nothing moves any more)."""
    wait(browser, lambda b: not b.execute_script(_BUSY))


def click(browser, css: str) -> None:
    """Click the element ``css`` of the settled page once it is visible and enabled."""
    settled(browser)
    wait(browser, ec.element_to_be_clickable((By.CSS_SELECTOR, css))).click()


def open_details(browser, css: str) -> None:
    """Open the ``<details>`` element ``css`` (click its summary) and wait until it is open."""
    click(browser, f"{css} > summary")
    wait(browser, lambda b: b.find_element(By.CSS_SELECTOR, css).get_attribute("open") is not None)


def text_of(browser, css: str) -> str:
    """The text of the first visible element matching ``css``, once it is there and not empty."""
    def read(driver):
        element = driver.find_element(By.CSS_SELECTOR, css)
        return element.text if element.is_displayed() else ""

    return wait(browser, read)


def shows(browser, css: str, text: str) -> str:
    """Wait until the element ``css`` contains ``text`` (an answer that has arrived); its whole text."""
    wait(browser, ec.text_to_be_present_in_element((By.CSS_SELECTOR, css), text))
    return text_of(browser, css)


def open_example(browser, server: str, key: str) -> None:
    """Load the page with example ``key`` (``/?example=key``); wait until its results are shown."""
    browser.get(f"{server}/?example={key}")
    wait(browser, ec.text_to_be_present_in_element((By.CSS_SELECTOR, "#results .title"),
                                                  bundled_examples()[key].title))


def no_alert(browser) -> bool:
    try:
        browser.switch_to.alert
    except NoAlertPresentException:
        return True
    return False


def test_page_loads_with_an_example_and_its_pictures(browser, server):
    browser.get(server + "/")
    assert text_of(browser, "#efficiency") == "0.8494"  # Brandenberger 1952: η' = 0.85
    Select(browser.find_element(By.ID, "example")).select_by_value("plus_set_reduction")  # open another one
    wait(browser, ec.text_to_be_present_in_element((By.CSS_SELECTOR, "#results .title"),
                                                  bundled_examples()["plus_set_reduction"].title))
    wait(browser, lambda b: b.find_elements(By.CSS_SELECTOR, "#fig-power svg"))
    settled(browser)
    assert len(browser.find_elements(By.CSS_SELECTOR, ".fig-body svg")) >= 5
    shows(browser, "#gutter", "22")  # line numbers, drawn once the swap has settled
    shot(browser, "1-plus-set")
    errors = [e for e in browser.get_log("browser") if e["level"] == "SEVERE"]
    assert not errors, errors  # no script errors, no CSP violations, no missing files


def test_change_a_speed_and_see_the_efficiency_change(browser, server):
    key = "three_shaft_power_split"
    open_example(browser, server, key)
    before = text_of(browser, "#efficiency")
    speed = browser.find_element(By.CSS_SELECTOR, 'tr[data-shaft="output"] input[name="speed"]')
    speed.clear()
    speed.send_keys("500", Keys.TAB)
    wait(browser, lambda b: b.find_element(By.ID, "efficiency").text != before)
    expected = loads_train_file(bundled_examples()[key].text.replace("output = 1500", "output = 500")).solve()
    assert text_of(browser, "#efficiency") == fmt(expected.efficiency, 4)
    assert "output = 500" in browser.find_element(By.ID, "toml").get_attribute("value")  # the text follows the form
    shot(browser, "2-speed-changed")


def test_switch_a_gear(browser, server):
    open_example(browser, server, "simpson_c4_3speed")
    assert text_of(browser, "tr.current td") == "1"
    click(browser, 'tr[data-gear="2"]')
    wait(browser, ec.presence_of_element_located((By.CSS_SELECTOR, 'tr.current[data-gear="2"]')))
    assert abs(float(text_of(browser, "#ratio")) - 1.46) < 0.01  # Ford C4 second gear, published 1.46
    assert Select(browser.find_element(By.ID, "gear")).first_selected_option.text == "2"
    assert 'gear = "2"' in browser.find_element(By.ID, "toml").get_attribute("value")
    shot(browser, "3-gear-2")


def test_the_animation_runs(browser, server):
    open_example(browser, server, "simple_set_ring_held_sun_drives")
    wait(browser, ec.presence_of_element_located((By.CSS_SELECTOR, "#fig-animation svg animateTransform")))
    angle = ("var t = document.querySelector('#fig-animation svg animateTransform').parentNode;"
             "var m = t.getCTM(); return Math.atan2(m.b, m.a);")
    first = browser.execute_script(angle)
    wait(browser, lambda b: abs(b.execute_script(angle) - first) > 0.05, timeout=20)  # it turns
    assert browser.execute_script("return document.querySelector('#fig-animation svg').animationsPaused()") is False
    size = browser.find_element(By.NAME, "fig_animation_size")  # the animation's width, as animate --size
    size.clear()
    size.send_keys("300", Keys.TAB)
    wait(browser, lambda b: b.find_element(By.CSS_SELECTOR, "#fig-animation svg").get_attribute("width") == "300")
    click(browser, "#fig-animation [data-enlarge]")  # at full width
    wait(browser, lambda b: b.find_element(By.ID, "zoom").get_attribute("open") is not None)
    assert browser.find_element(By.CSS_SELECTOR, "#zoom svg").size["width"] > 1000
    shot(browser, "4-animation")
    click(browser, "#zoom button")
    wait(browser, lambda b: b.find_element(By.ID, "zoom").get_attribute("open") is None)


def test_download_reports(browser, server, downloads):
    open_example(browser, server, "brandenberger_1952")
    for kind in ("json", "html", "toml"):
        click(browser, f'button[data-download="/download/{kind}"]')
        target = downloads / f"brandenberger_1952.{kind}"
        wait(browser, lambda _: target.exists() and target.stat().st_size > 0)
        wait(browser, ec.text_to_be_present_in_element((By.ID, "download-status"), f"downloaded brandenberger_1952.{kind}"))
    report = json.loads((downloads / "brandenberger_1952.json").read_text())
    assert report["schema"].startswith("epicyclic-report/") and abs(report["solution"]["efficiency"] - 0.85) < 0.005
    assert (downloads / "brandenberger_1952.html").read_text().startswith("<!DOCTYPE html>")
    assert (downloads / "brandenberger_1952.toml").read_text() == bundled_examples()["brandenberger_1952"].text
    # a picture as PNG at the resolution asked for
    open_details(browser, "#fig-flow details.save")
    Select(browser.find_element(By.NAME, "fig_flow_format")).select_by_value("png")
    dpi = browser.find_element(By.NAME, "fig_flow_dpi")
    dpi.clear()
    dpi.send_keys("60")
    click(browser, '#fig-flow button[data-download="/save/flow"]')
    target = downloads / "brandenberger_1952-flow.png"
    wait(browser, lambda _: target.exists() and target.stat().st_size > 0)
    assert target.read_bytes().startswith(b"\x89PNG")


def test_an_error_is_shown_at_its_line(browser, server):
    open_example(browser, server, "brandenberger_1952")
    editor = browser.find_element(By.ID, "toml")
    text = editor.get_attribute("value").replace("stationary_efficiency = 0.9", "stationary_efficiency = 1.9")
    browser.execute_script("arguments[0].value = arguments[1];"
                           "arguments[0].dispatchEvent(new Event('input', {bubbles: true}));", editor, text)
    editor.send_keys(Keys.CONTROL, Keys.ENTER)
    message = text_of(browser, "#results .problem .message")
    assert "key 'stationary_efficiency': expected an efficiency in (0, 1]" in message
    line = text.splitlines().index(next(l for l in text.splitlines() if l.startswith("stationary_efficiency"))) + 1
    assert text_of(browser, "#gutter b.err") == str(line)
    assert shows(browser, "#editor-status", "error at line") == f"error at line {line}"
    shot(browser, "5-error")


def test_script_in_a_name_stays_text(browser, server):
    open_example(browser, server, "simple_set_ring_held_sun_drives")
    editor = browser.find_element(By.ID, "toml")
    payload = '<img src=x onerror=alert(1)><script>alert(2)</script>'
    text = editor.get_attribute("value").replace('title = "', f'title = "{payload} ', 1)
    browser.execute_script("arguments[0].value = arguments[1];", editor, text)
    click(browser, "#solve")
    wait(browser, ec.text_to_be_present_in_element((By.CSS_SELECTOR, "#results .title"), payload))
    assert not browser.find_elements(By.CSS_SELECTOR, "#results img, #results script")
    assert no_alert(browser)


def test_geometry_form_and_german_explanation(browser, server):
    open_example(browser, server, "simple_set_ring_held_sun_drives")
    open_details(browser, "#tool-fit")
    click(browser, "#tool-fit button")
    shows(browser, "#tool-fit-result", "coaxiality")
    settled(browser)
    Select(browser.find_element(By.ID, "lang")).select_by_value("de")  # replaces the results, pictures included
    shows(browser, "#explain summary", "Deutsch")
    open_details(browser, "#explain details")  # once the new pictures are drawn: nothing moves under the click
    shows(browser, "#explain .epicyclic-explanation", "Wirkungsgrad")
    # the worked solution's long lines scroll inside the results column; the page itself does not get wider
    # than the window (it did: the grid column grew to the widest line, cutting the tables off at the right)
    assert browser.execute_script("return document.documentElement.scrollWidth <= window.innerWidth")
    shot(browser, "6-geometry-german")


def test_open_a_file_from_disk(browser, server, tmp_path):
    text = bundled_examples()["simple_set_sun_held_ring_drives"].text.replace('title = "', 'title = "Uploaded: ', 1)
    path = tmp_path / "my_train.toml"
    path.write_text(text, encoding="utf-8")
    browser.get(server + "/")
    wait(browser, ec.presence_of_element_located((By.ID, "efficiency")))
    browser.find_element(By.ID, "upload").send_keys(str(path))
    wait(browser, ec.text_to_be_present_in_element((By.CSS_SELECTOR, "#results .title"), "Uploaded: "))
    assert browser.find_element(By.CSS_SELECTOR, ".editor .source").text == "my_train.toml"
    assert browser.find_element(By.ID, "toml").get_attribute("value") == text


def test_efficiency_map_form_and_loss_split(browser, server, downloads):
    open_example(browser, server, "geometry_simple_set")
    split = shows(browser, "#loss-split", "bearing")  # the loss by source of each element and in all
    expected = loads_train_file(bundled_examples()["geometry_simple_set"].text).solve().elements["P"].loss_sources
    assert f"P {fmt(expected['mesh'], 6)} {fmt(expected['bearing'], 6)} {fmt(expected['drag'], 6)}" in split
    open_details(browser, "#tool-fit")  # the set's fields start from the file's geometry table
    Select(browser.find_element(By.NAME, "tool_fit_set")).select_by_value("P")
    wait(browser, lambda b: b.find_element(By.NAME, "tool_fit_module").get_attribute("value") == "1.75")
    assert browser.find_element(By.NAME, "tool_fit_x_sun").get_attribute("value") == "0.438"
    click(browser, "#tool-fit > button")
    shows(browser, "#tool-fit-result", "a_w = 56.7999 mm")  # lecad test run: a = 56.8 mm
    open_details(browser, "#tool-map")
    speed = browser.find_element(By.NAME, "tool_map_speed")
    speed.clear()
    speed.send_keys("1000..5000:21")
    click(browser, "#tool-map > button")
    summary = shows(browser, "#tool-map-result pre", "input speed 1000..5000 1/min (21 values)")
    assert "losses by source" in summary
    wait(browser, lambda b: b.find_element(By.CSS_SELECTOR, "#tool-map-result svg").size["height"] > 200)
    shot(browser, "7-efficiency-map")
    click(browser, '#tool-map-result button[data-download="/download/map.csv"]')
    target = downloads / "geometry_simple_set-map.csv"
    wait(browser, lambda _: target.exists() and target.stat().st_size > 0)
    lines = target.read_text().splitlines()
    assert lines[0].startswith("speed_rpm,torque_Nm,efficiency") and len(lines) == 1 + 21 * 50
    # a load beyond the friction correlation: the command line's message, at the form
    torque = browser.find_element(By.NAME, "tool_map_torque")
    torque.clear()
    torque.send_keys("1e300")
    click(browser, "#tool-map > button")
    assert "leaves no efficiency" in shows(browser, "#tool-map-result .problem .message", "μ·H_V >= 1")
    assert no_alert(browser)
