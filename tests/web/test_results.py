"""What the page says about a solved state: power state, held drives and loads, circulating power, solver errors.

The numbers are the library's (tested against published cases in tests/solver
and tests/results); these tests check that the page shows them in the reader's
units, says "no power flows" and "not defined" where that is the truth, and
puts solver-stage errors at the file's ``[operating_point]``.
"""

from __future__ import annotations

import re

import pytest

from epicyclic.io import loads_train_file
from epicyclic.io.tables import fmt
from epicyclic.plotting import figure_subject

from .test_app import kpi, textarea

SIMPLE = """title = "simple set"
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
teeth = { sun = 30, planet = 24, ring = 78 }
stationary_efficiency = 0.98
[[brake]]
name = "B"
shaft = "ring"
[operating_point]
speeds = { in = 3000 }
torques = { in = 10 }
drives = ["in"]
loads = ["out"]
"""


def state_of(html: str) -> str:
    match = re.search(r'id="self-locking" data-state="([^"]+)"', html)
    assert match, "no power state in the answer"
    return match.group(1)


def marked_line(html: str) -> int | None:
    """The line the editor marks (the out-of-band editor status)."""
    match = re.search(r'id="editor-status" class="editor-status" data-line="(\d*)"', html)
    assert match, "no editor status in the answer"
    return int(match.group(1)) if match.group(1) else None


def test_power_flowing_is_said_only_when_it_flows(client, page_form):
    answer = client.post("/apply/text", data=page_form(SIMPLE))
    assert answer.status_code == 200 and state_of(answer.text) == "flows"
    assert "power flows from the drive to the load as asked" in answer.text


def test_no_power_flows_at_a_standstill(client, page_form):
    """Input held at speed 0 with a torque: every shaft stands still, nothing flows, both ends take reactions."""
    text = SIMPLE.replace("speeds = { in = 3000 }", "speeds = { in = 0 }")
    solution = loads_train_file(text).solve()
    assert solution.input_power == solution.output_power == 0.0
    answer = client.post("/apply/text", data=page_form(text))
    assert answer.status_code == 200 and state_of(answer.text) == "none"
    assert "power flows from" not in answer.text and "No power flows through the train" in answer.text
    assert kpi(answer.text, "efficiency") == "—"
    for shaft in ("in", "out"):  # 10 N·m at the input, 10 (1 + 78/30) = 36 N·m at the held carrier (Willis)
        torque = fmt(abs(solution.torque(shaft)), 6)
        assert f"&#39;{shaft}&#39; is a {solution.shafts[shaft].role} but the train holds it still (speed 0): " \
               f"it takes {torque} N*m as a reaction torque" in answer.text
    assert abs(solution.torque("out")) == pytest.approx(36.0)
    shown = answer.text.split('id="explain"')[0]  # the worked solution has its own words
    assert shown.count("holds it still") == 2  # the solver's warnings are not repeated below


def test_a_held_load_takes_a_reaction_torque_in_the_files_units(client, examples, page_form):
    """Power split with the wheels (ring) held: the engine's power all goes to the generator."""
    text = examples["three_shaft_power_split"].text.replace("output = 1500", "output = 0")
    text = text.replace('torque = "N*m"', 'torque = "kp*m"')
    solution = loads_train_file(text).solve()
    answer = client.post("/apply/text", data=page_form(text))
    assert answer.status_code == 200 and state_of(answer.text) == "flows"
    kp_m = abs(solution.torque("output")) / 9.80665  # 1 kp·m = 9.80665 N·m
    assert f"it takes {fmt(kp_m, 6)} kp*m as a reaction torque, not power" in answer.text
    si = client.post("/apply/text", data=page_form(text, units="si"))
    assert f"it takes {fmt(abs(solution.torque('output')), 6)} N*m as a reaction torque" in si.text


def test_circulating_power_per_loop(client, examples, page_form):
    """ZF 8HP third gear (B + C + E): power circulates round r2s3 → E → r3s4 → C → in → P2."""
    text = examples["zf_8hp70_8speed"].text
    rows = [("in", "drive", "1", "torque", "1"), ("out", "load", "", "torque", "")]
    answer = client.post("/apply/form", data=page_form(text, *rows, gear="3"))
    assert answer.status_code == 200
    circulation = figure_subject(loads_train_file(textarea(answer.text)), "3").solution.circulation
    assert circulation.loops and circulation.ratio == pytest.approx(figure_subject(
        loads_train_file(text), "3").solution.circulation.ratio)
    assert kpi(answer.text, "circulating") == f"{fmt(circulation.ratio, 4)} × input"
    for loop in circulation.loops:
        row = f'<td class="text">{loop.describe()}</td><td>{fmt(loop.power, 6)} W</td><td>{fmt(loop.ratio, 4)}</td>'
        assert row in answer.text
    assert "power circulates:" not in answer.text.split('id="explain"')[0]  # shown as loops, not as a warning


