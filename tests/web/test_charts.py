"""The charts the browser draws (web.charts): the pictures' own data, in the page's units, valid JSON; the
vendored Chart.js; the downloads still the files of ``epicyclic plot``."""

from __future__ import annotations

import hashlib
import html
import json
import re
from importlib import resources
from pathlib import Path

import pytest

from epicyclic.io import loads_train_file
from epicyclic.plotting import figure_subject, speed_chart, torque_diagram
from epicyclic.web import Limits, create_app
from epicyclic.web.cache import AHEAD_KINDS
from epicyclic.web.charts import CHART_KINDS, ahead_kinds, chart_json, chart_specs

from .test_app import textarea

#: sha256 of /usr/share/javascript/chart.js/chart.min.js in Debian's libjs-chart.js 3.9.1+~0.2.1-2 (bookworm)
CHART_JS_SHA256 = "fbc45926e6b46845a0f905552a0e0b1331049bff1115ecf94dbe0904d895e710"
KP_CM = 0.0980665  # N·m per kp·cm (1 kp = 9.80665 N, CGPM 1901)


def _strict(text: str) -> dict:
    """JSON as a browser's JSON.parse reads it: NaN and Infinity are errors."""
    def refuse(constant: str):
        raise AssertionError(f"JSON holds {constant}")

    return json.loads(text, parse_constant=refuse)


def charts_of(page: str) -> dict[str, dict]:
    """Picture name → the chart the page sends for the browser to draw."""
    return {name: _strict(html.unescape(data)) for name, data in
            re.findall(r'data-chart-kind="(\w+)" data-chart="([^"]*)"', page)}


def test_not_finite_values_become_null():
    assert chart_json({"a": float("nan"), "b": [1.0, float("inf")], "c": {"d": -float("inf")}}) == \
        '{"a":null,"b":[1.0,null],"c":{"d":null}}'


def test_the_speed_chart_is_the_pictures_data(examples):
    """Simpson (Ford C4) second gear: output at 1/1.46 of the input (published ratio 1.46)."""
    train_file = loads_train_file(examples["simpson_c4_3speed"].text)
    subject = figure_subject(train_file, "2")
    chart = _strict(chart_specs(subject)["chart"])
    speeds = chart["panels"][0]
    gears = [label[0] for label in speeds["x"]["labels"]]
    assert gears == ["1", "2", "3", "R"] and speeds["highlight"] == 1
    series = {s["name"].split(" (")[0]: s["values"] for s in speeds["series"]}
    assert series["out"][1] == pytest.approx(1 / 1.46, rel=0.005)
    data = speed_chart(subject.transmission, gear="2")
    for shaft, row in data.speeds.items():
        assert series[shaft] == [row[g] for g in gears]  # the picture's own numbers
    slips = {s["name"]: s["values"] for s in chart["panels"][1]["series"]}
    assert all(slips[e][gears.index(g)] == v for e, row in data.slips.items() for g, v in row.items())
    assert speeds["y"]["title"] == "speed per input speed n / n_in"


def test_torques_are_in_the_files_units(examples):
    """Brandenberger's example is in kp·cm: so are the torque bars, the library's N·m converted."""
    train_file = loads_train_file(examples["brandenberger_1952"].text)
    subject = figure_subject(train_file)
    chart = _strict(chart_specs(subject)["torque"])
    bars = [b for panel in chart["panels"] for b in panel["bars"]]
    expected = torque_diagram(subject.solution).bars
    assert [b["actual"] for b in bars] == pytest.approx([b.actual / KP_CM for b in expected], rel=1e-9)
    assert chart["panels"][0]["y"]["title"] == "torque M in kp·cm"
    assert bars[1]["actual"] == pytest.approx(143.2, abs=0.05)  # shaft II, as the picture labels it


def test_powers_rectangles_and_the_loss(examples):
    """Powers as areas: the loss rectangle's power is the set's loss (Brandenberger Bild 8/9)."""
    train_file = loads_train_file(examples["brandenberger_1952"].text)
    subject = figure_subject(train_file)
    chart = _strict(chart_specs(subject)["power"])
    panel = chart["panels"][0]
    loss = [r for r in panel["rects"] if r["role"] == "loss" and r["friction"]]
    assert len(loss) == 1 and loss[0]["power"] == "0.2362 PS"  # the loss of the picture's title, in PS
    assert all(r["x0"] <= r["x1"] and r["y0"] <= r["y1"] for r in panel["rects"])
    assert panel["x"]["title"] == "speed n in U/min (rectangle width)"


def test_speed_plans_of_every_set(examples):
    train_file = loads_train_file(examples["zf_8hp70_8speed"].text)
    chart = _strict(chart_specs(figure_subject(train_file))["speed"])
    assert [p["title"][0] for p in chart["panels"]] == [f"Speed plan (Kutzbach) of set '{n}'" for n in
                                                        ("P1", "P2", "P3", "P4")]
    for panel in chart["panels"]:  # every line starts at the axis of the set or on a planet
        members = [s for s in panel["series"] if s.get("width") == 2]
        assert len(members) == 3 and all(s["points"][0] == [0.0, 0.0] for s in members)


