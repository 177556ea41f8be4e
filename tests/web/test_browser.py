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
from selenium.common.exceptions import (  # noqa: E402
    NoAlertPresentException,
    StaleElementReferenceException,
    TimeoutException,
)
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402
from selenium.webdriver.support import expected_conditions as ec  # noqa: E402
from selenium.webdriver.support.ui import Select, WebDriverWait  # noqa: E402

from epicyclic.io import loads_train_file  # noqa: E402
from epicyclic.io.tables import fmt  # noqa: E402
from epicyclic.web import Limits, create_app  # noqa: E402
from epicyclic.web.examples import bundled_examples  # noqa: E402


#: The app the server fixture serves (its job counters tell what the server did).
APP: list = []


@pytest.fixture(scope="module")
def server():
    """The app served by uvicorn on a free loopback port, in a thread; yields its URL."""
    import uvicorn

    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    app = create_app(Limits(workers=2))
    APP.append(app)
    config = uvicorn.Config(app, log_level="warning", lifespan="on")
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
    options.set_capability("unhandledPromptBehavior", "accept")  # "leave with unsaved edits?": leave
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
#: its indicator with ``htmx-request``), a swap settling, or a picture on screen still being drawn (one
#: below the window is drawn once it is scrolled to).  Content below the pictures moves while they arrive,
#: so a click is only sent to a settled page.
_BUSY = ("return !!document.querySelector('.htmx-request, .htmx-swapping, .htmx-settling, .htmx-added') || "
         "Array.from(document.querySelectorAll('.fig-body .loading')).some(e => e.offsetParent !== null && "
         "e.getBoundingClientRect().top < innerHeight && e.getBoundingClientRect().bottom > 0);")


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


def open_example(browser, server: str, key: str, query: str = "") -> None:
    """Load the page with example ``key`` (``/?example=key``, edits kept from before forgotten); wait until its
    results are shown."""
    browser.get(f"{server}/healthz")
    browser.execute_script("localStorage.clear()")
    browser.get(f"{server}/?example={key}{query}")
    wait(browser, ec.text_to_be_present_in_element((By.CSS_SELECTOR, "#results .title"),
                                                  bundled_examples()[key].title))


def tab(browser, name: str) -> None:
    """Show the tab ``name`` (results, gears, pictures, geometry, tools)."""
    click(browser, f'[data-tab-button="{name}"]')
    wait(browser, lambda b: b.find_element(By.ID, "ws").get_attribute("data-tab") == name)


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
    assert not browser.find_elements(By.CSS_SELECTOR, ".fig-body svg")  # pictures are drawn when shown
    tab(browser, "pictures")
    wait(browser, lambda b: b.find_elements(By.CSS_SELECTOR, "#fig-torque .chart-body[data-drawn] canvas"))
    browser.execute_script("document.getElementById('fig-flow').scrollIntoView()")  # drawn once on screen
    wait(browser, lambda b: b.find_elements(By.CSS_SELECTOR, "#fig-flow svg"))
    browser.execute_script("document.getElementById('fig-power').scrollIntoView()")
    wait(browser, lambda b: b.find_elements(By.CSS_SELECTOR, "#fig-power .chart-body[data-drawn] canvas"))
    settled(browser)
    assert len(browser.find_elements(By.CSS_SELECTOR, ".fig-body svg, .chart-body[data-drawn]")) >= 5
    shot(browser, "1-plus-set")
    # every picture readable: its smallest text at least 11 px on the screen
    smallest = browser.execute_script("""return Math.min.apply(null, Array.from(document.querySelectorAll(
        '.fig-body svg:not(:has(animateTransform)) text')).map(t => t.getBoundingClientRect().height > 0 ?
        parseFloat(getComputedStyle(t).fontSize) * Math.hypot(t.getScreenCTM().a, t.getScreenCTM().b) :
        Infinity));""")  # a rotated label's scale too
    assert smallest >= 10.9, smallest
    tab(browser, "results")
    shows(browser, "#gutter", "22")  # line numbers, drawn once the swap has settled
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
    tab(browser, "gears")
    assert text_of(browser, "tr.current td") == "1"
    click(browser, 'tr[data-gear="2"]')
    wait(browser, ec.presence_of_element_located((By.CSS_SELECTOR, 'tr.current[data-gear="2"]')))
    tab(browser, "results")
    assert abs(float(text_of(browser, "#ratio")) - 1.46) < 0.01  # Ford C4 second gear, published 1.46
    assert Select(browser.find_element(By.ID, "gear")).first_selected_option.text == "2"
    assert 'gear = ' not in browser.find_element(By.ID, "toml").get_attribute("value")  # a view, no edit
    shot(browser, "3-gear-2")


