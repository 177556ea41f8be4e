"""Reports: JSON schema, HTML self-contained, Markdown, notebook display."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from epicyclic import solve
from epicyclic.demo import brandenberger_1952
from epicyclic.io import load_train_file
from epicyclic.io.html_report import html_report
from epicyclic.io.json_report import SCHEMA, json_report, report_dict
from epicyclic.io.tables import fmt, markdown_report, text_report
from epicyclic.units import Units

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def brandenberger():
    f = load_train_file(EXAMPLES / "brandenberger_1952.toml")
    return f, f.solve()


def test_json_schema_keys_are_stable(brandenberger):
    f, s = brandenberger
    report = json.loads(json_report(s, f.units, title=f.title, source="x.toml"))
    assert set(report) == {"schema", "generator", "title", "source", "units", "solution", "ideal"}
    assert report["schema"] == SCHEMA and report["source"] == "x.toml"
    sol = report["solution"]
    assert {"shafts", "elements", "input_power", "output_power", "loss", "efficiency", "self_locking",
            "circulation", "degrees_of_freedom", "warnings", "ratio", "units"} <= set(sol)
    assert set(sol["circulation"]) == {"power", "ratio", "loops", "largest_element_power", "largest_element_ratio",
                                       "indeterminate"}
    assert set(sol["shafts"]["I"]) == {"speed", "torque", "power", "role"}
    planetary = sol["elements"]["planetary"]
    # Brandenberger 1952: with friction M1' = 66.7, M2' = −40.3, M3' = −26.4 cm kg (paper's signs, all
    # speeds negative; ours are opposite). The paper rounds its ratios to 1.49 and 0.284 first, so its
    # torques differ from the exact ones in the last printed digit: tolerance 0.15 kp·cm.
    # Its set has two suns (a and d both external), so the report names systems I and II first and second.
    assert planetary["ports"] == {"first": "I", "second": "II", "carrier": "III"}
    assert planetary["torques"]["first"] == pytest.approx(-66.7, abs=0.15)
    assert planetary["torques"]["second"] == pytest.approx(40.3, abs=0.15)
    assert planetary["torques"]["carrier"] == pytest.approx(26.4, abs=0.15)
    assert report["ideal"]["elements"]["planetary"]["torques"]["first"] == pytest.approx(-78.2, abs=0.25)
    # loss in PS = sum of element losses in PS
    assert sol["loss"] == pytest.approx(sum(e["loss"] for e in sol["elements"].values()))


def test_json_core_units_match_solution_to_dict():
    s = solve(*brandenberger_1952())
    report = report_dict(s)
    assert report["units"] == {"speed": "1/min", "torque": "N*m", "power": "W"}
    assert report["solution"]["shafts"] == s.to_dict()["shafts"]


def test_json_self_locking_has_no_efficiency():
    s = load_train_file(EXAMPLES / "plus_set_self_locking.toml").solve()
    report = report_dict(s)
    assert report["solution"]["efficiency"] is None
    assert report["solution"]["self_locking"]["formal_efficiency"] == pytest.approx(-1.55, abs=0.005)
    json.dumps(report, allow_nan=False)  # valid JSON: no NaN or infinity


def test_html_is_self_contained(brandenberger):
    f, s = brandenberger
    page = html_report(s, f.units, title=f.title, source="b.toml", description="<b>desc</b>")
    assert page.startswith("<!DOCTYPE html>") and page.rstrip().endswith("</html>")
    assert not re.search(r"<link|<script|\bsrc=|\bhref=|url\(|@import", page)
    assert "&lt;b&gt;desc&lt;/b&gt;" in page  # escaped
    assert "<table>" in page and "speed [U/min]" in page and "Worked solution" in page
    assert "M1&#x27;·(n1 − n3)·η0 + M2&#x27;·(n2 − n3) = 0" in page


def test_html_uses_plotting_figures_when_available(monkeypatch, brandenberger):
    import sys
    import types

    f, s = brandenberger
    fake = types.ModuleType("epicyclic.plotting")
    fake.report_figures = lambda solution, **frame: [("Speed plan", "<svg xmlns='http://www.w3.org/2000/svg'></svg>")]
    monkeypatch.setitem(sys.modules, "epicyclic.plotting", fake)
    page = html_report(s, f.units)
    assert "<figcaption>Speed plan</figcaption><svg" in page

    def broken(solution, **frame):
        raise RuntimeError("no ink")

    fake.report_figures = broken
    assert "diagrams could not be drawn (RuntimeError: no ink)" in html_report(s, f.units)
    assert "<figure>" not in html_report(s, f.units, figures=False)


def test_self_locking_banner_in_html():
    s = load_train_file(EXAMPLES / "plus_set_self_locking.toml").solve()
    page = html_report(s, figures=False, explanation=False)
    assert "class='lock'" in page and "Worked solution" not in page


def test_text_and_markdown_reports(brandenberger):
    f, s = brandenberger
    text = text_report(s, f.units)
    assert "torque [kp*cm]" in text and "143.239" in text and "0.8494" in text
    md = markdown_report(s, f.units)
    assert md.startswith("# Brandenberger 1952") and "|:---|" in md


@pytest.mark.parametrize("value, expected", [(None, "—"), (-0.0, "0"), (-1e-300, "-1e-300"), (2739.8412, "2739.84")])
def test_fmt(value, expected):
    assert fmt(value) == expected


def test_notebook_display_is_a_table():
    s = solve(*brandenberger_1952())
    page = s._repr_html_()
    assert "<table>" in page and "<th>shaft</th>" in page and "</table>" in page
    assert Units(power="PS").power == "PS"


@pytest.fixture(scope="module")
def wolfrom():
    f = load_train_file(EXAMPLES / "wolfrom_drive.toml")
    return f, f.solve()


def _row(table: str, element: str) -> str:
    return next(line for line in table.splitlines() if line.startswith(element + " ") or
                line.startswith(f"| {element} |") or line.startswith(f"<td>{element}</td>"))


def test_two_ring_set_reports_name_ports_first_second(wolfrom):
    """A Wolfrom set's port torques are 'first …, second …' in every report; a simple set keeps sun/ring.

    Regression: the Elements table said "sun 223.04, ring -242.96" for the two-ring set W (the solver's port
    names), while the file, the meshes and the forces call its central gears first (81) and second (78).
    """
    f, s = wolfrom
    text = text_report(s, f.units)
    assert "first 223.04, second -242.96, carrier 19.921" in _row(text, "W")
    assert "sun 5, ring 14.921, carrier -19.921" in _row(text, "S")
    assert "first 223.04, second -242.96, carrier 19.921" in markdown_report(s, f.units)
    page = html_report(s, f.units, figures=False)
    assert "first 223.04, second -242.96, carrier 19.921" in page and "sun 223" not in page
    assert "first 223.04" in s.table() and "first 223.04" in s._repr_html_()
    # the solver keeps its own port names; only the presentation changes
    assert set(s.elements["W"].torques) == {"sun", "ring", "carrier"}


def test_two_ring_set_json_ports_first_second(wolfrom):
    f, s = wolfrom
    report = report_dict(s, f.units)
    w = report["solution"]["elements"]["W"]
    assert w["ports"] == {"first": "r1", "second": "out", "carrier": "c"}
    assert set(w["torques"]) == set(w["speeds"]) == {"first", "second", "carrier"}
    assert w["speeds"]["second"] == pytest.approx(3000 / 52, rel=1e-12)
    assert report["solution"]["elements"]["S"]["ports"] == {"sun": "in", "ring": "r1", "carrier": "c"}
    # Lossless statics (Brandenberger 1952: M_b = -i0 M_a) with i0 = z_second z_planet_first / (z_first
    # z_planet_second) = 78·27/(81·24); output torque -52 × 5 N·m (ratio 52 from Willis, see the file).
    ideal = report["ideal"]["elements"]["W"]["torques"]
    assert ideal["second"] == pytest.approx(-78 * 27 / (81 * 24) * ideal["first"], rel=1e-12)
    assert ideal["second"] == pytest.approx(-52 * 5, rel=1e-12)


def test_two_ring_set_explain_names_first_second(wolfrom):
    from epicyclic.explain import explain

    _, s = wolfrom
    text = explain(s).text()
    assert "1 = first central gear 'r1', 2 = second central gear 'out'" in text
    assert "M_W.first" in text and "M_W.second" in text and "M_W.sun" not in text
    assert "1 = sun 'in', 2 = ring 'r1'" in text
    german = explain(s, lang="de").text()
    assert "1 = Sonnenrad 'in', 2 = Hohlrad 'r1'" in german
    assert "1 = erstes Zentralrad 'r1', 2 = zweites Zentralrad 'out'" in german
