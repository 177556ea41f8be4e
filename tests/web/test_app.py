"""API tests of ``epicyclic serve`` with Starlette's test client: every route, every bundled example."""

from __future__ import annotations

import json
import re

import pytest

from epicyclic.io import loads_train_file
from epicyclic.io.tables import fmt
from epicyclic.plotting import figure_subject
from epicyclic.web.examples import bundled_examples
from epicyclic.web.figures import FIGURES

EXAMPLES = sorted(bundled_examples())


def kpi(html: str, name: str) -> str:
    """The text of the results' key figure ``name`` (id in the page)."""
    match = re.search(rf'id="{name}">([^<]*)<', html)
    assert match, f"no {name} in the answer"
    return match.group(1)


def textarea(html: str) -> str:
    """The editor's text in an answer (the out-of-band textarea), unescaped."""
    import html as html_module

    match = re.search(r'<textarea id="toml"[^>]*>\n(.*?)</textarea>', html, re.S)
    assert match, "no textarea in the answer"
    return html_module.unescape(match.group(1))


# ---------------------------------------------------------------------- the page
def test_page_lists_every_example_and_sets_safe_headers(client, examples):
    page = client.get("/")
    assert page.status_code == 200
    for example in examples.values():
        assert f'value="{example.key}"' in page.text
    csp = page.headers["content-security-policy"]
    assert "script-src 'self'" in csp and "unsafe-eval" not in csp and "default-src 'none'" in csp
    assert page.headers["x-content-type-options"] == "nosniff"
    assert '"allowEval": false' in page.text  # htmx evaluates no expressions from attributes
    assert "<script>" not in page.text  # scripts come from files only (CSP)


def test_static_files_are_served_and_htmx_is_the_registry_file(client):
    import hashlib
    from importlib import resources

    js = client.get("/static/htmx.min.js")
    assert js.status_code == 200 and js.headers["content-type"].startswith("text/javascript")
    # sha256 of dist/htmx.min.js in the npm registry's tarball htmx.org@2.0.11 (npm pack htmx.org@2.0.11)
    assert hashlib.sha256(js.content).hexdigest() == "d6fdc75f204e6bdefa99b69bf1e6d4ac69b8a364f77929f45c13476b4000f717"
    assert resources.files("epicyclic.web").joinpath("static", "htmx.LICENSE").read_text().startswith("Zero-Clause BSD")
    assert client.get("/static/app.js").status_code == 200
    assert client.get("/static/../app.py").status_code == 404


@pytest.mark.parametrize("key", EXAMPLES)
def test_every_bundled_example_opens(client, examples, key):
    answer = client.post("/example", data={"example": key})
    assert answer.status_code == 200, answer.text[:500]
    example = examples[key]
    train_file = loads_train_file(example.train_text())
    assert f'value="{example.file_name}"' in answer.text  # the source shown and sent back
    for shaft in train_file.train.moving_shafts:
        assert f'data-shaft="{shaft}"' in answer.text  # one form row per shaft
    # the state `epicyclic plot` draws: the file's operating point, or a transmission's first gear at the default
    solution = figure_subject(train_file).solution
    expected = "— (self-locking)" if solution.self_locking else fmt(solution.efficiency, 4)
    assert kpi(answer.text, "efficiency") == expected
    assert textarea(answer.text) == example.train_text()  # opening never changes the text
    if train_file.operating_point is None:
        assert "at the default operating point" in answer.text


def test_unknown_example_is_not_a_path(client):
    for name in ("../../../etc/passwd", "/etc/passwd", "brandenberger_1952.toml", "nope"):
        answer = client.post("/example", data={"example": name})
        assert answer.status_code == 404
        assert "no bundled example" in answer.text and "root:" not in answer.text


