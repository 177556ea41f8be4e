"""The page's forms beside the results (fit, forces, search, efficiency map) and the loss split by source.

The page runs the command line's functions with the command line's parsers and
limits, so each form is checked against the command itself on the same file
(``epicyclic fit/forces/search/map`` through typer's test runner): the same
tables, the same CSV and JSON, the same message for bad input.  The numbers of
the commands themselves are checked against published cases in
tests/cli/test_geometry_cli.py and tests/losses/.
"""

from __future__ import annotations

import html
import json
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app as cli
from epicyclic.io import loads_train_file
from epicyclic.limits import MAX_MAP_POINTS
from epicyclic.web import Limits, create_app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
runner = CliRunner()


def example(name: str) -> tuple[str, Path]:
    path = EXAMPLES / f"{name}.toml"
    return path.read_text(encoding="utf-8"), path


def command(*args: str) -> str:
    result = runner.invoke(cli, [str(a) for a in args])
    assert result.exit_code == 0, result.output
    return result.output


def command_error(*args: str) -> str:
    result = runner.invoke(cli, [str(a) for a in args])
    assert result.exit_code == 2, result.output
    return " ".join(result.output.split())


def body(answer) -> str:
    assert answer.status_code == 200, answer.text[:600]
    return re.fullmatch(r'<div class="tool-output">(.*)</div>\s*', answer.text, re.S).group(1)


def message(answer) -> str:
    found = re.findall(r'<p class="message"><strong>error:</strong> (.*?)</p>', answer.text, re.S)
    assert answer.status_code == 422 and len(found) == 1, answer.text[:600]
    return html.unescape(found[0])


def fields_of(page: str, tool: str) -> dict[str, str]:
    """The starting values of a form as the page renders them (inputs and selected options)."""
    start = page.index(f'id="tool-{tool}-fields"')
    block = page[start:page.index("</div>", start)]
    values = dict(re.findall(rf'<input name="tool_{tool}_(\w+)" value="([^"]*)"', block))
    for name, options in re.findall(rf'<select name="tool_{tool}_(\w+)".*?>(.*?)</select>', block, re.S):
        values[name] = re.search(r'<option value="([^"]*)" selected>', options).group(1)
    return {k: html.unescape(v) for k, v in values.items()}


# ---------------------------------------------------------------------- starting values from the file
def test_forms_start_from_the_files_geometry(client, page_form):
    text, _ = example("geometry_simple_set")
    page = client.post("/apply/text", data=page_form(text)).text
    assert fields_of(page, "fit")["set"] == "every element with geometry"  # as `epicyclic fit FILE`
    assert "module" not in fields_of(page, "fit")  # the file's tables are used, not fields
    chosen = client.post("/tool/fit/fields", data=page_form(text, tool_fit_set="P"))
    assert chosen.status_code == 200
    fit = fields_of(chosen.text, "fit")
    # the file's [planetary.geometry]: lecad test run m_n 1.75 mm, 20°, x 0.438 / 0.0426 / 0
    assert (fit["module"], fit["pressure_angle"], fit["x_sun"], fit["x_planet"], fit["x_ring"]) == \
        ("1.75", "20", "0.438", "0.0426", "0")
    search = fields_of(page, "search")
    assert (search["module"], search["pressure_angle"], search["planets"]) == ("1.75", "20", "3")  # 3 planets


def test_each_set_brings_its_own_geometry(client, page_form):
    text, _ = example("zf_8hp70_geometry")  # P1..P3 at 1.5 mm, P4 at 1.75 mm
    p4 = fields_of(client.post("/tool/forces/fields", data=page_form(text, tool_forces_set="P4")).text, "forces")
    p1 = fields_of(client.post("/tool/forces/fields", data=page_form(text, tool_forces_set="P1")).text, "forces")
    assert (p1["set"], p1["module"], p4["set"], p4["module"]) == ("P1", "1.5", "P4", "1.75")
    stepped, _ = example("geometry_stepped_set")  # two planet gears: one profile shift each
    rows = fields_of(client.post("/tool/fit/fields", data=page_form(stepped, tool_fit_set="S")).text, "fit")
    table = loads_train_file(stepped).geometry["S"]  # the file's [planetary.geometry] profile_shift
    assert rows["x_sun"] == f"{table.x_sun:g}" and rows["x_planet"] == ", ".join(f"{x:g}" for x in table.x_planet)
    assert len(rows["x_planet"].split(",")) == 2


