"""Browser tests of issue 30's page items: Back/Forward, a gear click is no edit, a missing ``?file=``, own
files named like examples, unreadable uploads, the worked solution across a language switch, the console.

The fixtures are the browser tests' (:mod:`tests.web.test_browser`); every wait is bounded.
"""

from __future__ import annotations

import pytest

from tests.web.test_browser import (  # noqa: F401 - fixtures
    CHROMEDRIVER,
    CHROMIUM,
    browser,
    click,
    downloads,
    open_example,
    server,
    settled,
    shows,
    tab,
    wait,
)

if not (CHROMIUM.exists() and CHROMEDRIVER.exists()):  # pragma: no cover - test_browser skips the same way
    pytest.skip("chromium and chromium-driver are not installed", allow_module_level=True)

from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.support import expected_conditions as ec  # noqa: E402
from selenium.webdriver.support.ui import Select  # noqa: E402

from epicyclic.web.examples import bundled_examples  # noqa: E402

LEAVING = "var e = new Event('beforeunload', {cancelable: true}); window.dispatchEvent(e); return e.defaultPrevented;"


def title_is(browser, key: str) -> None:
    wait(browser, ec.text_to_be_present_in_element((By.CSS_SELECTOR, "#results .title"), bundled_examples()[key].title))


def severe(browser) -> list:
    return [e for e in browser.get_log("browser") if e["level"] == "SEVERE" and "favicon.ico" not in e["message"]]


def test_back_and_forward_step_through_examples_and_gears(browser, server):
    open_example(browser, server, "simpson_c4_3speed")
    severe(browser)  # the log so far is read: only this test's entries count below
    Select(browser.find_element(By.ID, "example")).select_by_value("wolfrom_drive")
    title_is(browser, "wolfrom_drive")
    settled(browser)
    browser.back()
    title_is(browser, "simpson_c4_3speed")
    settled(browser)
    browser.forward()
    title_is(browser, "wolfrom_drive")
    settled(browser)
    Select(browser.find_element(By.ID, "example")).select_by_value("zf_8hp70_8speed")
    title_is(browser, "zf_8hp70_8speed")
    tab(browser, "gears")
    click(browser, 'tr[data-gear="5"]')
    wait(browser, ec.presence_of_element_located((By.CSS_SELECTOR, 'tr.current[data-gear="5"]')))
    settled(browser)
    text = browser.find_element(By.ID, "toml").get_attribute("value")
    assert text == bundled_examples()["zf_8hp70_8speed"].text  # no gear = "5", no operating point written
    assert browser.execute_script(LEAVING) is False  # nothing to lose: no leave warning
    assert "(edited)" not in Select(browser.find_element(By.ID, "example")).first_selected_option.text
    assert "gear=5" in browser.current_url
    browser.back()  # the gear before
    wait(browser, ec.presence_of_element_located((By.CSS_SELECTOR, 'tr.current[data-gear="1"]')))
    settled(browser)
    browser.back()  # the example before
    title_is(browser, "wolfrom_drive")
    settled(browser)
    assert not severe(browser)  # the aborted and replaced requests are no errors


def test_a_file_link_whose_file_is_not_kept_says_so(browser, server):
    browser.get(f"{server}/healthz")
    browser.execute_script("localStorage.clear()")
    browser.get(server + '/?file=FVA_Planetary_stage.rexs&op=[["Sonnenwelle [34]","drive","1500","torque","1"]]')
    title_is(browser, "brandenberger_1952")
    note = browser.find_element(By.ID, "file-missing")
    assert note.is_displayed() and "FVA_Planetary_stage.rexs" in note.text and "not kept in this browser" in note.text
    assert "Sonnenwelle" not in browser.find_element(By.ID, "toml").get_attribute("value")
    assert not browser.find_elements(By.CSS_SELECTOR, "#results .problem")


def test_own_files_and_unreadable_uploads(browser, server, tmp_path):
    own = tmp_path / "zf_8hp70_8speed.toml"
    own.write_text(bundled_examples()["zf_8hp70_8speed"].text.replace("[[planetary]]", "# mine\n[[planetary]]", 1),
                   encoding="utf-8")
    open_example(browser, server, "brandenberger_1952")
    browser.find_element(By.ID, "upload").send_keys(str(own))
    wait(browser, lambda b: "file=zf_8hp70_8speed.toml" in b.current_url)
    assert "example=" not in browser.current_url
    settled(browser)
    broken = tmp_path / "broken.rexs"
    broken.write_bytes(b'<?xml version="1.0"?><model applicationId="x" version="1.4"><components><compo')
    browser.find_element(By.ID, "upload").send_keys(str(broken))
    shows(browser, "#results .problem .message", "was not opened")
    assert "# mine" in browser.find_element(By.ID, "toml").get_attribute("value")  # the open file stays
    assert browser.find_element(By.ID, "opform").is_displayed() and browser.find_element(By.ID, "tab-gears")


def test_the_worked_solution_stays_open_across_a_language_switch(browser, server):
    open_example(browser, server, "brandenberger_1952")
    click(browser, "#explain > details > summary")
    wait(browser, lambda b: b.find_element(By.CSS_SELECTOR, "#explain > details").get_attribute("open") is not None)
    Select(browser.find_element(By.ID, "lang")).select_by_value("de")
    shows(browser, "#explain summary", "Deutsch")
    settled(browser)
    assert browser.find_element(By.CSS_SELECTOR, "#explain > details").get_attribute("open") is not None
    severe(browser)
    editor = browser.find_element(By.ID, "toml")  # a bad text: 422 with the message, no console error
    browser.execute_script("arguments[0].value = arguments[0].value.replace('[[planetary]]', '[[planetary]');",
                           editor)
    click(browser, "#solve")
    shows(browser, "#results .problem .message", "line")
    settled(browser)
    assert not severe(browser)