# ---------------------------------------------------------------------- solving
def test_brandenberger_efficiency_as_published(client, examples, page_form):
    """Brandenberger 1952, Beispiel to Bild 10: η' = 0.85 (two digits), output 2.55 PS."""
    answer = client.post("/apply/text", data=page_form(examples["brandenberger_1952"].text))
    assert answer.status_code == 200
    assert abs(float(kpi(answer.text, "efficiency")) - 0.85) < 0.005
    assert abs(float(kpi(answer.text, "output-power").split()[0]) - 2.55) < 0.01
    assert 'id="self-locking"' in answer.text and "Not self-locking" in answer.text
    for element in ("planetary", "stage"):  # loss per element in the elements table
        assert f"<td>{element}</td>" in answer.text
    assert "textarea" not in answer.text  # a text change does not send the text back
    assert 'id="opform" class="panel opform"' in answer.text and 'hx-swap-oob="true"' in answer.text


def test_changing_a_speed_in_the_form_changes_efficiency_and_rewrites_the_text(client, examples, page_form):
    """Three-shaft power split (two degrees of freedom): the output speed moves the power split."""
    text = examples["three_shaft_power_split"].text
    shafts = [("engine", "drive", "2000", "torque", "100"), ("output", "load", "1500", "torque", ""),
              ("generator", "load", "", "torque", "")]
    first = client.post("/apply/form", data=page_form(text, *shafts))
    shafts[1] = ("output", "load", "500", "torque", "")
    second = client.post("/apply/form", data=page_form(text, *shafts))
    assert first.status_code == second.status_code == 200
    eta1, eta2 = float(kpi(first.text, "efficiency")), float(kpi(second.text, "efficiency"))
    expected = loads_train_file(text.replace("output = 1500", "output = 500")).solve().efficiency
    assert eta1 != eta2 and eta2 == pytest.approx(expected, abs=5e-5)
    rewritten = textarea(second.text)
    assert "speeds = {engine = 2000, output = 500}" in rewritten
    assert "# " in rewritten  # the file's comments survive
    assert loads_train_file(rewritten).solve().efficiency == pytest.approx(expected)


def test_switching_gears(client, examples, page_form):
    """Ford C4 (Simpson): published ratios 2.46, 1.46, 1.00, reverse 2.18 (rounded to two digits); the text gets
    the form's operating point but never the gear shown."""
    opened = client.post("/example", data={"example": "simpson_c4_3speed"})
    text = textarea(opened.text)
    shafts = [("in", "drive", "1000 1/min", "torque", "100 N*m"), ("out", "load", "", "torque", "")]
    for gear, ratio in (("1", 2.46), ("2", 1.46), ("3", 1.00), ("R", -2.18)):
        answer = client.post("/apply/form", data=page_form(text, *shafts, gear=gear))
        assert answer.status_code == 200, answer.text[:400]
        assert float(kpi(answer.text, "ratio")) == pytest.approx(ratio, abs=0.01)
        assert f'<tr data-gear="{gear}" class="current"' in answer.text
        assert "gear =" not in textarea(answer.text)  # the gear shown is the page's view, not an edit (issue 30)
        assert 'id="gear-state"' in answer.text and f"gear {gear} (" in answer.text


def test_a_click_on_a_gear_leaves_the_text_as_it_is(client, examples, page_form):
    """Issue 30: choosing a gear (the form unchanged otherwise) solves in it without writing ``gear = "5"`` or
    the default operating point into the text, so the file is not edited (no leave warning)."""
    from epicyclic.web.state import default_operating_rows

    text = examples["zf_8hp70_8speed"].text
    spec = loads_train_file(text).transmission
    rows = [(r.shaft, r.role, r.speed, r.moment, r.value) for r in
            default_operating_rows(loads_train_file(text).train.moving_shafts, spec.input, spec.output)]
    answer = client.post("/apply/form", data=page_form(text, *rows, gear="5"))
    assert answer.status_code == 200, answer.text[:400]
    assert '<tr data-gear="5" class="current"' in answer.text
    assert '<textarea id="toml"' not in answer.text  # the text is not swapped: it is as it was
    expected = figure_subject(loads_train_file(text), "5").solution.ratio
    assert float(kpi(answer.text, "ratio")) == pytest.approx(expected, abs=1e-3)
    assert '<option value="5" selected>' in client.post("/apply/text", data=page_form(text, gear="5")).text