def test_a_file_without_geometry_keeps_the_form_defaults(client, examples, page_form):
    page = client.post("/apply/text", data=page_form(examples["simple_set_ring_held_sun_drives"].text)).text
    fit = fields_of(page, "fit")
    assert fit["set"] == "P" and fit["module"] == "2"
    assert "every element with geometry" not in page


# ---------------------------------------------------------------------- the same results as the commands
def _cli_html(output: str) -> str:
    """The body of a command's HTML output without its title heading (the page has its own)."""
    body = output.split("<body>", 1)[1].rsplit("</body>", 1)[0]
    return re.sub(r"^<h1>.*?</h1>", "", body, count=1)


@pytest.mark.parametrize("name", ["geometry_simple_set", "geometry_stepped_set", "wolfrom_drive",
                                  "zf_8hp70_geometry"])
def test_fit_and_forces_of_every_element_are_the_commands(client, page_form, name):
    text, path = example(name)
    fit = body(client.post("/tool/fit", data=page_form(text, tool_fit_set="every element with geometry")))
    assert fit == _cli_html(command("fit", path, "-f", "html"))
    forces = body(client.post("/tool/forces", data=page_form(text, tool_forces_set="every element with geometry")))
    assert forces == _cli_html(command("forces", path, "-f", "html"))


def test_fit_options_are_the_commands(client, page_form):
    text, path = example("geometry_simple_set")
    fit = body(client.post("/tool/fit", data=page_form(text, tool_fit_planets="5", tool_fit_unequal="yes",
                                                       tool_fit_min_clearance="2", tool_fit_undercut="practical")))
    cli_html = _cli_html(command("fit", path, "-f", "html", "--planets", "5", "--allow-unequal",
                                 "--min-clearance", "2", "--undercut", "practical"))
    assert fit == cli_html and "5 planets" in fit


def test_one_set_with_the_files_values_is_the_files_geometry(client, page_form):
    """Fields left at their starting values reproduce the file's table (face widths etc. kept); a changed
    field is a variant of it."""
    text, path = example("geometry_simple_set")
    rows = fields_of(client.post("/tool/fit/fields", data=page_form(text, tool_fit_set="P")).text, "fit")
    same = body(client.post("/tool/fit", data=page_form(text, **{f"tool_fit_{k}": v for k, v in rows.items()})))
    assert same == _cli_html(command("fit", path, "-f", "html"))
    rows["module"] = "2"
    other = body(client.post("/tool/fit", data=page_form(text, **{f"tool_fit_{k}": v for k, v in rows.items()})))
    assert "<td>42.0000</td>" in other  # sun d = m z = 2 × 21 mm (ISO 21771)
    forces = body(client.post("/tool/forces", data=page_form(text, tool_forces_set="P", tool_forces_load_sharing="1.2")))
    file_forces = body(client.post("/tool/forces", data=page_form(text, tool_forces_set="P")))
    f_t = [float(v) for v in re.findall(r"<td>planet</td><td>[\d.]+</td><td>sun-planet</td><td>([\d.]+)</td>", file_forces + forces)]
    assert f_t[0] == pytest.approx(1073.1067, abs=1e-4)  # `epicyclic forces` of the file: K_γ = 1, 3 planets
    assert f_t[-1] == pytest.approx(1.2 * f_t[0], rel=1e-6)  # design forces scale with K_γ


def test_search_is_the_commands(client, page_form):
    text, _ = example("geometry_simple_set")
    fields = dict(ratio="5.2", tolerance="3%", planets="3..4", module="1.75", sun="15..40", planet="15..40",
                  ring="", pressure_angle="20", min_clearance="1", undercut="practical", interference="yes",
                  limit="10", held="ring", driver="sun", driven="carrier")
    data = page_form(text, **{f"tool_search_{k}": v for k, v in fields.items()})
    table = html.unescape(re.search(r"<pre>(.*)</pre>", body(client.post("/tool/search", data=data)), re.S).group(1))
    args = ("search", "--ratio", "5.2", "--tolerance", "3%", "--planets", "3..4", "--module", "1.75", "--sun",
            "15..40", "--planet", "15..40", "--min-clearance", "1", "--undercut", "practical")
    assert table + "\n" == command(*args, "--limit", "10")
    csv = client.post("/download/search.csv", data=data)
    assert csv.status_code == 200 and csv.text == command(*args, "-f", "csv")
    assert csv.headers["content-disposition"].endswith('-search.csv"')
    assert json.loads(client.post("/download/search.json", data=data).text) == \
        json.loads(command(*args, "-f", "json"))


