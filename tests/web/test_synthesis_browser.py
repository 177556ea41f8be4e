"""The Synthesis tab in headless Chromium: size stated, a search with its progress, Cancel, a candidate opened in
the editor and analysed there (the fixtures and helpers of ``test_browser.py``).

The searches: the Simpson (Ford C4) three-speed the form starts with (about a second), and one with three sets
and three clutches (381 tasks, minutes of fitting) that is cancelled or left.
"""

from __future__ import annotations

import re

from web.test_browser import (APP, browser, click, downloads, open_example, server, settled, shows,  # noqa: F401
                              tab, text_of, wait)

from selenium.webdriver.common.by import By  # noqa: E402  (after the module's skip when chromium is missing)

LONG = {"synth_forward": "2.40, 1.47, 1.0, 0.67", "synth_reverse": "-2.0", "synth_simple": "3", "synth_clutches": "3",
        "synth_engaged": "2"}


def _fill(browser, fields: dict) -> None:
    """Set the form's fields at once; one change: the size is stated again."""
    browser.execute_script("""
        for (const [name, value] of Object.entries(arguments[0])) { document.getElementsByName(name)[0].value = value; }
        document.getElementsByName("synth_top")[0].dispatchEvent(new Event("change", {bubbles: true}));""", fields)


def _done(browser) -> int:
    status = browser.find_elements(By.ID, "synthesis-status")
    return int(status[0].get_attribute("data-done")) if status else -1


def _long_search(browser) -> str:
    """Start the long search and wait until a few of its tasks are done; its progress line."""
    _fill(browser, LONG)
    shows(browser, "#synthesis-estimate", "381 task(s)")
    click(browser, "#synthesis-run")
    wait(browser, lambda b: _done(b) >= 3)
    return text_of(browser, "#synthesis-status")


def test_a_search_runs_and_a_candidate_opens_in_the_editor(browser, server):
    open_example(browser, server, "simpson_c4_3speed")
    tab(browser, "synthesis")
    bound = shows(browser, "#synthesis-estimate", "Before it runs")
    assert "41 mechanisms" in bound and "41 task(s)" in bound  # stated before anything runs
    editor = browser.find_element(By.ID, "toml")
    editor.send_keys("\n# my own note\n")  # the open file has edits that are not saved
    click(browser, "#synthesis-run")
    shows(browser, "#synthesis-result", "candidate(s), best first")
    assert "Pareto" in text_of(browser, "#synthesis-result")
    # issue 30: the candidate table fits its panel (at the window of the tests, 1400 px): nothing to scroll to
    widths = browser.execute_script(
        "var t = document.querySelector('#synthesis-result .synthesis-table table');"
        "var p = document.getElementById('synthesis'); return [t.getBoundingClientRect().width, p.clientWidth];")
    assert widths[0] <= widths[1] + 1, widths
    browser.execute_script("window.asked = []; window.confirm = function (q) { window.asked.push(q); return true; };")
    click(browser, '[data-open-candidate="1"]')
    shows(browser, "#results .title", "candidate 1")
    assert browser.execute_script("return window.asked.length") == 1  # the usual warning came first
    wait(browser, lambda b: b.find_element(By.ID, "ws").get_attribute("data-tab") == "results")
    assert re.fullmatch(r"0\.9\d{3}", text_of(browser, "#efficiency"))  # the normal analysis of the candidate
    source = text_of(browser, "#workspace .source")
    assert re.fullmatch(r"candidate_01-[0-9a-f]{8}\.toml", source)
    assert "candidate 1" in browser.find_element(By.ID, "toml").get_attribute("value")
    # the Synthesis tab kept its candidates; the example's edits are kept in the browser
    tab(browser, "synthesis")
    assert browser.find_elements(By.CSS_SELECTOR, "#synthesis-candidates [data-open-candidate]")
    assert any("# my own note" in (browser.execute_script("return localStorage.getItem(arguments[0])", key) or "")
               for key in browser.execute_script("return Object.keys(localStorage)"))


def test_progress_and_cancel(browser, server):
    open_example(browser, server, "brandenberger_1952")
    tab(browser, "synthesis")
    progress = _long_search(browser)
    assert re.search(r"Searching: \d+/381 tasks \(\d+ %\), \d+ candidate\(s\) so far", progress)
    found = int(re.search(r"(\d+) candidate\(s\) so far", progress).group(1))
    browser.find_element(By.ID, "synthesis-cancel").click()  # not click(): the search is a request in flight
    note = shows(browser, "#synthesis-result", "The search was cancelled")
    assert int(re.search(r"(\d+) candidate\(s\) of the", note).group(1)) >= found  # found so far are kept
    assert not APP[-1].state.searches.running


def test_leaving_the_page_cancels_the_search(browser, server):
    jobs, searches = APP[-1].state.jobs, APP[-1].state.searches
    open_example(browser, server, "brandenberger_1952")
    tab(browser, "synthesis")
    before = jobs.cancelled
    _long_search(browser)
    browser.get(server + "/healthz")  # the page is left: the browser drops the search's request
    wait(browser, lambda _: jobs.cancelled >= before + 1 and not searches.running, timeout=20)