def test_the_page_sends_the_charts_and_draws_the_other_pictures(client):
    page = client.post("/example", data={"example": "zf_8hp70_8speed"}).text
    assert sorted(charts_of(page)) == sorted(CHART_KINDS)
    for name in ("lever", "flow", "animation"):  # still drawn by the server when shown
        assert f'hx-post="/figure/{name}" hx-trigger="intersect once"' in page
    for name in CHART_KINDS:  # the picture of `epicyclic plot` on request, and in the downloads
        assert f'hx-post="/figure/{name}" hx-include="#ws" hx-target="#fig-{name} .fig-picture"' in page
        assert f'data-download="/save/{name}"' in page


def test_a_gear_change_sends_that_gears_charts(client, examples, page_form):
    text = examples["simpson_c4_3speed"].text
    rows = [("in", "drive", "1000 1/min", "torque", "100 N*m"), ("out", "load", "", "torque", "")]
    first = charts_of(client.post("/apply/form", data=page_form(text, *rows, gear="1")).text)
    second = charts_of(client.post("/apply/form", data=page_form(text, *rows, gear="2")).text)
    assert (first["chart"]["panels"][0]["highlight"], second["chart"]["panels"][0]["highlight"]) == (0, 1)
    out = [b["actual"] for b in second["torque"]["panels"][0]["bars"] if b["label"] == ["out"]][0]
    train_file = loads_train_file(textarea(client.post("/apply/form", data=page_form(text, *rows, gear="2")).text))
    assert out == pytest.approx(figure_subject(train_file, "2").solution.shafts["out"].torque)  # gear 2's own
    assert -out / 100 == pytest.approx(1.46, rel=0.03)  # about the ratio 1.46 times the input torque (η < 1)
    assert "gear 2: " in second["torque"]["title"]


def test_without_browser_charts_the_server_draws_every_picture():
    from starlette.testclient import TestClient

    assert ahead_kinds(True) == ("lever", "flow") and ahead_kinds(False) == AHEAD_KINDS
    with TestClient(create_app(Limits(workers=1, browser_charts=False))) as client:
        page = client.post("/example", data={"example": "zf_8hp70_8speed"}).text
        assert "data-chart" not in page and page.count('hx-trigger="intersect once" hx-include="#ws"') == 7
        assert client.app.state.cache.kinds == AHEAD_KINDS


def test_chart_js_is_debians_file_with_its_licence(client):
    js = client.get("/static/chart.min.js")
    assert js.status_code == 200 and hashlib.sha256(js.content).hexdigest() == CHART_JS_SHA256
    assert js.content.startswith(b"/*!\n * Chart.js v3.9.1")
    static = resources.files("epicyclic.web").joinpath("static")
    assert static.joinpath("chart.LICENSE").read_text().startswith("The MIT License")
    notice = static.joinpath("chart.NOTICE").read_text()
    assert "libjs-chart.js" in notice and "3.9.1+~0.2.1-2" in notice and CHART_JS_SHA256 in notice
    page = client.get("/").text
    assert '<script src="/static/chart.min.js" defer></script>' in page and "<script>" not in page
    assert client.get("/static/charts.js").status_code == 200


def _cli_plot(path: Path, kind: str, out: Path, *options: str) -> bytes:
    from typer.testing import CliRunner

    from epicyclic.cli.main import app

    result = CliRunner().invoke(app, ["plot", str(path), "--kind", kind, "--out", str(out), *options])
    assert result.exit_code == 0, result.output
    return out.read_bytes()


def _undated(svg: bytes) -> bytes:
    return re.sub(rb"<dc:date>[^<]*</dc:date>", b"", svg)


@pytest.mark.parametrize("key, kind, format", [("brandenberger_1952", "torque", "png"),
                                               ("simpson_c4_3speed", "chart", "svg")])
def test_downloads_are_the_files_of_epicyclic_plot(client, examples, page_form, tmp_path, key, kind, format):
    """A chart the browser draws is saved as `epicyclic plot` writes the picture (PNG byte for byte; SVG
    but for its date)."""
    path = tmp_path / f"{key}.toml"
    path.write_text(examples[key].text, encoding="utf-8")
    saved = client.post(f"/save/{kind}", data={**page_form(examples[key].text, source=path.name),
                                              f"fig_{kind}_format": format, f"fig_{kind}_dpi": "40"})
    assert saved.status_code == 200
    written = _cli_plot(path, kind, tmp_path / f"cli.{format}", "--dpi", "40")
    assert _undated(saved.content) == _undated(written)


def test_a_hostile_name_is_text_in_the_charts(client, page_form):
    """A set named with markup reaches the browser's charts as the same text (drawn on a canvas or set as
    textContent, never parsed as HTML), and the page around it stays inert (test_hostile)."""
    from .test_hostile import assert_inert, hostile

    payload = '"><img src=x onerror=alert(1)>'
    answer = client.post("/apply/text", data=page_form(hostile(set_name=payload)))
    assert answer.status_code == 200
    assert_inert(answer.text)
    titles = [p["title"] for p in charts_of(answer.text)["torque"]["panels"]]
    assert f"torques on {payload}" in titles
