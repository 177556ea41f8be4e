"""Browser tests of the charts the browser draws (web.charts, static/charts.js) in Debian's headless chromium:
drawn with their data points, the value under the pointer, zoom, a gear change, nothing drawn or asked for
in a hidden tab.  The fixtures and helpers are those of ``test_browser.py`` (skipped without chromium)."""

from __future__ import annotations

import pytest

from .test_browser import browser, click, downloads, open_example, server, settled, shot, tab, wait  # noqa: F401

from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402

from epicyclic.io import loads_train_file  # noqa: E402
from epicyclic.plotting import figure_subject, speed_chart  # noqa: E402
from epicyclic.web.examples import bundled_examples  # noqa: E402

#: The Chart.js chart of a picture's first canvas (``kind``, panel ``index``), read in the page.
CHART = "var c = document.querySelectorAll('#fig-' + arguments[0] + ' .chart-body canvas')[arguments[1]];" \
        "var chart = c && Chart.getChart(c);"
#: Requests of the page so far for pictures (the server's /figure/<kind>).
ASKED = ("return performance.getEntriesByType('resource').map(e => new URL(e.name).pathname)"
         ".filter(p => p.startsWith('/figure/'));")


def drawn(browser, kind: str) -> None:
    """Scroll picture ``kind`` into view and wait until its chart is drawn (a chart is drawn once on screen)."""
    browser.execute_script("document.getElementById('fig-' + arguments[0]).scrollIntoView()", kind)
    wait(browser, lambda b: b.find_elements(By.CSS_SELECTOR, f"#fig-{kind} .chart-body[data-drawn] canvas"))


def hover(browser, kind: str, index: int, dataset: int, point: int) -> list[str]:
    """Move the pointer onto data point ``point`` of ``dataset`` of panel ``index``; the tooltip's lines."""
    canvas = browser.find_elements(By.CSS_SELECTOR, f"#fig-{kind} .chart-body canvas")[index]
    browser.execute_script("arguments[0].scrollIntoView({block: 'center'})", canvas)
    x, y = browser.execute_script(CHART + "var p = chart.getDatasetMeta(arguments[2]).data[arguments[3]];"
                                  "return [p.x, p.y];", kind, index, dataset, point)
    size = canvas.size
    ActionChains(browser).move_to_element_with_offset(canvas, int(x - size["width"] / 2),
                                                      int(y - size["height"] / 2)).perform()
    return wait(browser, lambda b: b.execute_script(
        CHART + "return chart.tooltip.getActiveElements().length ? "
        "chart.tooltip.body.map(b => b.lines).flat() : null;", kind, index, 0, 0))