def test_the_animation_runs(browser, server):
    open_example(browser, server, "simple_set_ring_held_sun_drives", "&tab=pictures")
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
    tab(browser, "pictures")
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
    open_example(browser, server, "zf_8hp70_8speed")
    editor = browser.find_element(By.ID, "toml")
    text = editor.get_attribute("value").replace('output = "out"', 'output = "nowhere"')
    browser.execute_script("arguments[0].value = arguments[1];"
                           "arguments[0].dispatchEvent(new Event('input', {bubbles: true}));", editor, text)
    editor.send_keys(Keys.CONTROL, Keys.ENTER)
    message = text_of(browser, "#results .problem .message")
    assert "[transmission], key 'output': unknown shaft 'nowhere'" in message
    line = text.splitlines().index('output = "nowhere"') + 1
    assert line > 60  # far below the first screen of the editor
    assert text_of(browser, "#gutter b.err") == str(line)
    assert shows(browser, "#editor-status", "error at line") == f"error at line {line}"
    # the editor is scrolled to it, and the mark is beside that line of the text (not off by the scroll bar)
    where = """var t = document.getElementById('toml'), mark = document.querySelector('#gutter b.err');
        var style = getComputedStyle(t), height = parseFloat(style.lineHeight);
        var top = t.getBoundingClientRect().top + parseFloat(style.paddingTop) + (arguments[0] - 1) * height - t.scrollTop;
        var box = t.getBoundingClientRect();
        return [mark.getBoundingClientRect().top, top, box.top, box.bottom];"""
    mark, expected, box_top, box_bottom = browser.execute_script(where, line)
    assert abs(mark - expected) < 2 and box_top < expected < box_bottom, (mark, expected, box_top, box_bottom)
    browser.execute_script("arguments[0].scrollTop = arguments[0].scrollHeight;", editor)  # to the end: no drift
    # the gutter follows on the scroll event, which the browser fires with the next frame: wait for it (bounded)
    offsets = []

    def settled(_):
        mark, expected, _, _ = browser.execute_script(where, line)
        offsets.append(mark - expected)
        return abs(offsets[-1]) < 2

    try:
        wait(browser, settled)
    except TimeoutException:
        raise AssertionError(f"the error mark stays {offsets[-1]:.1f} px off its line after scrolling") from None
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
    tab(browser, "geometry")
    open_details(browser, "#tool-fit")
    click(browser, "#tool-fit button")
    shows(browser, "#tool-fit-result", "coaxiality")
    settled(browser)
    Select(browser.find_element(By.ID, "lang")).select_by_value("de")  # replaces the results, pictures included
    tab(browser, "results")
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
    # the example list shows the file that is open; the address names it, and a reload opens it again
    assert Select(browser.find_element(By.ID, "example")).first_selected_option.text == "file: my_train.toml"
    wait(browser, lambda b: "file=my_train.toml" in b.current_url)
    browser.refresh()
    wait(browser, ec.text_to_be_present_in_element((By.CSS_SELECTOR, "#results .title"), "Uploaded: "))
    assert browser.find_element(By.ID, "toml").get_attribute("value") == text