# ---------------------------------------------------------------------- the efficiency map
def test_the_map_is_the_commands(client, page_form, tmp_path):
    text, path = example("geometry_simple_set")
    data = page_form(text, tool_map_speed="1000..4000:7", tool_map_torque="20..200:5", source="geometry_simple_set.toml")
    result = body(client.post("/tool/map", data=data))
    summary = html.unescape(re.search(r"<pre>(.*?)</pre>", result, re.S).group(1))
    assert summary + "\n" == command("map", path, "--speed", "1000..4000:7", "--torque", "20..200:5")
    assert "<svg" in result and "efficiency" in result and "no loss tables" not in result
    for suffix in ("csv", "json"):
        answer = client.post(f"/download/map.{suffix}", data=data)
        command("map", path, "--speed", "1000..4000:7", "--torque", "20..200:5", "-o", tmp_path / f"m.{suffix}")
        assert answer.status_code == 200 and answer.text == (tmp_path / f"m.{suffix}").read_text()
        assert answer.headers["content-disposition"] == f'attachment; filename="geometry_simple_set-map.{suffix}"'
    png = client.post("/download/map.png", data=data)
    assert png.status_code == 200 and png.content.startswith(b"\x89PNG")


def test_the_map_of_a_gear_in_coast(client, page_form):
    text, path = example("zf_8hp70_geometry")
    page = client.post("/apply/text", data=page_form(text)).text
    assert fields_of(page, "map")["gear"] == "1"  # the file's operating-point gear
    data = page_form(text, tool_map_speed="1000..3000:3", tool_map_torque="50..150:3", tool_map_gear="5",
                     tool_map_direction="coast")
    summary = html.unescape(re.search(r"<pre>(.*?)</pre>", body(client.post("/tool/map", data=data)), re.S).group(1))
    assert summary + "\n" == command("map", path, "--speed", "1000..3000:3", "--torque", "50..150:3", "--gear", "5",
                                     "--coast")
    assert "gear 5 (coast" in summary


def test_a_map_without_loss_tables_says_why_it_is_flat(client, examples, page_form):
    data = page_form(examples["brandenberger_1952"].text, tool_map_speed="500..1000:3", tool_map_torque="1..2:2")
    result = body(client.post("/tool/map", data=data))
    assert "no loss tables" in result and "<svg" in result
    assert 'id="tool-map-fields"' in client.post("/apply/text", data=page_form(examples["brandenberger_1952"].text)).text
    assert 'name="tool_map_gear"' not in client.post("/tool/map/fields", data=data).text  # no transmission, no gear


@pytest.mark.parametrize("fields, cli_args, fragment", [
    (dict(tool_map_speed="fast"), ("--speed", "fast"), "expected a value or a range A..B:N in 1/min"),
    (dict(tool_map_speed="6000..500:5"), ("--speed", "6000..500:5"), "expected 0 < A <= B"),
    (dict(tool_map_torque="10..50:many"), ("--torque", "10..50:many"), "the count after ':' must be a whole number"),
    (dict(tool_map_torque="10..50:10000000"), ("--torque", "10..50:10000000"), "must lie in 2..10000"),
    (dict(tool_map_speed="1..2:5000", tool_map_torque="1..2:5000"), ("--speed", "1..2:5000", "--torque", "1..2:5000"),
     f"5000 × 5000 points exceed the limit of {MAX_MAP_POINTS:,}"),
    (dict(tool_map_torque="1e300"), ("--torque", "1e300"), "leaves no efficiency (μ·H_V >= 1)"),
])
def test_map_errors_are_the_commands(client, page_form, fields, cli_args, fragment):
    text, path = example("geometry_simple_set")
    said = message(client.post("/tool/map", data=page_form(text, source=str(path), **fields)))
    cli_said = command_error("map", path, *cli_args)
    assert fragment in said and fragment in cli_said
    if "leaves no efficiency" in fragment:  # a loss model's error: the command's line, word for word
        assert cli_said == f"error: {said}"