def test_charts_are_drawn_when_shown_with_values_under_the_pointer(browser, server):
    """Simpson (Ford C4): nothing asked for or drawn in the hidden Pictures tab; shown, the speed chart has a
    point per gear and shaft, the value under the pointer is the library's; a gear change draws the new gear."""
    key = "simpson_c4_3speed"
    open_example(browser, server, key)
    settled(browser)
    assert browser.execute_script(ASKED) == []  # no picture asked for while the Pictures tab is hidden
    assert not browser.find_elements(By.CSS_SELECTOR, ".chart-body[data-drawn], .fig-body svg")
    tab(browser, "pictures")
    drawn(browser, "chart")
    settled(browser)
    asked = set(browser.execute_script(ASKED))  # the pictures the server draws, as they come on screen
    assert "/figure/animation" in asked and asked <= {"/figure/animation", "/figure/lever", "/figure/flow"}, asked
    points = browser.execute_script(CHART + "return chart.data.datasets.map(d => [d.label, d.data]);", "chart", 0)
    transmission = figure_subject(loads_train_file(bundled_examples()[key].text)).transmission
    expected = speed_chart(transmission).speeds
    assert {label.split(" (")[0]: values for label, values in points} == \
        {shaft: [row[g] for g in ("1", "2", "3", "R")] for shaft, row in expected.items()}
    out = [k for k, (label, _) in enumerate(points) if label == "out (output)"][0]
    lines = hover(browser, "chart", 0, out, 1)  # the output shaft in gear 2
    assert "out (output): 0.6857 × n_in" in lines, lines  # 1 / 1.4583 (Ford C4 second gear, published 1.46)
    shot(browser, "9-charts")
    fonts = browser.execute_script(  # every text of every chart drawn at 11 px or more
        "return Array.from(document.querySelectorAll('.chart-body canvas')).map(c => Chart.getChart(c))"
        ".filter(c => c).flatMap(c => [c.options.plugins.title.font.size, c.options.plugins.legend.labels.font.size,"
        " ...Object.values(c.scales).flatMap(s => [s.options.ticks.font.size, s.options.title.font.size])]);")
    assert len(fonts) > 20 and min(fonts) >= 11, fonts
    # zoom: a box dragged across the middle of the torque panel narrows its axis; a double-click zooms out
    drawn(browser, "torque")
    canvas = browser.find_elements(By.CSS_SELECTOR, "#fig-torque .chart-body canvas")[0]
    browser.execute_script("arguments[0].scrollIntoView({block: 'center'})", canvas)
    before = browser.execute_script(CHART + "return [chart.scales.y.min, chart.scales.y.max];", "torque", 0)
    ActionChains(browser).move_to_element_with_offset(canvas, -40, -60).click_and_hold().move_by_offset(80, 60) \
        .release().perform()
    def y_range(b):
        return b.execute_script(CHART + "return [chart.scales.y.min, chart.scales.y.max];", "torque", 0)

    wait(browser, lambda b: y_range(b)[1] - y_range(b)[0] < 0.7 * (before[1] - before[0]))  # (events: next frame)
    ActionChains(browser).double_click(canvas).perform()
    wait(browser, lambda b: y_range(b) == before)
    # a gear change: the charts of gear 2 (the gear highlighted, its torques)
    torques = browser.execute_script(CHART + "return chart.data.datasets.at(-1).data;", "torque", 0)
    click(browser, '.gear-strip button[data-gear="2"]')
    wait(browser, lambda b: "gear 2" in b.find_element(By.CSS_SELECTOR, "#results .title").text)
    drawn(browser, "torque")
    wait(browser, lambda b: b.execute_script(CHART + "return chart && chart.options.plugins.band.index;",
                                             "chart", 0) == 1)
    assert browser.execute_script(CHART + "return chart.data.datasets.at(-1).data;", "torque", 0) != torques
    errors = [e for e in browser.get_log("browser") if e["level"] == "SEVERE" and "favicon.ico" not in e["message"]]
    assert not errors, errors


def test_the_power_chart_names_the_rectangle_under_the_pointer(browser, server):
    open_example(browser, server, "brandenberger_1952", "&tab=pictures")
    drawn(browser, "power")
    rects = browser.execute_script(CHART + "return chart.data.datasets.at(-1).rects;", "power", 0)
    loss = [k for k, r in enumerate(rects) if r["role"] == "loss"][0]
    lines = hover(browser, "power", 0, len(browser.execute_script(CHART + "return chart.data.datasets;", "power",
                                                                    0)) - 1, loss)
    assert any(line.startswith("loss: ΔM_ring") and "0.2362 PS" in line for line in lines), lines
    click(browser, "#fig-power [data-enlarge]")  # at the window's width
    wait(browser, lambda b: b.find_elements(By.CSS_SELECTOR, "#zoom canvas"))
    assert browser.find_element(By.CSS_SELECTOR, "#zoom canvas").size["width"] > 600
    click(browser, "#zoom button")


@pytest.mark.parametrize("kind", ["torque"])
def test_the_picture_of_a_chart_comes_on_request(browser, server, kind):
    open_example(browser, server, "brandenberger_1952", "&tab=pictures")
    drawn(browser, kind)
    assert not browser.find_elements(By.CSS_SELECTOR, f"#fig-{kind} .fig-picture svg")
    click(browser, f"#fig-{kind} .chart-hint button")
    wait(browser, lambda b: b.find_elements(By.CSS_SELECTOR, f"#fig-{kind} .fig-picture svg"))