def test_units_and_language(client, examples, page_form):
    text = examples["brandenberger_1952"].text
    file_units = client.post("/apply/text", data=page_form(text)).text
    si = client.post("/apply/text", data=page_form(text, units="si", lang="de")).text
    assert "speed [U/min]" in file_units and "torque [kp*cm]" in file_units
    assert "speed [1/min]" in si and "torque [N*m]" in si and "power [W]" in si
    assert "Wirkungsgrad" in si and "Wirkungsgrad" not in file_units


def test_self_locking_shows_thresholds(client, examples, page_form):
    answer = client.post("/apply/text", data=page_form(examples["plus_set_self_locking"].text))
    solution = loads_train_file(examples["plus_set_self_locking"].text).solve()
    assert solution.self_locking is not None
    assert "Self-locking:</strong>" in answer.text and kpi(answer.text, "efficiency") == "— (self-locking)"
    for name, eta in solution.self_locking.thresholds.items():
        assert f"{name}: self-locks for η0 &lt; {fmt(eta, 6)}" in answer.text


# ---------------------------------------------------------------------- pictures, forms, downloads
#: An example each picture applies to (the speed chart needs a transmission).
PICTURE_OF = {kind: "simpson_c4_3speed" if kind == "chart" else "brandenberger_1952" for kind in FIGURES}


@pytest.mark.parametrize("kind", list(FIGURES))
def test_every_picture_is_inline_svg(client, examples, page_form, kind):
    answer = client.post(f"/figure/{kind}", data=page_form(examples[PICTURE_OF[kind]].text))
    assert answer.status_code == 200, answer.text[:300]
    assert "<svg" in answer.text and "<script" not in answer.text
    if kind == "animation":
        assert "<animateTransform" in answer.text


def test_animation_options(client, examples, page_form):
    """A set at its speeds, the same set in the Willis phases (tec-science), an unknown set is a message."""
    data = page_form(examples["simple_set_ring_held_sun_drives"].text)
    plain = client.post("/figure/animation", data={**data, "fig_animation_option": "P"})
    willis = client.post("/figure/animation", data={**data, "fig_animation_option": "P|willis"})
    assert plain.status_code == willis.status_code == 200
    assert "carrier turns" not in plain.text and "carrier turns" in willis.text
    unknown = client.post("/figure/animation", data={**data, "fig_animation_option": "Q"})
    assert unknown.status_code == 422 and "Q" in unknown.text


def test_unknown_picture(client, examples, page_form):
    answer = client.post("/figure/../../etc", data=page_form(examples["brandenberger_1952"].text))
    assert answer.status_code == 404


def test_geometry_forms(client, examples, page_form):
    text = examples["simple_set_ring_held_sun_drives"].text
    fit = client.post("/tool/fit", data=page_form(text, tool_fit_set="P", tool_fit_module="2"))
    assert fit.status_code == 200 and "coaxiality" in fit.text and "assembly" in fit.text
    forces = client.post("/tool/forces", data=page_form(text, tool_forces_set="P"))
    assert forces.status_code == 200 and "<table" in forces.text
    search = client.post("/tool/search", data=page_form(text, tool_search_ratio="4", tool_search_tolerance="0",
                                                         tool_search_sun="14..30", tool_search_planet="14..30",
                                                         tool_search_planets="3..4"))
    # search_teeth's own example: 4.0 exactly with 14..30 teeth starts with (21, 21, 63) at 3 and 4 planets
    assert search.status_code == 200
    assert search.text.split("-----\n", 1)[1].split()[:4] == ["21", "21", "63", "3"]


@pytest.mark.parametrize("field, value, message", [
    ("tool_fit_module", "abc", "expected a number"),
    ("tool_fit_module", "-1", "expected a number from 0.05 to 100"),
    ("tool_fit_set", "nope", "expected one of &#39;P&#39;"),
    ("tool_fit_x_planet", "0,0,0,0,0,0,0,0,0,0,0,0,0", "expected 1 to 12"),
])
def test_geometry_form_errors(client, examples, page_form, field, value, message):
    text = examples["simple_set_ring_held_sun_drives"].text
    answer = client.post("/tool/fit", data=page_form(text, **{field: value}))
    assert answer.status_code == 422 and message in answer.text