def test_search_errors_are_the_commands(client, examples, page_form):
    text = examples["brandenberger_1952"].text
    for field, value, cli_option in (("ratio", "0", "--ratio"), ("tolerance", "150%", "--tolerance"),
                                     ("planets", "6..3", "--planets"), ("sun", "1..20", "--sun"),
                                     ("ring", "many", "--ring")):
        said = message(client.post("/tool/search", data=page_form(text, **{f"tool_search_{field}": value})))
        cli_said = command_error("search", "--ratio", "5", cli_option, value) if field != "ratio" else \
            command_error("search", "--ratio", value)
        assert said.split(": ", 2)[2] == cli_said.split(": ", 3)[3], (said, cli_said)  # the same words after the name


def test_a_map_past_the_time_limit_is_stopped(page_form):
    from starlette.testclient import TestClient

    text, _ = example("zf_8hp70_geometry")
    with TestClient(create_app(Limits(workers=1, solve_timeout=0.5))) as client:
        slow = client.post("/tool/map", data=page_form(text, tool_map_speed="500..6000:1000",
                                                       tool_map_torque="10..500:1000"))
        assert slow.status_code == 504 and "longer than 0.5 s" in slow.text
        assert client.get("/healthz").text == "ok"


# ---------------------------------------------------------------------- the loss split
def test_the_loss_split_by_source(client, page_form):
    text, _ = example("geometry_simple_set")
    page = client.post("/apply/text", data=page_form(text)).text
    split = re.search(r'<div id="loss-split">(.*?)</div>', page, re.S).group(1)
    solution = loads_train_file(text).solve()
    rows = dict((r[0], r[1:]) for r in re.findall(r"<tr><td>(\w+)</td><td>([^<]*)</td><td>([^<]*)</td>"
                                                   r"<td>([^<]*)</td><td>([^<]*)</td></tr>", split))
    sources = solution.elements["P"].loss_sources
    mesh, bearing, drag, total = (float(v) for v in rows["P"])
    assert (mesh, bearing, drag) == pytest.approx((sources["mesh"], sources["bearing"], sources["drag"]), rel=1e-5)
    assert total == pytest.approx(solution.loss, rel=1e-5)  # the parts add up to the element's loss
    assert rows["all"] == rows["P"]  # one element with losses
    assert "<th>loss by source</th>" in page  # and the summary line, as `epicyclic analyze`


def test_the_loss_split_of_a_transmission_gear(client, page_form):
    text, _ = example("zf_8hp70_geometry")
    page = client.post("/apply/text", data=page_form(text, gear="3")).text
    split = re.search(r'<div id="loss-split">(.*?)</div>', page, re.S).group(1)
    assert all(f"<td>{name}</td>" in split for name in ("P1", "P2", "P3", "P4", "all"))


def test_no_loss_split_without_loss_models(client, examples, page_form):
    page = client.post("/apply/text", data=page_form(examples["brandenberger_1952"].text)).text
    assert 'id="loss-split"' not in page and "loss by source" not in page


def test_search_needs_three_different_members(client, examples, page_form):
    data = page_form(examples["brandenberger_1952"].text, tool_search_held="sun", tool_search_driver="sun")
    said = message(client.post("/tool/search", data=data))
    assert "give three different members" in said
    assert "give three different members" in command_error("search", "--ratio", "4", "--held", "sun", "--driver", "sun")


def test_forces_of_one_wolfrom_set_share_the_planet_with_the_other(client, page_form):
    """The form for set W alone still solves the planet it shares with set S as one body (its bearing
    is the vector sum of the meshes of both sets, as `epicyclic forces` of the whole file says)."""
    text, path = example("wolfrom_drive")
    one = body(client.post("/tool/forces", data=page_form(text, tool_forces_set="W")))
    assert "planets shared with set &#x27;S&#x27;" in one and "S: planet-ring = W: first-planet_first" in one
    bearing = re.findall(r"<td>planet_first\+planet_second</td><td>0.00</td><td>first-planet_first</td>"
                         r"(?:<td>[\d.]+</td>){3}<td>([\d.]+)</td>", one)
    assert bearing and bearing[0] in command("forces", path)