def test_efficiency_map_form_and_loss_split(browser, server, downloads):
    open_example(browser, server, "geometry_simple_set")
    split = shows(browser, "#loss-split", "bearing")  # the loss by source of each element and in all
    expected = loads_train_file(bundled_examples()["geometry_simple_set"].text).solve().elements["P"].loss_sources
    assert f"P {fmt(expected['mesh'], 6)} {fmt(expected['bearing'], 6)} {fmt(expected['drag'], 6)}" in split
    tab(browser, "geometry")
    open_details(browser, "#tool-fit")  # the set's fields start from the file's geometry table
    Select(browser.find_element(By.NAME, "tool_fit_set")).select_by_value("P")
    wait(browser, lambda b: b.find_element(By.NAME, "tool_fit_module").get_attribute("value") == "1.75")
    assert browser.find_element(By.NAME, "tool_fit_x_sun").get_attribute("value") == "0.438"
    click(browser, "#tool-fit > button")
    shows(browser, "#tool-fit-result", "a_w = 56.7999 mm")  # lecad test run: a = 56.8 mm
    tab(browser, "tools")
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


def test_the_address_holds_example_gear_operating_point_and_tab(browser, server):
    open_example(browser, server, "simpson_c4_3speed")
    tab(browser, "gears")
    click(browser, 'tr[data-gear="2"]')
    wait(browser, ec.presence_of_element_located((By.CSS_SELECTOR, 'tr.current[data-gear="2"]')))
    speed = browser.find_element(By.CSS_SELECTOR, 'tr[data-shaft="in"] input[name="speed"]')
    speed.clear()
    speed.send_keys("2500 1/min", Keys.TAB)
    wait(browser, lambda b: "2500" in b.current_url and "gear=2" in b.current_url and "tab=gears" in b.current_url)
    tab(browser, "results")
    ratio, power = text_of(browser, "#ratio"), text_of(browser, "#input-power")
    tab(browser, "gears")
    shared = browser.current_url
    browser.execute_script("localStorage.clear()")  # a shared link: another browser, nothing kept
    browser.get(shared)
    wait(browser, ec.presence_of_element_located((By.CSS_SELECTOR, 'tr.current[data-gear="2"]')))
    assert browser.find_element(By.ID, "ws").get_attribute("data-tab") == "gears"
    assert browser.find_element(By.CSS_SELECTOR, 'tr[data-shaft="in"] input[name="speed"]').get_attribute(
        "value") == "2500 1/min"
    tab(browser, "results")
    assert (text_of(browser, "#ratio"), text_of(browser, "#input-power")) == (ratio, power)
    assert Select(browser.find_element(By.ID, "example")).first_selected_option.get_attribute("value") == \
        "simpson_c4_3speed"


def test_edits_are_kept_and_leaving_with_them_warns(browser, server):
    open_example(browser, server, "brandenberger_1952")
    leaving = ("var e = new Event('beforeunload', {cancelable: true}); window.dispatchEvent(e); "
               "return e.defaultPrevented;")
    assert browser.execute_script(leaving) is False  # nothing changed yet
    editor = browser.find_element(By.ID, "toml")
    editor.send_keys(Keys.CONTROL, Keys.END)
    editor.send_keys("\n# my note\n")
    wait(browser, lambda b: "kept" in b.find_element(By.ID, "draft-status").text)
    assert browser.execute_script(leaving) is True
    assert "(edited)" in Select(browser.find_element(By.ID, "example")).first_selected_option.text
    browser.refresh()  # the prompt is accepted (unhandledPromptBehavior)
    wait(browser, lambda b: "# my note" in b.find_element(By.ID, "toml").get_attribute("value"))
    shows(browser, "#draft-restored", "were restored")
    click(browser, "#discard-draft")
    wait(browser, lambda b: b.find_element(By.ID, "toml").get_attribute("value") ==
         bundled_examples()["brandenberger_1952"].text)