def test_circulating_power_is_not_defined_where_the_split_is_indeterminate(client, page_form):
    """Two engaged clutches between the same shafts leave their torque split open (tests/results)."""
    text = """title = "parallel clutches"
[[planetary]]
name = "P"
sun = "a"
ring = "ring"
carrier = "b"
stationary_ratio = -2
stationary_efficiency = 0.98
[[clutch]]
name = "C1"
first = "a"
second = "x"
[[clutch]]
name = "C2"
first = "a"
second = "x"
[[gear]]
name = "G"
first = "ring"
second = "x"
ratio = 1.5
efficiency = 0.98
[operating_point]
speeds = { x = 1000 }
torques = { x = 10 }
drives = ["x"]
loads = ["b"]
"""
    assert loads_train_file(text).solve().circulation.indeterminate == ("C1", "C2")
    answer = client.post("/apply/text", data=page_form(text))
    assert answer.status_code == 200
    assert kpi(answer.text, "circulating") == "not defined"
    assert "Not defined: the torque split of &#39;C1&#39;, &#39;C2&#39; is statically indeterminate" in answer.text


@pytest.mark.parametrize("speed, torque, units, says", [
    ("1e300", "1e300", "", "big.toml: [operating_point]: the power of shaft &#39;in&#39; is not a finite number"),
    # 1e299 W solves, but is 1e311 pW in the file's units: the report's check names the result
    ("1e150", "1e149", '[units]\npower = "pW"\n', "big.toml: result &#39;solution.shafts.in.power&#39; is inf"),
])
def test_a_result_that_overflows_is_an_error_at_the_operating_point(client, page_form, speed, torque, units, says):
    text = SIMPLE.replace("speeds = { in = 3000 }", f"speeds = {{ in = {speed} }}").replace(
        "torques = { in = 10 }", f"torques = {{ in = {torque} }}") + units
    answer = client.post("/apply/text", data=page_form(text, source="big.toml"))
    assert answer.status_code == 422
    assert says in answer.text and "not a finite number" in answer.text
    assert marked_line(answer.text) == text.splitlines().index("[operating_point]") + 1
    for kind in ("speed", "animation"):  # the pictures say the same, nothing is drawn from infinities
        picture = client.post(f"/figure/{kind}", data=page_form(text, source="big.toml"))
        assert picture.status_code == 422 and says in picture.text


def test_a_nearly_singular_train_is_an_error_at_the_operating_point(client, page_form):
    """A loop whose ratios nearly cancel: a stage 2e-12 from the set's own ratio (issue 13)."""
    text = SIMPLE.replace("teeth = { sun = 30, planet = 24, ring = 78 }", "stationary_ratio = -2").replace(
        '[[brake]]\nname = "B"\nshaft = "ring"\n',
        '[[gear]]\nname = "G"\nfirst = "in"\nsecond = "ring"\nratio = -2.000000000004\n').replace(
        'speeds = { in = 3000 }\ntorques = { in = 10 }\ndrives = ["in"]\nloads = ["out"]',
        'speeds = { out = 3000 }\ntorques = { out = 10 }\ndrives = ["out"]\nloads = ["ring"]')
    answer = client.post("/apply/text", data=page_form(text, source="near.toml"))
    assert answer.status_code == 422
    assert "near.toml: [operating_point]" in answer.text and "nearly cancelling ratios" in answer.text
    line = marked_line(answer.text)
    assert line is not None and line >= text.splitlines().index("[operating_point]") + 1


def test_a_failing_gear_is_named_and_marked_at_its_schedule_line(client, page_form):
    text = """title = "two speeds"
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
teeth = { sun = 30, planet = 24, ring = 78 }
[[brake]]
name = "B"
shaft = "ring"
[[clutch]]
name = "C"
first = "in"
second = "ring"
[transmission]
input = "in"
output = "out"
[transmission.schedule]
"1" = ["B"]
"2" = []
"""
    answer = client.post("/apply/text", data=page_form(text, source="t.toml"))
    assert answer.status_code == 422
    assert "t.toml: [transmission], key &#39;schedule.2&#39;" in answer.text
    assert marked_line(answer.text) == text.splitlines().index('"2" = []') + 1


def test_the_default_point_notice_is_said_once_in_the_results_tab(client):
    """Issue 30: the notice of the default operating point was above the tabs and so repeated in every tab;
    it is in the Results tab (the pictures say it in their titles, the gear table its input level)."""
    answer = client.post("/example", data={"example": "zf_8hp70_8speed"}).text
    assert answer.count('id="default-point"') == 1
    results = answer.split('data-panel="results"', 1)[1].split('data-panel="gears"', 1)[0]
    assert 'id="default-point"' in results