def test_the_map_form_speaks_the_files_units(client, page_form, tmp_path):
    """A file with [units] rad/s and kp*m: the form starts from the default range written in them, says so,
    and reads its fields in them, as `epicyclic map` of that file does."""
    text, _ = example("geometry_simple_set")
    text = text.replace("\n[lubricant]", '\n[units]\nspeed = "rad/s"\ntorque = "kp*m"\n\n[lubricant]', 1)
    assert "[units]" in text
    path = tmp_path / "units.toml"
    path.write_text(text, encoding="utf-8")
    page = client.post("/apply/text", data=page_form(text)).text
    start = fields_of(page, "map")
    assert (start["speed"], start["torque"]) == ("52.3599..628.319:50", "1.01972..50.9858:50")
    assert "input speeds [rad/s]" in page and "input torques [kp·m]" in page
    data = page_form(text, tool_map_speed="100..600:6", tool_map_torque="2..20:4")
    summary = html.unescape(re.search(r"<pre>(.*?)</pre>", body(client.post("/tool/map", data=data)), re.S).group(1))
    assert "input speed 100..600 rad/s (6 values), input torque 2..20 kp*m (4 values)" in summary
    assert summary + "\n" == command("map", path, "--speed", "100..600:6", "--torque", "2..20:4")
    assert command("map", path, "--speed", "954.93..5729.58:6 rpm", "--torque", "2..20:4").splitlines()[1] == \
        "input speed 100..600 rad/s (6 values), input torque 2..20 kp*m (4 values)"


def test_the_rating_panel_is_the_rate_command(client, page_form):
    """The Geometry and rating tab's load-capacity form shows the rating `epicyclic rate -f html` writes
    (ISO 6336 method B, every factor), below-minimum meshes marked as there."""
    path = EXAMPLES / "rating" / "simple_set.toml"
    page = body(client.post("/tool/rating", data=page_form(path.read_text(encoding="utf-8"))))
    assert page.startswith("<section class='rating'>") and "ISO 6336:2019" in page
    report = command("rate", path, "-f", "html")
    report = report[report.index("<section class='rating'>"):]  # after the command's input echo (the file's own
    cells = re.findall(r"<td[^>]*>([^<]*)</td>", report)       # values, which the page shows in its editor)
    numbers = [c for c in cells if re.fullmatch(r"[\d.e+…\s-]+", c) and c.strip()]
    assert numbers and re.findall(r"<td[^>]*>([^<]*)</td>", page).count(numbers[0]) >= 1
    page_cells = set(re.findall(r"<td[^>]*>([^<]*)</td>", page))
    assert set(numbers) <= page_cells  # the command's numbers, every one
    assert report.count("class='below'") == page.count("class='below'")
    plain = client.post("/tool/rating", data=page_form(example("geometry_simple_set")[0]))
    assert "no [rating] table" in message(plain)


def test_the_rating_table_is_typeset_for_the_page(client, page_form):
    """Issue 30: words left-aligned, σ_H and N/mm² written as in ISO 6336-1:2019, clause 4 (not sigma_H and
    N/mm^2), and the two wheels of a mesh named by their members, not "gear 1/2" (read as transmission gears)."""
    path = EXAMPLES / "rating" / "simple_set.toml"
    page = body(client.post("/tool/rating", data=page_form(path.read_text(encoding="utf-8"))))
    assert "σ_H [N/mm²]" in page and "sigma_H" not in page and "N/mm^2" not in page
    assert "gear 1" not in page and "gear 2" not in page
    assert "<th>sun</th><th>planet</th>" in page and "<th>planet</th><th>ring</th>" in page
    assert "<td class='text'>sun-planet</td>" in page and "<td class='text'>K_Hβ</td>" in page


def test_the_load_capacity_form_says_plainly_that_a_file_has_no_rating_table(client, examples):
    """Issue 30: on a file without [rating] the form says so at once (no Run button that fails), and on the
    rating example it runs."""
    answer = client.post("/example", data={"example": "zf_8hp70_8speed"})
    missing = re.search(r'id="tool-rating-missing">([^<]*)<', answer.text)
    assert missing and "has no [rating] table" in html.unescape(missing.group(1))
    rated = client.post("/example", data={"example": "simple_set"})
    assert rated.status_code == 200 and 'id="tool-rating-missing"' not in rated.text
    assert 'hx-post="/tool/rating"' in rated.text