def test_downloaded_toml_keeps_windows_line_endings(browser, server, downloads, tmp_path):
    text = bundled_examples()["simple_set_sun_held_ring_drives"].text.replace("\n", "\r\n")
    path = tmp_path / "crlf_train.toml"
    path.write_bytes(text.encode("utf-8"))
    open_example(browser, server, "brandenberger_1952")
    browser.find_element(By.ID, "upload").send_keys(str(path))
    wait(browser, lambda b: b.find_element(By.CSS_SELECTOR, ".editor .source").text == "crlf_train.toml")
    click(browser, 'button[data-download="/download/toml"]')
    target = downloads / "crlf_train.toml"
    wait(browser, lambda _: target.exists() and target.stat().st_size > 0)
    assert target.read_bytes() == text.encode("utf-8")


def test_the_gear_table_in_the_browser_is_the_command_lines(browser, server, tmp_path):
    from tests.web.test_numbers import cli_gear_rows

    key = "zf_8hp70_geometry"  # loss models from the geometry: η differs from gear to gear
    path = tmp_path / f"{key}.toml"
    path.write_text(bundled_examples()[key].text, encoding="utf-8")
    open_example(browser, server, key, "&tab=gears")
    wait(browser, ec.presence_of_element_located((By.CSS_SELECTOR, ".gear-table tbody tr")))
    rows = [[td.text for td in tr.find_elements(By.TAG_NAME, "td")]
            for tr in browser.find_elements(By.CSS_SELECTOR, ".gear-table tbody tr")]
    assert rows == cli_gear_rows(path)
    shot(browser, "8-gears-8hp-geometry")


@pytest.fixture(scope="module")
def foreign_page(server):
    """A page of another origin (its own server on another loopback port) whose form posts to the page's
    server at once: what a web page elsewhere could do (cross-site request forgery)."""
    import http.server

    page = (f'<!DOCTYPE html><form id="f" method="post" action="{server}/example">'
            '<input name="example" value="brandenberger_1952"></form>'
            "<script>document.getElementById('f').submit()</script>").encode()

    class Handler(http.server.BaseHTTPRequestHandler):
        def do_GET(self):  # noqa: N802 - the standard library's name
            self.send_response(200)
            self.send_header("Content-Type", "text/html")
            self.end_headers()
            self.wfile.write(page)

        def log_message(self, *args):
            pass

    other = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    thread = threading.Thread(target=other.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{other.server_address[1]}/"
    other.shutdown()
    other.server_close()


def test_a_post_from_another_origin_is_refused(browser, server, foreign_page):
    jobs, cache = APP[-1].state.jobs, APP[-1].state.cache
    wait(browser, lambda _: not cache.plans and not jobs.pending)  # nothing drawn ahead any more
    before = jobs.started
    browser.get(foreign_page)  # its form is sent to the page's server at once
    wait(browser, lambda b: "refused" in b.find_element(By.TAG_NAME, "body").text)
    assert "another site (Sec-Fetch-Site: same-site)" in browser.find_element(By.TAG_NAME, "body").text
    assert jobs.started == before  # refused before any work
    assert "0.8494" not in browser.page_source


def test_a_dropped_requests_job_is_cancelled(browser, server):
    jobs = APP[-1].state.jobs
    open_example(browser, server, "geometry_simple_set", "&tab=tools")
    open_details(browser, "#tool-map")
    for name, grid in (("speed", "500..6000:1000"), ("torque", "10..500:900")):  # a long map
        field = browser.find_element(By.NAME, f"tool_map_{name}")
        field.clear()
        field.send_keys(grid)
    before = jobs.cancelled
    click(browser, "#tool-map > button")
    wait(browser, lambda _: any(client != "ahead" for client in jobs.per_client))  # the map runs (not a picture
    # drawn ahead for the gears of the test before)
    browser.get(server + "/healthz")  # the page is left: the browser drops the request
    wait(browser, lambda _: jobs.cancelled >= before + 1, timeout=20)  # long before the map would be done
    wait(browser, lambda _: not any(client != "ahead" for client in jobs.per_client), timeout=20)