def test_downloads(client, examples, page_form):
    text = examples["brandenberger_1952"].text
    data = page_form(text, source="brandenberger_1952.toml")
    report = client.post("/download/json", data=data)
    assert report.status_code == 200
    assert report.headers["content-disposition"] == 'attachment; filename="brandenberger_1952.json"'
    body = json.loads(report.text)
    assert body["schema"].startswith("epicyclic-report/") and body["units"]["power"] == "PS"
    assert body["solution"]["efficiency"] == pytest.approx(loads_train_file(text).solve().efficiency)
    page = client.post("/download/html", data=data)
    assert page.status_code == 200 and page.text.startswith("<!DOCTYPE html>") and "<script" not in page.text
    toml = client.post("/download/toml", data=data)
    assert toml.status_code == 200 and toml.text == text
    assert toml.headers["content-disposition"].endswith('.toml"')
    assert client.post("/download/exe", data=data).status_code == 422


def test_upload(client, examples):
    text = examples["simple_set_ring_held_sun_drives"].text
    answer = client.post("/upload", files={"file": ("my set.toml", text.encode(), "application/toml")})
    assert answer.status_code == 200 and "my set.toml" in answer.text
    latin = client.post("/upload", files={"file": ("x.toml", "title = 'Übersetzung'".encode("latin-1"))})
    assert latin.status_code == 422 and "UTF-8" in latin.text
    assert client.post("/upload", data={"units": "file"}).status_code == 400


def test_geometry_from_the_file_when_it_has_one():
    """A file's geometry table of a set gives the form's starting values; a changed field gives a variant."""
    from types import SimpleNamespace

    from epicyclic.geometry import SetGeometry
    from epicyclic.web.tools import ALL, TOOLS, Context, form_rows, run_tool

    train_file = loads_train_file(bundled_examples()["simple_set_ring_held_sun_drives"].text)
    pset = train_file.train.element("P")
    with_geometry = SimpleNamespace(train=train_file.train, geometry={"P": SetGeometry.create(pset, module=3.5)},
                                    transmission=None, source="t.toml")
    starting = {f.name: value for f, value, _ in form_rows(TOOLS["fit"], Context(with_geometry), "P")}
    assert starting["module"] == "3.5"
    from_file = run_tool("fit", {"tool_fit_set": ALL}, Context(with_geometry))
    from_form = run_tool("fit", {"tool_fit_set": "P", "tool_fit_module": "2"}, Context(with_geometry))
    # pitch diameters d = m z (ISO 21771): sun 30 teeth → 105 mm at m = 3.5, 60 mm at m = 2
    assert "<td>105.0000</td>" in from_file and "<td>60.0000</td>" in from_form
    without = run_tool("fit", {"tool_fit_set": "P", "tool_fit_module": "2"}, Context(train_file))
    assert "<td>60.0000</td>" in without


def test_the_forms_placeholders_and_hints_follow_the_units_shown(client, examples, page_form):
    """Issue 30: with the page in rpm, lbf·ft, hp the form says so (a plain number stays the file's unit, as the
    loader reads it, and the hint says that too)."""
    answer = client.post("/apply/text", data=page_form(examples["simpson_c4_3speed"].text, units="rpm-hp")).text
    form = answer[answer.index('id="opform"'):]
    assert 'placeholder="e.g. 1500 rpm"' in form and 'placeholder="e.g. 100 lbf*ft"' in form
    assert "<code>3 hp</code>" in form and "a plain number is in the file's unit (1/min" in form
    plain = client.post("/apply/text", data=page_form(examples["simpson_c4_3speed"].text)).text
    assert 'placeholder="1/min"' in plain[plain.index('id="opform"'):]
